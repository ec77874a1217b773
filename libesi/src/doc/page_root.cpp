#include "doc/page_root.hpp"

#include "esi/version.hpp"

namespace esi::doc {

void add_common(PageObject& root, const PageCommon& common) {
    root.add("generator", ViewValue::of_static("esi-doc"));
    root.add("version", ViewValue::of_static(version()));
    root.add("source_file", common.source_file);
    root.add("lang", common.lang);
    root.add("languages", common.languages);
    root.add("css", common.css);
    root.add("vendor_name", common.vendor_name);
    root.add("vendor_id_hex", common.vendor_id_hex);
}

namespace {
void add_names(const Names& names, std::set<std::uint32_t>& lcids) {
    for (const auto& n : names) lcids.insert(n.lcid.value_or(default_lcid));
}
}  // namespace

void collect_languages(const EtherCATInfo& info, std::set<std::uint32_t>& lcids) {
    if (info.vendor) add_names(info.vendor->names, lcids);
    for (const Group& g : info.groups) add_names(g.names, lcids);
    for (const Device& d : info.devices) add_names(d.names, lcids);
    for (const Module& m : info.modules) add_names(m.names, lcids);
}

std::string languages_text(const std::set<std::uint32_t>& lcids) {
    std::string out;
    for (const std::uint32_t lcid : lcids) {
        const auto code = language_of_lcid(lcid);
        out += (out.empty() ? "" : ", ") + (code ? std::string(*code) : "LcId " + std::to_string(lcid));
    }
    return out;
}

std::string html_lang(std::uint32_t lcid) {
    const auto code = language_of_lcid(lcid);
    return code ? std::string(*code) : std::string("en");
}

std::uint32_t page_language(std::uint32_t lcid, const std::set<std::uint32_t>& file_lcids) {
    if (file_lcids.contains(lcid)) return lcid;
    if (file_lcids.empty() || file_lcids.contains(default_lcid)) return default_lcid;
    return *file_lcids.begin();
}

}  // namespace esi::doc
