#pragma once
// The one table that says how bad each kind of change is, and why. Every class esi-diff reports
// comes from here (plus the revision context below); docs/esi-diff.md prints the same table.

#include <span>
#include <string_view>

#include "esi/diff/change.hpp"

namespace esi {

struct ChangeKindInfo {
    ChangeKind kind;
    std::string_view id;  // stable kebab-case id used in every output format
    ChangeClass change_class;
    std::string_view reason;  // why a master configured from the old file is (not) affected
};

// All kinds in declaration order.
[[nodiscard]] std::span<const ChangeKindInfo> change_kinds();
[[nodiscard]] const ChangeKindInfo& info(ChangeKind kind);
[[nodiscard]] std::string_view to_string(ChangeKind kind);

// How the compared device pair relates: the same identity on both sides, a new revision whose
// predecessor the new file no longer describes (it replaces it), or a new revision added next to
// a predecessor that is still described.
enum class RevisionContext { same_revision, replaced_revision, added_revision };

// The class of a change of `kind` found while comparing devices in `context`. An added revision
// leaves every configuration made from the old file valid (the old revision is still there), so
// what differs from its predecessor is at most compatible.
[[nodiscard]] ChangeClass classify(ChangeKind kind, RevisionContext context = RevisionContext::same_revision);

// The kinds that are reported as errors (a rule was broken) rather than as differences.
[[nodiscard]] bool is_error(ChangeKind kind);

}  // namespace esi
