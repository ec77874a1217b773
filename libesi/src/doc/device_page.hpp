#pragma once
// The page model of one device: its identity and its sections (docs/esi-doc.md, "The page
// view"), built from the model into the view the device template renders.

#include <string>

#include "doc/page_context.hpp"
#include "esi/model/device.hpp"

namespace esi::doc {

// The `device` object of a page: identity, table of contents and every section.
[[nodiscard]] ViewValue device_view(const Device& device, const PageContext& context);

// A page for a file without devices: an EtherCATDict's dictionary or an EtherCATModule's
// modules, under `title`.
[[nodiscard]] ViewValue dictionary_file_view(const Dictionary& dictionary, const std::string& title, const PageContext& context);
[[nodiscard]] ViewValue module_file_view(const EtherCATInfo& info, const std::string& title, const PageContext& context);

// "Name (Type)" as index and page titles show a device.
[[nodiscard]] std::string device_title(const Device& device, const PageContext& context);

}  // namespace esi::doc
