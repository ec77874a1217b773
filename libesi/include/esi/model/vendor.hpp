#pragma once
#include "esi/model/common.hpp"

namespace esi {

struct Vendor {
    std::optional<std::uint32_t> id;  // Vendor/Id
    SourcePos id_pos;
    Names names;
    Names comments;
    Names urls;
    std::optional<std::string> description_url;
    Images images;
    std::optional<std::string> unique_name;   // @UniqueName (deprecated, CTT 5-2)
    std::optional<std::string> file_version;  // @FileVersion
    SourcePos pos;
    Extras extras;
};

struct Group {
    std::string type;  // Group/Type: the key Device/GroupType refers to
    SourcePos type_pos;
    Names names;
    Names comments;
    Images images;
    std::optional<std::int32_t> sort_order;
    std::optional<std::string> parent_group;
    SourcePos pos;
    Extras extras;
};

}  // namespace esi
