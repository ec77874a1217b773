#include "esi/xml/foreign_root.hpp"

#include <array>
#include <utility>

namespace esi {

namespace {

// Roots found in the corpus beside ESI files (shared/corpus/eni, master-configs) and the project
// files of the configuration tools that write them.
constexpr std::array<std::pair<std::string_view, std::string_view>, 5> known_roots{{
    {"EtherCATConfig", "an ENI (ETG.2100 network configuration)"},
    {"EncryptedEtherCATConfig", "an encrypted ENI (TwinCAT)"},
    {"masters", "a linuxcnc-ethercat (lcec) master configuration"},
    {"EtherCATMailbox", "a list of mailbox init commands (the ENI InitCmds grammar)"},
    {"TcSmProject", "a TwinCAT project"},
}};

bool is_name_char(char c) {
    return c != ' ' && c != '\t' && c != '\r' && c != '\n' && c != '>' && c != '/' && c != '\0';
}

}  // namespace

std::optional<ForeignDocument> recognise_foreign_root(std::string_view root_name) {
    for (const auto& [root, what] : known_roots)
        if (root_name == root) return ForeignDocument{std::string(root), what};
    return std::nullopt;
}

std::string first_element_name(std::string_view xml) {
    std::size_t i = 0;
    while (i < xml.size()) {
        const std::size_t open = xml.find('<', i);
        if (open == std::string_view::npos || open + 1 >= xml.size()) return {};
        const std::string_view rest = xml.substr(open);
        std::string_view close;
        if (rest.starts_with("<?")) close = "?>";
        else if (rest.starts_with("<!--")) close = "-->";
        else if (rest.starts_with("<!")) close = ">";  // DOCTYPE; an internal subset is skipped bracket by bracket below
        if (close.empty()) {
            std::size_t end = open + 1;
            while (end < xml.size() && is_name_char(xml[end])) ++end;
            std::string_view name = xml.substr(open + 1, end - open - 1);
            if (const std::size_t colon = name.find(':'); colon != std::string_view::npos) name.remove_prefix(colon + 1);
            return std::string(name);
        }
        std::size_t from = open + 2;
        if (close == ">") {
            // <!DOCTYPE root [ <!ENTITY …> … ]>: skip past the internal subset's closing bracket.
            const std::size_t bracket = xml.find('[', from);
            const std::size_t gt = xml.find('>', from);
            if (bracket != std::string_view::npos && bracket < gt) {
                const std::size_t end_subset = xml.find(']', bracket);
                if (end_subset == std::string_view::npos) return {};
                from = end_subset;
            }
        }
        const std::size_t end = xml.find(close, from);
        if (end == std::string_view::npos) return {};
        i = end + close.size();
    }
    return {};
}

std::optional<ForeignDocument> recognise_foreign_document(std::string_view xml) {
    return recognise_foreign_root(first_element_name(xml));
}

}  // namespace esi
