#pragma once
// Which pages esi-doc writes for a document and the view each page's template renders
// (docs/esi-doc.md, "The page view"): one device page per selected device, a page for a
// dictionary file or a module file, and the index. Building the views apart from rendering them
// lets the tests walk exactly the views the templates see (tests/doc/view_fields_test.cpp keeps
// the documented field list in step with them).

#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "doc/page_context.hpp"
#include "esi/device_selector.hpp"
#include "esi/model/ethercat_info.hpp"

namespace esi::doc {

// A page that is not about one device: an EtherCATDict's dictionary or an EtherCATModule's modules.
struct ExtraPage {
    std::string file;
    std::string title;
    const EtherCATInfo* info = nullptr;      // module file
    const Dictionary* dictionary = nullptr;  // dictionary file
};

struct PagePlan {
    std::vector<const Device*> devices;  // in document order
    std::vector<ExtraPage> extras;       // only without --device
    [[nodiscard]] bool empty() const { return devices.empty() && extras.empty(); }
};

[[nodiscard]] PagePlan plan_pages(const EsiDocument& document, const std::optional<DeviceSelector>& device);

enum class PageKind { device, index };

// Called once per page, the index last; `root` lives until the call returns.
using PageSink = std::function<void(PageKind kind, const std::filesystem::path& file, const ViewValue& root)>;

// The views of every page of `plan`, device pages (then extra pages) in order, then the index.
void build_page_views(const EsiDocument& document, const PagePlan& plan, const std::filesystem::path& output_dir, std::uint32_t lcid,
                      std::string css, const PageSink& sink);

}  // namespace esi::doc
