#pragma once
// A lint rule: an id, a default severity, a rationale that cites its source, examples, and a
// check over the model. Rules never print; they report through a RuleContext.

#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "esi/check/effective_config.hpp"
#include "esi/diagnostic.hpp"
#include "esi/model/ethercat_info.hpp"

namespace esi {

class RuleContext;
namespace rules {
class RuleCache;  // indexes of the document's Dictionaries shared by the rules (libesi/src/check)
}

using CheckFunction = void (*)(const EsiDocument& document, RuleContext& context);

// Defined with designated initialisers right below its check function, e.g.
//   constexpr Rule sm_overlap{.id = "sm-overlap", .default_severity = Severity::error, …,
//                             .check = check_overlap};
struct Rule {
    std::string_view id;  // kebab-case, prefixed by area: sm-…, pdo-…, od-…
    Severity default_severity = Severity::warning;
    std::string_view summary;    // one line
    std::string_view rationale;  // why it matters, with its source (ETG document, manual, field failure)
    std::string_view bad_example;
    std::string_view good_example;
    // Null for rules whose diagnostics come from a front end (xml-syntax …) or another stage.
    CheckFunction check = nullptr;
    // What esi-lint --fix does to the rule's findings (Diagnostic::fix); empty: no safe fix.
    std::string_view fix = {};
};

// What a rule sees while it runs: the document, the limits that apply, and a way to report.
class RuleContext {
public:
    // `cache`, when given, is shared by all rules run over this document (run_rules), so indexes
    // and object layouts are built once; without it the context builds its own.
    RuleContext(const EsiDocument& document, const Rule& rule, Severity severity, const EffectiveConfig& config,
                Diagnostics& sink, rules::RuleCache* cache = nullptr);
    ~RuleContext();
    RuleContext(const RuleContext&) = delete;
    RuleContext& operator=(const RuleContext&) = delete;

    [[nodiscard]] const EsiDocument& document() const { return document_; }
    // The vendor limits that apply to a device (overrides may scope limits by product code).
    [[nodiscard]] const Limits& limits_for(const Device& device) const { return config_.limits_for(device.type.product_code); }
    [[nodiscard]] const Limits& limits() const { return config_.limits; }
    [[nodiscard]] const Rule& rule() const { return rule_; }
    [[nodiscard]] rules::RuleCache& cache();

    void report(SourcePos pos, std::string message, std::vector<DiagnosticNote> notes = {});
    // A finding with a safe fix (esi-lint --fix); `fix` absent reports it without one.
    void report(SourcePos pos, std::string message, std::optional<Fix> fix);
    void report(SourcePos pos, std::string message, std::vector<DiagnosticNote> notes, std::optional<Fix> fix);
    // A note pointing at another place in the same file.
    [[nodiscard]] DiagnosticNote note(SourcePos pos, std::string message) const {
        return DiagnosticNote{document_.path, pos, std::move(message)};
    }

private:
    const EsiDocument& document_;
    const Rule& rule_;
    Severity severity_;
    const EffectiveConfig& config_;
    Diagnostics& sink_;
    rules::RuleCache* cache_;
    std::unique_ptr<rules::RuleCache> own_cache_;
};

}  // namespace esi
