#include "index_cache.hpp"

#include <charconv>

namespace esi::net {

namespace {

constexpr std::string_view header = "libesi-esi-index 3";

std::uint64_t fnv1a(std::string_view text) {
    std::uint64_t h = 0xcbf29ce484222325ull;
    for (unsigned char c : text) {
        h ^= c;
        h *= 0x100000001b3ull;
    }
    return h;
}

std::string hex64(std::uint64_t v) {
    static constexpr char digits[] = "0123456789abcdef";
    std::string out(16, '0');
    for (int i = 15; i >= 0; --i, v >>= 4) out[static_cast<std::size_t>(i)] = digits[v & 0xF];
    return out;
}

std::string escape(std::string_view text) {
    std::string out;
    out.reserve(text.size());
    for (char c : text) {
        if (c == '\\') out += "\\\\";
        else if (c == '\t') out += "\\t";
        else if (c == '\n') out += "\\n";
        else out += c;
    }
    return out;
}

std::optional<std::string> unescape(std::string_view text) {
    std::string out;
    out.reserve(text.size());
    for (std::size_t i = 0; i < text.size(); ++i) {
        if (text[i] != '\\') {
            out += text[i];
            continue;
        }
        if (++i == text.size()) return std::nullopt;
        if (text[i] == '\\') out += '\\';
        else if (text[i] == 't') out += '\t';
        else if (text[i] == 'n') out += '\n';
        else return std::nullopt;
    }
    return out;
}

// Splits off the next space-separated field.
std::optional<std::string_view> field(std::string_view& line) {
    const std::size_t space = line.find(' ');
    if (space == std::string_view::npos || space == 0) return std::nullopt;
    const std::string_view out = line.substr(0, space);
    line.remove_prefix(space + 1);
    return out;
}

template <class T>
bool number(std::string_view text, T& out) {
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), out);
    return ec == std::errc{} && end == text.data() + text.size();
}

bool optional_u32(std::string_view text, std::optional<std::uint32_t>& out) {
    if (text == "-") {
        out.reset();
        return true;
    }
    std::uint32_t v = 0;
    if (!number(text, v)) return false;
    out = v;
    return true;
}

std::string format_optional(const std::optional<std::uint32_t>& v) { return v ? std::to_string(*v) : "-"; }

}  // namespace

std::optional<IndexCache> parse_index_cache(std::string_view text) {
    IndexCache cache;
    std::size_t pos = 0;
    auto next_line = [&]() -> std::optional<std::string_view> {
        if (pos >= text.size()) return std::nullopt;
        const std::size_t nl = text.find('\n', pos);
        if (nl == std::string_view::npos) return std::nullopt;  // every line ends with a newline
        const std::string_view line = text.substr(pos, nl - pos);
        pos = nl + 1;
        return line;
    };
    const auto first = next_line();
    if (!first || *first != header) return std::nullopt;
    CachedFile* current = nullptr;
    std::size_t expected_devices = 0;
    for (;;) {
        const auto line_opt = next_line();
        if (!line_opt) return std::nullopt;  // no end line: truncated
        std::string_view line = *line_opt;
        if (line.starts_with("end ")) {
            std::string_view rest = line.substr(4);
            const auto count_text = field(rest);
            std::size_t count = 0;
            if (!count_text || !number(*count_text, count) || count != cache.size()) return std::nullopt;
            if (rest != hex64(fnv1a(text.substr(0, pos - line.size() - 1)))) return std::nullopt;
            if (current && current->devices.size() != expected_devices) return std::nullopt;
            return pos == text.size() ? std::optional<IndexCache>(std::move(cache)) : std::nullopt;
        }
        if (line.size() < 2 || line[1] != ' ') return std::nullopt;
        const char kind = line[0];
        line.remove_prefix(2);
        if (kind == 'F') {
            if (current && current->devices.size() != expected_devices) return std::nullopt;
            CachedFile file;
            const auto size = field(line), mtime = field(line), ctime = field(line), inode = field(line), count = field(line);
            if (!size || !mtime || !ctime || !inode || !count || !number(*size, file.file.size) || !number(*mtime, file.file.mtime_ns) ||
                !number(*ctime, file.file.ctime_ns) || !number(*inode, file.file.inode) || !number(*count, expected_devices))
                return std::nullopt;
            const auto path = unescape(line);
            if (!path || path->empty()) return std::nullopt;
            file.file.path = *path;
            auto [it, inserted] = cache.emplace(*path, std::move(file));
            if (!inserted) return std::nullopt;
            current = &it->second;
        } else if (kind == 'H') {
            if (!current || current->devices.empty()) return std::nullopt;
            HiddenIdentity h;
            const auto product = field(line);
            if (!product || !optional_u32(*product, h.product_code) || !optional_u32(line, h.revision_no)) return std::nullopt;
            current->devices.back().hides.push_back(h);
        } else if (kind == 'P') {
            const auto problem = unescape(line);
            if (!current || !problem) return std::nullopt;
            current->file.problem = *problem;
        } else if (kind == 'D') {
            if (!current) return std::nullopt;
            IndexedDevice d;
            const auto vendor = field(line), product = field(line), revision = field(line), offset = field(line),
                       line_no = field(line), column = field(line), ordinal = field(line);
            if (!vendor || !product || !revision || !offset || !line_no || !column || !ordinal) return std::nullopt;
            if (!optional_u32(*vendor, d.vendor_id) || !optional_u32(*product, d.product_code) ||
                !optional_u32(*revision, d.revision_no) || !number(*offset, d.offset) || !number(*line_no, d.line) ||
                !number(*column, d.column) || !number(*ordinal, d.ordinal))
                return std::nullopt;
            const std::size_t tab = line.find('\t');
            if (tab == std::string_view::npos) return std::nullopt;
            const std::size_t tab2 = line.find('\t', tab + 1);
            if (tab2 == std::string_view::npos) return std::nullopt;
            const auto type = unescape(line.substr(0, tab));
            const auto name = unescape(line.substr(tab + 1, tab2 - tab - 1));
            const auto vendor_name = unescape(line.substr(tab2 + 1));
            if (!type || !name || !vendor_name) return std::nullopt;
            d.type = *type;
            d.name = *name;
            d.vendor_name = *vendor_name;
            current->devices.push_back(std::move(d));
        } else {
            return std::nullopt;
        }
    }
}

std::string format_index_cache(const IndexCache& cache) {
    std::string out(header);
    out += '\n';
    for (const auto& [path, entry] : cache) {
        out += "F " + std::to_string(entry.file.size) + ' ' + std::to_string(entry.file.mtime_ns) + ' ' +
               std::to_string(entry.file.ctime_ns) + ' ' + std::to_string(entry.file.inode) + ' ' + std::to_string(entry.devices.size()) +
               ' ' + escape(path) + '\n';
        if (!entry.file.problem.empty()) out += "P " + escape(entry.file.problem) + '\n';
        for (const IndexedDevice& d : entry.devices) {
            out += "D " + format_optional(d.vendor_id) + ' ' + format_optional(d.product_code) + ' ' +
                   format_optional(d.revision_no) + ' ' + std::to_string(d.offset) + ' ' + std::to_string(d.line) + ' ' +
                   std::to_string(d.column) + ' ' + std::to_string(d.ordinal) + ' ' + escape(d.type) + '\t' + escape(d.name) + '\t' + escape(d.vendor_name) +
                   '\n';
            for (const HiddenIdentity& h : d.hides)
                out += "H " + format_optional(h.product_code) + ' ' + format_optional(h.revision_no) + '\n';
        }
    }
    const std::uint64_t checksum = fnv1a(out);
    out += "end " + std::to_string(cache.size()) + ' ' + hex64(checksum) + '\n';
    return out;
}

}  // namespace esi::net
