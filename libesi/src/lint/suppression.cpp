#include "esi/lint/suppression.hpp"

#include <cstring>
#include <limits>

#include "esi/check/registry.hpp"
#include "esi/number.hpp"

namespace esi {

namespace {

constexpr std::uint32_t to_end = std::numeric_limits<std::uint32_t>::max();

std::vector<std::string> split_rules(std::string_view list) {
    std::vector<std::string> out;
    while (!list.empty()) {
        const auto comma = list.find(',');
        const std::string_view item = trim(list.substr(0, comma));
        if (!item.empty()) out.emplace_back(item);
        if (comma == std::string_view::npos) break;
        list.remove_prefix(comma + 1);
    }
    return out;
}
}  // namespace

bool Suppressions::suppresses(const Diagnostic& diagnostic) const {
    if (diagnostic.rule == "xml-syntax") return false;
    for (const auto& r : regions) {
        if (r.rule != "all" && r.rule != diagnostic.rule) continue;
        if (diagnostic.pos.line >= r.first_line && diagnostic.pos.line <= r.last_line) return true;
    }
    return false;
}

namespace {

constexpr std::string_view marker = "esi-lint:";

// Where the next directive's marker is, at or after `from`, with the comment around it ("<!--"
// at `open`, "-->" at `close`); npos when there is none. In the comments the reader found, when
// it read the text (the directive is the first marker of a comment); else in the whole text, with
// the comment around a marker told from the nearest "<!--" and "-->".
struct Found {
    std::size_t at = std::string_view::npos;
    std::size_t open = 0;
    std::size_t close = 0;
};

class MarkerSearch {
public:
    explicit MarkerSearch(const SourceText& source) : text_(source.text()), comments_(source.comments()) {}

    Found next(std::size_t from) {
        if (comments_) {
            for (; comment_ < comments_->size(); ++comment_) {
                const TextSpan c = (*comments_)[comment_];
                if (c.begin < from) continue;
                const std::size_t close = c.end - 3;
                const std::size_t at = text_.substr(0, close).find(marker, c.begin + 4);
                if (at != std::string_view::npos) {
                    ++comment_;
                    return {at, c.begin, close};
                }
            }
            return {};
        }
        for (std::size_t at = from; (at = find_marker(at)) != std::string_view::npos; at += marker.size()) {
            // Only inside a comment: the nearest "<!--" before must be after the nearest "-->".
            const auto open = text_.rfind("<!--", at);
            const auto close_before = text_.rfind("-->", at);
            const auto close = text_.find("-->", at);
            if (open == std::string_view::npos || (close_before != std::string_view::npos && close_before > open) ||
                close == std::string_view::npos)
                continue;
            return {at, open, close};
        }
        return {};
    }

private:
    // The marker is found by its ':', which ESI files hardly use outside namespace prefixes and
    // URLs, with memchr; std::string::find stopped at every 'e' of the file instead, about 3
    // instructions a byte over the whole text of every file linted.
    std::size_t find_marker(std::size_t from) const {
        for (std::size_t colon = from + marker.size() - 1; colon < text_.size(); ++colon) {
            const void* hit = std::memchr(text_.data() + colon, ':', text_.size() - colon);
            if (!hit) break;
            colon = static_cast<std::size_t>(static_cast<const char*>(hit) - text_.data());
            const std::size_t start = colon + 1 - marker.size();
            if (start >= from && text_.substr(start, marker.size()) == marker) return start;
        }
        return std::string_view::npos;
    }

    std::string_view text_;
    const std::vector<TextSpan>* comments_;
    std::size_t comment_ = 0;
};

}  // namespace

Suppressions find_suppressions(const SourceText& source, Diagnostics& diagnostics) {
    Suppressions out;
    const std::string_view text = source.text();
    MarkerSearch search(source);
    for (Found found = search.next(0); found.at != std::string_view::npos; found = search.next(found.close)) {
        const std::size_t at = found.at;
        const std::size_t open = found.open;
        const std::size_t close = found.close;
        const SourcePos pos = source.position_of(open);
        std::string_view body = trim(text.substr(at + marker.size(), close - at - marker.size()));
        const auto eq = body.find('=');
        const std::string_view verb = trim(body.substr(0, eq));
        if (eq == std::string_view::npos || (verb != "disable" && verb != "enable" && verb != "disable-next-line")) {
            diagnostics.emplace(Severity::warning, "lint-directive",
                                "unknown esi-lint directive '" + std::string(body) +
                                    "' (expected disable=, enable= or disable-next-line=)",
                                source.path(), pos);
            continue;
        }
        const std::uint32_t end_line = source.position_of(close).line;
        for (const std::string& rule : split_rules(body.substr(eq + 1))) {
            if (rule != "all" && !find_rule(rule)) {
                diagnostics.emplace(Severity::warning, "lint-directive", "esi-lint directive names unknown rule '" + rule + "'",
                                    source.path(), pos);
                continue;
            }
            if (verb == "disable") {
                out.regions.push_back({rule, pos.line, to_end});
            } else if (verb == "disable-next-line") {
                out.regions.push_back({rule, end_line + 1, end_line + 1});
            } else {
                // enable: close the open regions of this rule.
                for (auto& r : out.regions)
                    if (r.rule == rule && r.last_line == to_end) r.last_line = pos.line;
            }
        }
    }
    return out;
}

}  // namespace esi
