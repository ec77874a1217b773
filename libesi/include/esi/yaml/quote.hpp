#pragma once
// A YAML double-quoted scalar that the project's YAML reader (libyaml) reads back as exactly
// the text written, whatever the text holds: every writer of YAML in libesi (the importer,
// `esi-net init`) quotes outside text through this.
//
// The reader takes not only LF and CR for line breaks but also NEL (U+0085), LINE SEPARATOR
// (U+2028) and PARAGRAPH SEPARATOR (U+2029) (YAML 1.1 b-char); written raw inside quotes they
// would be folded into a space, and anywhere else (a comment) they end the line. So they are
// escaped (\N, \L, \P), as are the C0 and C1 controls, DEL, surrogates, U+FEFF, U+FFFE and
// U+FFFF, which YAML does not allow raw. Bytes that are not UTF-8 have no YAML spelling: the
// caller learns of them (`ok` false) and refuses the text; they are written \xNN meanwhile so
// that the result is still one valid scalar.

#include <string>
#include <string_view>

namespace esi::yaml {

struct QuotedText {
    std::string text;  // "…", with the quotes
    bool ok = true;    // false: the input held bytes that are not UTF-8
};

// `ascii_only`: every character outside printable ASCII is escaped too, so the result can go
// into a comment or any line without changing it.
[[nodiscard]] QuotedText double_quoted(std::string_view text, bool ascii_only = false);

}  // namespace esi::yaml
