#pragma once
// The roots of an ESI file: EtherCATInfo (the usual case), EtherCATInfoList (several infos,
// e.g. written by the IgH tool), EtherCATModule (a module description file) and EtherCATDict
// (a separate dictionary file).

#include <memory>

#include "esi/encoding.hpp"
#include "esi/model/device.hpp"
#include "esi/model/vendor.hpp"
#include "esi/source_text.hpp"

namespace esi {

struct EtherCATInfo {
    std::optional<std::string> version;  // @Version
    std::optional<Vendor> vendor;
    bool has_descriptions = false;
    std::vector<Group> groups;
    std::vector<Device> devices;
    bool has_modules = false;  // a <Modules> element was present
    std::vector<Module> modules;
    SourcePos pos;
    SourcePos descriptions_pos;
    Extras extras;  // InfoReference, root namespace attributes
    Extras descriptions_extras;

    [[nodiscard]] const Group* find_group(std::string_view type) const;
};

// ethercat_diag: an ETG diagnosis-message file (EtherCATDiag.xsd), which describes no device; its
// content is kept in root_extras.
enum class DocumentKind { ethercat_info, ethercat_info_list, ethercat_module, ethercat_dict, ethercat_diag, unknown };

[[nodiscard]] std::string_view root_element_name(DocumentKind kind);

struct EsiDocument {
    DocumentKind kind = DocumentKind::unknown;
    std::string path;
    SourceEncoding encoding = SourceEncoding::utf8;
    // ethercat_info: one; ethercat_info_list: one per listed info; ethercat_module: one holding
    // Vendor and Modules.
    std::vector<EtherCATInfo> infos;
    std::optional<Dictionary> dictionary;  // ethercat_dict
    std::optional<std::string> dict_version;
    SourcePos root_pos;
    Extras root_extras;  // attributes and unknown children of an InfoList, Dict or Diag root
    // The decoded text, kept so that reports can quote source lines; may be null.
    SourceTextPtr source;

    // The catalogue that holds `device` (its Vendor, Groups and Modules); null when the device
    // is not one of this document's.
    [[nodiscard]] const EtherCATInfo* info_of(const Device& device) const;
};

}  // namespace esi
