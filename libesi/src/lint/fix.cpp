#include "esi/lint/fix.hpp"

#include <algorithm>
#include <map>
#include <utility>

#include "esi/encoding.hpp"
#include "esi/io/atomic_write.hpp"
#include "esi/io/read_file.hpp"
#include "esi/lint/config.hpp"

namespace esi {

namespace {

bool is_ascii(std::string_view text) {
    return std::all_of(text.begin(), text.end(), [](char c) { return static_cast<unsigned char>(c) < 0x80; });
}

// Maps offsets in the decoded UTF-8 text to offsets in the file's bytes.
class OffsetMap {
public:
    OffsetMap(const DecodedText& decoded) : decoded_(decoded) {
        switch (decoded.encoding) {
            case SourceEncoding::utf8: break;
            case SourceEncoding::utf8_bom: shift_ = 3; break;
            case SourceEncoding::latin1:
            case SourceEncoding::windows1252: single_byte_ = true; break;
            case SourceEncoding::utf16le:
            case SourceEncoding::utf16be: why_not_ = "UTF-16 files are not fixed"; break;
        }
        if (decoded.first_invalid_offset != std::string::npos) why_not_ = "the file has bytes that are not valid in its encoding";
    }
    [[nodiscard]] const std::string& why_not() const { return why_not_; }

    // nullopt when the edit cannot be expressed in the file's encoding byte for byte.
    std::optional<TextEdit> to_bytes(const TextEdit& edit) {
        if (edit.offset + edit.length > decoded_.utf8.size()) return std::nullopt;
        if (!single_byte_) return TextEdit{edit.offset + shift_, edit.length, edit.replacement};
        // One byte per character: a replacement must be ASCII to keep that (the replaced text may be
        // anything, e.g. a removed copy with umlauts: its length in bytes is its count of characters).
        if (!is_ascii(edit.replacement)) return std::nullopt;
        if (edit.offset < decoded_at_) decoded_at_ = raw_at_ = 0;  // edits come in order; restart otherwise
        advance_to(edit.offset);
        const std::size_t raw_offset = raw_at_;
        advance_to(edit.offset + edit.length);
        return TextEdit{raw_offset, raw_at_ - raw_offset, edit.replacement};
    }

private:
    void advance_to(std::size_t decoded_offset) {
        for (; decoded_at_ < decoded_offset; ++decoded_at_)
            if ((static_cast<unsigned char>(decoded_.utf8[decoded_at_]) & 0xC0) != 0x80) ++raw_at_;
    }

    const DecodedText& decoded_;
    std::size_t shift_ = 0;
    bool single_byte_ = false;
    std::string why_not_;
    std::size_t decoded_at_ = 0;
    std::size_t raw_at_ = 0;
};

using FindingKey = std::pair<std::string, std::string>;  // rule, message: positions move with the edits

std::map<FindingKey, int> findings_of(const Diagnostics& diagnostics) {
    std::map<FindingKey, int> out;
    for (const auto& d : diagnostics) ++out[{d.rule, d.message}];
    return out;
}

}  // namespace

FixedText apply_fixes(std::string_view original, const std::string& path, const EffectiveConfig& config) {
    FixedText out;
    out.original = std::string(original);
    out.bytes = out.original;
    const FileReport before = lint_bytes(original, path, config);
    std::vector<const Diagnostic*> fixable;
    for (const auto& d : before.diagnostics)
        if (d.fix && !d.fix->edits.empty()) fixable.push_back(&d);
    if (fixable.empty()) return out;

    const DecodedText decoded = decode_xml_bytes(original);
    OffsetMap map(decoded);
    if (!map.why_not().empty()) {
        out.refused = map.why_not();
        return out;
    }
    // Whole fixes, in file order; a fix that overlaps one taken before waits for the next run.
    std::sort(fixable.begin(), fixable.end(),
              [](const Diagnostic* a, const Diagnostic* b) { return a->fix->edits.front().offset < b->fix->edits.front().offset; });
    std::vector<TextEdit> edits;
    std::vector<const Diagnostic*> fixed;
    std::size_t end_of_last = 0;
    for (const Diagnostic* d : fixable) {
        std::vector<TextEdit> mapped;
        bool usable = true;
        std::size_t end = end_of_last;
        for (const TextEdit& edit : d->fix->edits) {
            std::optional<TextEdit> m = map.to_bytes(edit);
            if (!m || m->offset < end) {
                usable = false;
                break;
            }
            end = m->offset + m->length;
            mapped.push_back(std::move(*m));
        }
        if (!usable) continue;
        end_of_last = end;
        edits.insert(edits.end(), mapped.begin(), mapped.end());
        fixed.push_back(d);
    }
    std::string result;
    result.reserve(original.size());
    std::size_t at = 0;
    for (const TextEdit& e : edits) {
        result.append(original.substr(at, e.offset - at));
        result.append(e.replacement);
        at = e.offset + e.length;
    }
    result.append(original.substr(at));

    // lint → fix → lint: every fixed finding is gone, and no finding is new.
    std::map<FindingKey, int> expected = findings_of(before.diagnostics);
    for (const Diagnostic* d : fixed) --expected[{d->rule, d->message}];
    const FileReport after = lint_bytes(result, path, config);
    for (const auto& [key, count] : findings_of(after.diagnostics)) {
        const auto it = expected.find(key);
        if (it == expected.end() || count > it->second) {
            out.refused = "fixing would leave or make the finding '" + key.second + "' [" + key.first + "]";
            return out;
        }
    }
    out.bytes = std::move(result);
    out.edits = std::move(edits);
    out.applied = fixed.size();
    return out;
}

FixedText fix_file(const std::filesystem::path& path, const LintOptions& options) {
    FixedText refused;
    std::string error;
    std::optional<std::string> bytes = read_file_bytes(path, error);
    if (!bytes) {
        refused.refused = "cannot read: " + error;
        return refused;
    }
    EffectiveConfig config;
    std::optional<std::filesystem::path> config_path = options.config_path;
    if (!config_path) config_path = find_config_for(path);
    if (config_path) {
        const ConfigResult loaded = load_lint_config(*config_path);
        if (!loaded.config) {
            refused.original = *bytes;
            refused.bytes = std::move(*bytes);
            refused.refused = "its configuration " + config_path->string() + " has errors";
            return refused;
        }
        config = effective_config(*loaded.config, path);
    }
    return apply_fixes(*bytes, path.string(), config);
}

Diagnostics write_fixed_file(const std::filesystem::path& path, const FixedText& fixed) {
    std::error_code ec;
    const std::filesystem::perms permissions = std::filesystem::status(path, ec).permissions();
    Diagnostics out = write_file_atomically(path, fixed.bytes);
    if (!out.has_errors() && !ec) {
        std::filesystem::permissions(path, permissions, ec);
        if (ec) out.emplace(Severity::warning, "io-error", "fixed, but its permissions could not be restored: " + ec.message(), path.string(), {});
    }
    return out;
}

}  // namespace esi
