#include "esi/lint/xsd.hpp"

#include <libxml/parser.h>
#include <libxml/parserInternals.h>
#include <libxml/uri.h>
#include <libxml/xmlschemas.h>

#include <algorithm>
#include <cstdarg>
#include <cstdio>
#include <mutex>
#include <optional>
#include <set>
#include <vector>

namespace esi {

struct SchemaSet::Impl {
    xmlSchemaPtr info = nullptr;
    xmlSchemaPtr module = nullptr;
    xmlSchemaPtr dict = nullptr;
    std::filesystem::path dir;
    std::set<std::string> present;  // the schema files that exist in dir (compiled or not)
    // Why a schema is not there to validate with: the two need different fixes.
    [[nodiscard]] std::string why_unusable(const std::string& file) const {
        if (!present.count(file))
            return "the file is missing (give the directory of the ETG schema files: EtherCATInfo.xsd, EtherCATBase.xsd …)";
        return "the file is there but does not compile (a schema file it includes is missing or broken; see the xml-schema "
               "messages about it)";
    }
    ~Impl() {
        for (xmlSchemaPtr s : {info, module, dict})
            if (s) xmlSchemaFree(s);
    }
};

namespace {

namespace fs = std::filesystem;

// libxml2 2.9 has one external-entity loader for the whole process and error handlers per thread,
// with no way to give them to a schema parser. So the library installs, once, a loader that
// consults the scope of the calling thread: inside SchemaSet::load or validate it reads only
// files below the schema directory and refuses everything else (no network, no other file);
// on any other thread, or outside these calls, it hands over to the loader that was installed
// before, so a program's own use of libxml2 is unchanged. The error handlers are set for the
// duration of a scope and restored after it, so libxml2 never writes to stderr for us.
struct LibxmlScope {
    Diagnostics* diagnostics = nullptr;
    std::string path;                 // what the messages are about when libxml2 names no file
    std::optional<fs::path> allowed;  // canonical directory files may be loaded from; none: nothing
    std::set<std::string> refused;    // each refused location is reported once
    const SourceText* source = nullptr;  // the instance validated, to find an element's column
};

thread_local LibxmlScope* active_scope = nullptr;
xmlExternalEntityLoader previous_loader = nullptr;
std::once_flag libxml_init;

// The local file a URL names, if it names one: a path, or a file: URL. Anything with another
// scheme (http:, ftp:, ...) names none.
std::optional<fs::path> local_file(std::string_view url) {
    if (url.rfind("file://", 0) == 0) {
        url.remove_prefix(7);
        if (url.rfind("localhost/", 0) == 0) url.remove_prefix(9);
        char* unescaped = xmlURIUnescapeString(std::string(url).c_str(), 0, nullptr);
        if (!unescaped) return std::nullopt;
        fs::path path(unescaped);
        xmlFree(unescaped);
        return path;
    }
    const auto colon = url.find(':');
    const auto slash = url.find('/');
    if (colon != std::string_view::npos && colon > 1 && (slash == std::string_view::npos || colon < slash)) return std::nullopt;
    return fs::path(url);
}

bool inside(const fs::path& file, const fs::path& dir) {
    std::error_code ec;
    const fs::path resolved = fs::weakly_canonical(file, ec);  // through symbolic links
    if (ec) return false;
    const fs::path relative = resolved.lexically_relative(dir);
    return !relative.empty() && *relative.begin() != ".." && relative != ".";
}

xmlParserInputPtr guarded_loader(const char* url, const char* id, xmlParserCtxtPtr context) {
    LibxmlScope* scope = active_scope;
    if (!scope) return previous_loader ? previous_loader(url, id, context) : nullptr;
    if (url && scope->allowed) {
        if (const auto file = local_file(url); file && inside(*file, *scope->allowed)) return previous_loader(url, id, context);
    }
    const std::string location = url ? url : (id ? id : "");
    if (scope->refused.insert(location).second) {
        scope->diagnostics->emplace(Severity::error, "xml-schema",
                                    "refused to load '" + excerpt(location, 240) + "': " +
                                        (scope->allowed ? "schema validation reads only files inside " + scope->allowed->string() +
                                                              ", never the network"
                                                        : std::string("the document is validated without loading anything")),
                                    scope->path, SourcePos{});
    }
    return nullptr;
}

// One line: libxml2 ends messages with a newline and breaks some inside (a list of expected
// elements), and the GitHub and GitLab formats take a raw newline for the end of a finding.
std::string trimmed(const char* text) {
    std::string message;
    bool space = false;
    for (const char* c = text; c && *c; ++c) {
        if (*c == '\n' || *c == '\r' || *c == '\t' || *c == ' ') {
            space = !message.empty();
            continue;
        }
        if (space) message.push_back(' ');
        space = false;
        message.push_back(*c);
    }
    return message;
}

// The column of the element libxml2 names on its line: validation errors carry only a line, so
// the column is where "<name" starts on that line (the first such tag, 1 when none is found).
std::uint32_t column_of(const LibxmlScope& scope, const xmlError& error, std::uint32_t line) {
    if (error.int2 > 0) return static_cast<std::uint32_t>(error.int2);  // the parser's own column
    if (!scope.source || line == 0 || line > scope.source->line_count()) return 1;
    const auto* node = static_cast<const xmlNode*>(error.node);
    if (!node || node->type != XML_ELEMENT_NODE || !node->name) return 1;
    const std::string_view text = scope.source->line(line);
    const std::string name = reinterpret_cast<const char*>(node->name);
    for (std::size_t at = text.find('<'); at != std::string_view::npos; at = text.find('<', at + 1)) {
        std::string_view rest = text.substr(at + 1);
        if (const auto colon = rest.find(':'); colon != std::string_view::npos && colon < rest.find_first_of(" \t/>"))
            rest.remove_prefix(colon + 1);  // a namespace prefix
        if (rest.starts_with(name) && (rest.size() == name.size() || std::string_view(" \t/>").find(rest[name.size()]) != std::string_view::npos))
            return scope.source->code_points(scope.source->line_start(line), scope.source->line_start(line) + at) + 1;
    }
    return 1;
}

void structured_error(void* user, xmlErrorPtr error) {
    auto* scope = static_cast<LibxmlScope*>(user);
    if (!error || !scope || !scope->diagnostics) return;
    const std::string message = trimmed(error->message);
    if (message.empty()) return;
    // A file libxml2 names (an included schema) is where the problem is.
    const std::string file = error->file ? error->file : scope->path;
    const Severity severity = error->level == XML_ERR_WARNING ? Severity::warning : Severity::error;
    const auto line = static_cast<std::uint32_t>(error->line > 0 ? error->line : 0);
    const bool in_instance = !error->file || file == scope->path;
    const std::uint32_t column = line == 0 ? 0 : in_instance ? column_of(*scope, *error, line) : static_cast<std::uint32_t>(std::max(error->int2, 1));
    scope->diagnostics->emplace(severity, "xml-schema", message, file, SourcePos{line, column});
}

// Messages libxml2 writes outside the structured channel (some I/O and loader warnings).
void generic_error(void* user, const char* format, ...) {
    auto* scope = static_cast<LibxmlScope*>(user);
    if (!scope || !scope->diagnostics) return;
    char buffer[1024];
    va_list arguments;
    va_start(arguments, format);
    std::vsnprintf(buffer, sizeof buffer, format, arguments);
    va_end(arguments);
    const std::string message = trimmed(buffer);
    if (message.empty() || message == "error :" || message == "warning :") return;
    scope->diagnostics->emplace(Severity::warning, "xml-schema", message, scope->path, SourcePos{});
}

// Installs `scope` for this thread: the loader's policy and the error handlers, restored on exit.
class ScopeGuard {
public:
    explicit ScopeGuard(LibxmlScope& scope)
        : previous_scope_(active_scope),
          previous_structured_(xmlStructuredError),
          previous_structured_context_(xmlStructuredErrorContext),
          previous_generic_(xmlGenericError),
          previous_generic_context_(xmlGenericErrorContext) {
        active_scope = &scope;
        xmlSetStructuredErrorFunc(&scope, structured_error);
        xmlSetGenericErrorFunc(&scope, generic_error);
    }
    ~ScopeGuard() {
        xmlSetStructuredErrorFunc(previous_structured_context_, previous_structured_);
        xmlSetGenericErrorFunc(previous_generic_context_, previous_generic_);
        active_scope = previous_scope_;
    }
    ScopeGuard(const ScopeGuard&) = delete;
    ScopeGuard& operator=(const ScopeGuard&) = delete;

private:
    LibxmlScope* previous_scope_;
    xmlStructuredErrorFunc previous_structured_;
    void* previous_structured_context_;
    xmlGenericErrorFunc previous_generic_;
    void* previous_generic_context_;
};

void initialise_libxml() {
    std::call_once(libxml_init, [] {
        xmlInitParser();
        previous_loader = xmlGetExternalEntityLoader();
        xmlSetExternalEntityLoader(guarded_loader);
    });
}

xmlSchemaPtr load_schema(const fs::path& file, LibxmlScope& scope, std::set<std::string>* set_present) {
    std::error_code ec;
    if (!fs::is_regular_file(file, ec)) return nullptr;
    if (set_present) set_present->insert(file.filename().string());
    scope.path = file.string();
    xmlSchemaParserCtxtPtr parser = xmlSchemaNewParserCtxt(file.c_str());
    if (!parser) return nullptr;
    xmlSchemaSetParserStructuredErrors(parser, structured_error, &scope);
    xmlSchemaPtr schema = xmlSchemaParse(parser);
    xmlSchemaFreeParserCtxt(parser);
    return schema;
}

// The first entity reference in the tree (content or attribute value), or null. libxml2's
// validator cannot walk one ("Internal error: xmlSchemaVDocWalk") and expanding it is what the
// reader never does, so such a document is reported as not validated.
xmlNodePtr first_entity_reference(xmlNodePtr root) {
    std::vector<xmlNodePtr> stack{root};
    while (!stack.empty()) {
        xmlNodePtr node = stack.back();
        stack.pop_back();
        for (; node; node = node->next) {
            if (node->type == XML_ENTITY_REF_NODE) return node;
            if (node->type != XML_ELEMENT_NODE) continue;
            for (xmlAttrPtr a = node->properties; a; a = a->next)
                for (xmlNodePtr v = a->children; v; v = v->next)
                    if (v->type == XML_ENTITY_REF_NODE) return node;
            if (node->children) stack.push_back(node->children);
        }
    }
    return nullptr;
}

void not_validated(Diagnostics& out, const std::string& path, SourcePos pos, const std::string& why) {
    out.emplace(Severity::error, "xml-schema", "not validated against the schema: " + why, path, pos);
}

}  // namespace

SchemaSet::~SchemaSet() = default;

std::shared_ptr<SchemaSet> SchemaSet::load(const std::filesystem::path& dir, Diagnostics& diagnostics) {
    initialise_libxml();
    std::shared_ptr<SchemaSet> set(new SchemaSet());
    set->impl_ = std::make_unique<Impl>();
    set->impl_->dir = dir;
    Diagnostics problems;
    LibxmlScope scope;
    scope.diagnostics = &problems;
    std::error_code ec;
    scope.allowed = fs::canonical(dir, ec);
    if (ec) scope.allowed.reset();
    {
        const ScopeGuard guard(scope);
        set->impl_->info = load_schema(dir / "EtherCATInfo.xsd", scope, &set->impl_->present);
        set->impl_->module = load_schema(dir / "EtherCATModule.xsd", scope, &set->impl_->present);
        set->impl_->dict = load_schema(dir / "EtherCATDict.xsd", scope, &set->impl_->present);
    }
    if (!set->impl_->info)
        diagnostics.emplace(Severity::error, "io-error", "no usable EtherCATInfo.xsd in " + dir.string() + ": " + set->impl_->why_unusable("EtherCATInfo.xsd"),
                            dir.string(), {});
    diagnostics.append(std::move(problems));
    return set;
}

Diagnostics SchemaSet::validate(const SourceText& source) const {
    Diagnostics out;
    LibxmlScope scope;  // allows no loading at all: the instance needs nothing from outside
    scope.diagnostics = &out;
    scope.path = source.path();
    scope.source = &source;
    const ScopeGuard guard(scope);
    // The text is already UTF-8; tell libxml2 so, whatever the declaration says. Nothing is
    // loaded (NONET, no DTD loading, no entity substitution); messages come through the handlers.
    const int parse_options = XML_PARSE_NONET | XML_PARSE_HUGE;
    xmlDocPtr doc = xmlReadMemory(source.text().data(), static_cast<int>(source.text().size()), source.path().c_str(), "UTF-8",
                                  parse_options);
    if (!doc) {
        Diagnostics why = std::move(out);
        out = Diagnostics();
        const Diagnostic* first = why.empty() ? nullptr : &why.items()[0];
        not_validated(out, source.path(), first ? first->pos : SourcePos{},
                      "libxml2 cannot read the file" + (first ? ": " + first->message : std::string()));
        return out;
    }
    const xmlNodePtr root = xmlDocGetRootElement(doc);
    const std::string root_name = root && root->name ? reinterpret_cast<const char*>(root->name) : "";
    struct Root {
        const char* element;
        const char* schema_file;
        xmlSchemaPtr schema;
    };
    const Root roots[] = {{"EtherCATInfo", "EtherCATInfo.xsd", impl_->info},
                          {"EtherCATModule", "EtherCATModule.xsd", impl_->module},
                          {"EtherCATDict", "EtherCATDict.xsd", impl_->dict}};
    xmlSchemaPtr schema = nullptr;
    const char* schema_file = nullptr;
    for (const Root& r : roots) {
        if (root_name != r.element) continue;
        schema = r.schema;
        schema_file = r.schema_file;
    }
    const SourcePos root_pos{static_cast<std::uint32_t>(root ? xmlGetLineNo(root) : 0), root ? 1u : 0u};
    if (!schema) {
        not_validated(out, source.path(), root_pos,
                      schema_file ? std::string("no usable ") + schema_file + " in " + impl_->dir.string() + ": " + impl_->why_unusable(schema_file)
                                  : "the ETG schemas describe no root element '" + excerpt(root_name) + "'");
    } else if (const xmlNodePtr reference = first_entity_reference(root)) {
        const auto line = static_cast<std::uint32_t>(xmlGetLineNo(reference));
        not_validated(out, source.path(), SourcePos{line, 1u},
                      "the document uses entity references, which are never expanded (the first: &" +
                          excerpt(reference->name ? reinterpret_cast<const char*>(reference->name) : "") + ";)");
    } else {
        xmlSchemaValidCtxtPtr context = xmlSchemaNewValidCtxt(schema);
        xmlSchemaSetValidStructuredErrors(context, structured_error, &scope);
        const int outcome = xmlSchemaValidateDoc(context, doc);
        xmlSchemaFreeValidCtxt(context);
        if (outcome < 0 || (outcome > 0 && !out.has_errors()))
            not_validated(out, source.path(), root_pos, "libxml2 could not complete the validation");
    }
    xmlFreeDoc(doc);
    return out;
}

}  // namespace esi
