#include "esi/check/registry.hpp"

#include <algorithm>

#include "check/areas.hpp"
#include "check/rule_cache.hpp"
#include "esi/text_distance.hpp"

namespace esi {

namespace {
std::vector<Rule> build_catalogue() {
    std::vector<Rule> rules;
    rules::add_xml(rules);
    rules::add_identity(rules);
    rules::add_sm(rules);
    rules::add_sm_esc(rules);
    rules::add_fmmu(rules);
    rules::add_pdo_structure(rules);
    rules::add_pdo_entry(rules);
    rules::add_pdo_object(rules);
    rules::add_pdo_default(rules);
    rules::add_od_type(rules);
    rules::add_od_object(rules);
    rules::add_od_structure(rules);
    rules::add_mailbox(rules);
    rules::add_initcmd(rules);
    rules::add_dc(rules);
    rules::add_eeprom(rules);
    rules::add_deprecated(rules);
    rules::add_profile(rules);
    rules::add_profile_device(rules);
    std::sort(rules.begin(), rules.end(), [](const Rule& a, const Rule& b) { return a.id < b.id; });
    return rules;
}
}  // namespace

std::span<const Rule> all_rules() {
    static const std::vector<Rule> catalogue = build_catalogue();
    return catalogue;
}

const Rule* find_rule(std::string_view id) {
    const auto rules = all_rules();
    const auto it = std::lower_bound(rules.begin(), rules.end(), id, [](const Rule& r, std::string_view key) { return r.id < key; });
    return it != rules.end() && it->id == id ? &*it : nullptr;
}

std::string_view nearest_rule_id(std::string_view id) {
    std::vector<std::string_view> ids;
    for (const Rule& r : all_rules()) ids.push_back(r.id);
    const std::string nearest = closest_match(id, ids);
    const Rule* rule = nearest.empty() ? nullptr : find_rule(nearest);
    return rule ? rule->id : std::string_view();  // the catalogue's own id: it outlives the call
}

RuleContext::RuleContext(const EsiDocument& document, const Rule& rule, Severity severity, const EffectiveConfig& config,
                         Diagnostics& sink, rules::RuleCache* cache)
    : document_(document), rule_(rule), severity_(severity), config_(config), sink_(sink), cache_(cache) {}

RuleContext::~RuleContext() = default;

rules::RuleCache& RuleContext::cache() {
    if (!cache_) {
        own_cache_ = std::make_unique<rules::RuleCache>();
        cache_ = own_cache_.get();
    }
    return *cache_;
}

void RuleContext::report(SourcePos pos, std::string message, std::vector<DiagnosticNote> notes) {
    Diagnostic& d = sink_.emplace(severity_, std::string(rule_.id), std::move(message), document_.path, pos);
    for (auto& note : notes) note.message = bounded_message(std::move(note.message));
    d.notes = std::move(notes);
}

void RuleContext::report(SourcePos pos, std::string message, std::optional<Fix> fix) {
    sink_.emplace(severity_, std::string(rule_.id), std::move(message), document_.path, pos).fix = std::move(fix);
}

void RuleContext::report(SourcePos pos, std::string message, std::vector<DiagnosticNote> notes, std::optional<Fix> fix) {
    Diagnostic& d = sink_.emplace(severity_, std::string(rule_.id), std::move(message), document_.path, pos);
    for (auto& note : notes) note.message = bounded_message(std::move(note.message));
    d.notes = std::move(notes);
    d.fix = std::move(fix);
}

}  // namespace esi
