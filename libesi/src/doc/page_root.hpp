#pragma once
// The fields every page's view starts with (docs/esi-doc.md): generator, source file, language,
// the stylesheet to inline, the vendor.

#include <set>
#include <string>

#include "doc/page_context.hpp"

namespace esi::doc {

struct PageCommon {
    std::string source_file;  // file name only: pages do not depend on where the file was
    std::string lang;         // the page's HTML lang
    std::string languages;    // the file's languages, "en, de"
    std::string css;
    std::string vendor_name;
    std::string vendor_id_hex;
};

// Adds the common fields to a page's root object.
void add_common(PageObject& root, const PageCommon& common);

// The languages an EtherCATInfo's names come in (vendor, groups, devices, modules), by code or LcId.
void collect_languages(const EtherCATInfo& info, std::set<std::uint32_t>& lcids);
[[nodiscard]] std::string languages_text(const std::set<std::uint32_t>& lcids);

// The HTML lang of a page in language `lcid` ("en" for an LcId without a code).
[[nodiscard]] std::string html_lang(std::uint32_t lcid);

// The language a page's names are in when `lcid` was asked for and the file's names come in
// `file_lcids` (collect_languages): `lcid` when the file has it, else English as localized_text
// falls back to it (texts without LcId count as English), else the file's lowest LcId. <html
// lang> must name the language the page is read in (WCAG 2.1, 3.1.1), not the one asked for.
[[nodiscard]] std::uint32_t page_language(std::uint32_t lcid, const std::set<std::uint32_t>& file_lcids);

}  // namespace esi::doc
