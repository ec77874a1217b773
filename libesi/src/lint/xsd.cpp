#include "esi/lint/xsd.hpp"

#include <libxml/parser.h>
#include <libxml/xmlschemas.h>

#include <cstdarg>
#include <mutex>

namespace esi {

struct SchemaSet::Impl {
    xmlSchemaPtr info = nullptr;
    xmlSchemaPtr module = nullptr;
    xmlSchemaPtr dict = nullptr;
    ~Impl() {
        for (xmlSchemaPtr s : {info, module, dict})
            if (s) xmlSchemaFree(s);
    }
};

namespace {

std::once_flag libxml_init;

// libxml2 reports through varargs callbacks; collect them, with line numbers, into diagnostics.
struct ErrorSink {
    Diagnostics* diagnostics;
    std::string path;
};

void structured_error(void* user, xmlErrorPtr error) {
    auto* sink = static_cast<ErrorSink*>(user);
    if (!error || !sink) return;
    std::string message = error->message ? error->message : "schema error";
    while (!message.empty() && (message.back() == '\n' || message.back() == ' ')) message.pop_back();
    sink->diagnostics->emplace(Severity::error, "xml-schema", message, sink->path,
                               SourcePos{static_cast<std::uint32_t>(error->line > 0 ? error->line : 0), error->line > 0 ? 1u : 0u});
}

xmlSchemaPtr load_schema(const std::filesystem::path& file, Diagnostics& diagnostics) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(file, ec)) return nullptr;
    ErrorSink sink{&diagnostics, file.string()};
    xmlSchemaParserCtxtPtr parser = xmlSchemaNewParserCtxt(file.c_str());
    if (!parser) return nullptr;
    xmlSchemaSetParserStructuredErrors(parser, structured_error, &sink);
    xmlSchemaPtr schema = xmlSchemaParse(parser);
    xmlSchemaFreeParserCtxt(parser);
    return schema;
}

}  // namespace

SchemaSet::~SchemaSet() = default;

std::shared_ptr<SchemaSet> SchemaSet::load(const std::filesystem::path& dir, Diagnostics& diagnostics) {
    std::call_once(libxml_init, [] { xmlInitParser(); });
    std::shared_ptr<SchemaSet> set(new SchemaSet());
    set->impl_ = std::make_unique<Impl>();
    Diagnostics schema_problems;
    set->impl_->info = load_schema(dir / "EtherCATInfo.xsd", schema_problems);
    set->impl_->module = load_schema(dir / "EtherCATModule.xsd", schema_problems);
    set->impl_->dict = load_schema(dir / "EtherCATDict.xsd", schema_problems);
    if (!set->impl_->info) {
        diagnostics.emplace(Severity::error, "io-error", "no usable EtherCATInfo.xsd in " + dir.string(), dir.string(), {});
        diagnostics.append(std::move(schema_problems));
    }
    return set;
}

Diagnostics SchemaSet::validate(const SourceText& source) const {
    Diagnostics out;
    ErrorSink sink{&out, source.path()};
    // The text is already UTF-8; tell libxml2 so, whatever the declaration says. Never load
    // external entities or DTDs from the network.
    const int parse_options = XML_PARSE_NONET | XML_PARSE_NOERROR | XML_PARSE_NOWARNING | XML_PARSE_HUGE;
    xmlDocPtr doc = xmlReadMemory(source.text().data(), static_cast<int>(source.text().size()), source.path().c_str(), "UTF-8",
                                  parse_options);
    if (!doc) return out;  // not well-formed: the reader already said so
    const xmlNodePtr root = xmlDocGetRootElement(doc);
    xmlSchemaPtr schema = nullptr;
    if (root && root->name) {
        const std::string_view name = reinterpret_cast<const char*>(root->name);
        if (name == "EtherCATInfo") schema = impl_->info;
        else if (name == "EtherCATModule") schema = impl_->module;
        else if (name == "EtherCATDict") schema = impl_->dict;
    }
    if (schema) {
        xmlSchemaValidCtxtPtr context = xmlSchemaNewValidCtxt(schema);
        xmlSchemaSetValidStructuredErrors(context, structured_error, &sink);
        xmlSchemaValidateDoc(context, doc);
        xmlSchemaFreeValidCtxt(context);
    }
    xmlFreeDoc(doc);
    return out;
}

}  // namespace esi
