#include "esi/lsp/lint_document.hpp"

#include "esi/encoding.hpp"
#include "esi/load/document.hpp"
#include "esi/lint/config.hpp"

namespace esi::lsp {

namespace {

// The text in the 8-bit encoding its declaration names, when every character has a byte there.
std::optional<std::string> encode_8bit(std::string_view utf8) {
    std::string out;
    out.reserve(utf8.size());
    for (std::size_t i = 0; i < utf8.size(); ++i) {
        const auto c = static_cast<unsigned char>(utf8[i]);
        if (c < 0x80) {
            out += static_cast<char>(c);
        } else if ((c == 0xC2 || c == 0xC3) && i + 1 < utf8.size()) {
            // U+0080..U+00FF: two bytes, 110000xx 10xxxxxx.
            out += static_cast<char>(((c & 0x03) << 6) | (static_cast<unsigned char>(utf8[i + 1]) & 0x3F));
            ++i;
        } else {
            return std::nullopt;
        }
    }
    return out;
}

// Config problems are reported on the document's first line (the editor shows no other file's
// problems for it), with the config's own location in the message.
void report_config_problems(const Diagnostics& problems, const std::string& path, FileReport& report) {
    for (const Diagnostic& problem : problems) {
        Diagnostic d = problem;
        d.message = "in " + format_location(problem.path, problem.pos) + ": " + problem.message;
        d.path = path;
        d.pos = SourcePos{1, 1};
        d.fix.reset();
        report.diagnostics.add(std::move(d));
    }
}

}  // namespace

DocumentLint lint_document(std::string_view text, const std::string& path) {
    DocumentLint out;
    const std::string shown_path = path.empty() ? std::string("<buffer>") : path;
    LintConfig config;
    if (!path.empty()) {
        if (const std::optional<std::filesystem::path> config_path = find_config_for(path)) {
            ConfigResult loaded = load_lint_config(*config_path);
            if (loaded.diagnostics.has_errors() || !loaded.config) {
                // esi-lint lints nothing under a broken config; neither does the editor.
                out.report.path = shown_path;
                report_config_problems(loaded.diagnostics, shown_path, out.report);
                return out;
            }
            config = std::move(*loaded.config);
            report_config_problems(loaded.diagnostics, shown_path, out.report);
        }
    }
    const EffectiveConfig effective = effective_config(config, std::filesystem::path(path.empty() ? std::string("buffer.xml") : path));
    Diagnostics config_warnings = std::move(out.report.diagnostics);

    out.xml = document_format(text, path) == DocumentFormat::esi_xml;
    std::string_view bytes = text;
    std::optional<std::string> encoded;
    if (out.xml) {
        DecodedText decoded = decode_xml_bytes(text);
        out.fixes_apply = decoded.utf8 == text;
        if (!out.fixes_apply && (decoded.encoding == SourceEncoding::latin1 || decoded.encoding == SourceEncoding::windows1252)) {
            encoded = encode_8bit(text);
            if (encoded && decode_xml_bytes(*encoded).utf8 == text) {
                bytes = *encoded;
                out.fixes_apply = true;
            }
        }
    }
    out.report = lint_bytes(bytes, shown_path, effective);
    out.report.diagnostics.append(std::move(config_warnings));
    out.report.diagnostics.sort();
    return out;
}

}  // namespace esi::lsp
