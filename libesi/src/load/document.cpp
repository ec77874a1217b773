#include "esi/load/document.hpp"

#include "esi/io/read_file.hpp"
#include "esi/xml/reader.hpp"
#include "esi/yaml/source.hpp"

namespace esi {

namespace {

bool is_blank(unsigned char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n'; }

bool has_yaml_extension(const std::filesystem::path& path) {
    const std::string ext = path.extension().string();
    return ext == ".yaml" || ext == ".yml";
}

LoadedDocument from_device_source(DeviceSource source) {
    LoadedDocument out;
    out.format = DocumentFormat::yaml_source;
    out.document = std::move(source.document);
    out.diagnostics = std::move(source.diagnostics);
    out.device_limits = std::move(source.device_limits);
    return out;
}

}  // namespace

DocumentFormat document_format(std::string_view bytes, const std::filesystem::path& path) {
    auto byte = [&](std::size_t i) { return static_cast<unsigned char>(bytes[i]); };
    std::size_t i = 0;
    std::size_t step = 1;  // bytes per code unit: 2 in UTF-16
    if (bytes.size() >= 3 && byte(0) == 0xEF && byte(1) == 0xBB && byte(2) == 0xBF) {
        i = 3;
    } else if (bytes.size() >= 2 && ((byte(0) == 0xFF && byte(1) == 0xFE) || (byte(0) == 0xFE && byte(1) == 0xFF))) {
        i = 2;
        step = 2;
    } else if (bytes.size() >= 2 && (byte(0) == 0 || byte(1) == 0)) {
        step = 2;  // UTF-16 without a byte-order mark: every ASCII character has a zero byte
    }
    for (; i + step <= bytes.size(); i += step) {
        // In UTF-16 the ASCII byte is the non-zero one of the pair, whichever the byte order.
        const unsigned char c = step == 2 ? static_cast<unsigned char>(byte(i) | byte(i + 1)) : byte(i);
        if (is_blank(c)) continue;
        return c == '<' ? DocumentFormat::esi_xml : DocumentFormat::yaml_source;
    }
    return has_yaml_extension(path) ? DocumentFormat::yaml_source : DocumentFormat::esi_xml;
}

bool LoadedDocument::usable() const {
    if (!document) return false;
    return format == DocumentFormat::esi_xml || !diagnostics.has_errors();
}

LoadedDocument load_document(std::string bytes, const std::string& path) {
    if (document_format(bytes, path) == DocumentFormat::yaml_source) return from_device_source(load_device_source(bytes, path));
    LoadedDocument out;
    ReadResult read = read_esi_owned(std::move(bytes), path);
    out.document = std::move(read.document);
    out.diagnostics = std::move(read.diagnostics);
    return out;
}

LoadedDocument load_document_file(const std::filesystem::path& path) {
    // A file named as a YAML source is read under the YAML front end's own (smaller) bounds, so
    // that an oversized file or an endless stream given as one stops early; any other file is
    // read whole and told apart by its content.
    if (has_yaml_extension(path)) return from_device_source(load_device_source_file(path));
    std::string error;
    std::optional<std::string> bytes = read_file_bytes(path, error);
    if (!bytes) {
        LoadedDocument out;
        out.diagnostics.emplace(Severity::error, "io-error", "cannot read file: " + error, path.string(), SourcePos{});
        return out;
    }
    return load_document(std::move(*bytes), path.string());
}

}  // namespace esi
