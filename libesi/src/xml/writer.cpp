// ESI writer: the roots (EtherCATInfo, EtherCATInfoList, EtherCATModule, EtherCATDict), Vendor,
// Descriptions and Groups, and the helpers every element family shares. Element and attribute
// order follow ETG.2000 schema 1.17 (EtherCATInfo.xsd, EtherCATBase.xsd, EtherCATDict.xsd; the
// EtherCATModule root from EtherCATModule.xsd 1.14, the newest that has it).

#include "esi/xml/writer.hpp"

#include "esi/io/atomic_write.hpp"
#include "xml/writer_model.hpp"

namespace esi {

namespace xml_writer {

namespace {

constexpr std::string_view info_order[] = {"InfoReference", "Vendor", "Descriptions"};
constexpr std::string_view module_root_order[] = {"Vendor", "Modules"};
constexpr std::string_view descriptions_order[] = {"Groups", "Devices", "Modules"};
constexpr std::string_view info_list_order[] = {"EtherCATInfo"};
constexpr std::string_view dict_root_order[] = {"Dictionary"};
constexpr std::string_view vendor_order[] = {"Id",         "Name",           "Comment",        "URL",           "DescriptionURL",
                                             "Image16x14", "ImageFile16x14", "ImageData16x14", "VendorSpecific"};
constexpr std::string_view group_order[] = {"Type",           "Name",           "Comment",       "Image16x14",
                                            "ImageFile16x14", "ImageData16x14", "VendorSpecific"};

bool is_lower_hex(char c) { return c >= 'a' && c <= 'f'; }

void write_vendor(XmlEmitter& out, const Vendor& vendor) {
    out.begin("Vendor");
    put_text(out, "UniqueName", vendor.unique_name);
    put_text(out, "FileVersion", vendor.file_version);
    write_extra_attributes(out, vendor.extras);
    ChildPlacer children(out, vendor.extras, vendor_order);
    if (vendor.id) {
        children.at("Id");
        out.leaf("Id", identity_hex(*vendor.id).view());
    }
    write_names(out, children, "Name", vendor.names);
    write_names(out, children, "Comment", vendor.comments);
    write_names(out, children, "URL", vendor.urls);
    if (vendor.description_url) {
        children.at("DescriptionURL");
        out.leaf("DescriptionURL", *vendor.description_url);
    }
    write_images(out, children, vendor.images);
    children.finish();
    out.end();
}

void write_group(XmlEmitter& out, const Group& group) {
    out.begin("Group");
    put_decimal(out, "SortOrder", group.sort_order);
    put_text(out, "ParentGroup", group.parent_group);
    write_extra_attributes(out, group.extras);
    ChildPlacer children(out, group.extras, group_order);
    children.at("Type");
    out.leaf("Type", group.type);
    write_names(out, children, "Name", group.names);
    write_names(out, children, "Comment", group.comments);
    write_images(out, children, group.images);
    children.finish();
    out.end();
}

void write_modules(XmlEmitter& out, const std::vector<Module>& modules) {
    out.begin("Modules");
    for (const auto& module : modules) write_module(out, module);
    out.end();
}

void write_descriptions(XmlEmitter& out, const EtherCATInfo& info) {
    out.begin("Descriptions");
    write_extra_attributes(out, info.descriptions_extras);
    ChildPlacer children(out, info.descriptions_extras, descriptions_order);
    // Groups and Devices are required by the schema even when empty.
    children.at("Groups");
    out.begin("Groups");
    for (const auto& group : info.groups) write_group(out, group);
    out.end();
    children.at("Devices");
    out.begin("Devices");
    for (const auto& device : info.devices) write_device(out, device);
    out.end();
    if (info.has_modules || !info.modules.empty()) {
        children.at("Modules");
        write_modules(out, info.modules);
    }
    children.finish();
    out.end();
}

// EtherCATInfo (also inside EtherCATInfoList) or, with `module_root`, EtherCATModule.
void write_info(XmlEmitter& out, const EtherCATInfo& info, bool module_root) {
    out.begin(module_root ? "EtherCATModule" : "EtherCATInfo");
    put_text(out, "Version", info.version);
    write_extra_attributes(out, info.extras);
    ChildPlacer children(out, info.extras, module_root ? ChildOrder(module_root_order) : ChildOrder(info_order));
    if (info.vendor) {
        children.at("Vendor");
        write_vendor(out, *info.vendor);
    }
    if (module_root) {
        children.at("Modules");  // required by EtherCATModule.xsd
        write_modules(out, info.modules);
    } else if (info.has_descriptions || !info.groups.empty() || !info.devices.empty() || !info.modules.empty() ||
               !info.descriptions_extras.empty()) {
        children.at("Descriptions");
        write_descriptions(out, info);
    }
    children.finish();
    out.end();
}

void write_info_list(XmlEmitter& out, const EsiDocument& document) {
    out.begin("EtherCATInfoList");
    write_extra_attributes(out, document.root_extras);
    ChildPlacer children(out, document.root_extras, info_list_order);
    for (const auto& info : document.infos) {
        children.at("EtherCATInfo");
        write_info(out, info, false);
    }
    children.finish();
    out.end();
}

void write_dict_root(XmlEmitter& out, const EsiDocument& document) {
    out.begin("EtherCATDict");
    put_text(out, "Version", document.dict_version);
    write_extra_attributes(out, document.root_extras);
    ChildPlacer children(out, document.root_extras, dict_root_order);
    if (document.dictionary) {
        children.at("Dictionary");
        write_dictionary(out, *document.dictionary);
    }
    children.finish();
    out.end();
}

DocumentKind effective_kind(const EsiDocument& document) {
    switch (document.kind) {
        case DocumentKind::ethercat_info:
            // Only a list can hold several infos; writing just the first would drop the rest.
            return document.infos.size() > 1 ? DocumentKind::ethercat_info_list : DocumentKind::ethercat_info;
        case DocumentKind::unknown:
            if (document.infos.empty() && document.dictionary) return DocumentKind::ethercat_dict;
            return document.infos.size() > 1 ? DocumentKind::ethercat_info_list : DocumentKind::ethercat_info;
        default: return document.kind;
    }
}

}  // namespace

void text_hex_data(XmlEmitter& out, const HexData& data) {
    bool lower = false;
    for (const char c : data.text) lower = lower || is_lower_hex(c);
    if (!lower) {
        out.text(data.text);
        return;
    }
    std::string upper = data.text;
    for (char& c : upper)
        if (is_lower_hex(c)) c = static_cast<char>(c - 'a' + 'A');
    out.text(upper);
}

void leaf_hex_data(XmlEmitter& out, std::string_view name, const HexData& data) {
    out.begin(name);
    text_hex_data(out, data);
    out.end();
}

void write_localized(XmlEmitter& out, std::string_view element, const LocalizedText& text) {
    out.begin(element);
    if (text.lcid) put_decimal(out, "LcId", *text.lcid);
    out.text(text.text);
    out.end();
}

void write_names(XmlEmitter& out, ChildPlacer& children, std::string_view element, const Names& names) {
    for (const auto& name : names) {
        children.at(element);
        write_localized(out, element, name);
    }
}

void write_images(XmlEmitter& out, ChildPlacer& children, const Images& images) {
    if (images.image16x14) {
        children.at("Image16x14");
        out.leaf("Image16x14", *images.image16x14);
    }
    if (images.image_file16x14) {
        children.at("ImageFile16x14");
        out.leaf("ImageFile16x14", *images.image_file16x14);
    }
    if (images.image_data16x14) {
        children.at("ImageData16x14");
        leaf_hex_data(out, "ImageData16x14", *images.image_data16x14);
    }
}

}  // namespace xml_writer

std::string write_esi(const EsiDocument& document, const WriteOptions& options) {
    using namespace xml_writer;
    std::string text;
    // Rewritten files come out close to their source size; one allocation covers most of them.
    text.reserve(document.source ? document.source->text().size() + document.source->text().size() / 8 + 256 : 64 * 1024);
    XmlEmitter out(text, options.indent, options.line_ending);
    out.declaration();
    static const EtherCATInfo empty_info;
    const EtherCATInfo& first_info = document.infos.empty() ? empty_info : document.infos.front();
    switch (effective_kind(document)) {
        case DocumentKind::ethercat_info_list: write_info_list(out, document); break;
        case DocumentKind::ethercat_module: write_info(out, first_info, true); break;
        case DocumentKind::ethercat_dict: write_dict_root(out, document); break;
        default: write_info(out, first_info, false); break;
    }
    out.finish();
    return text;
}

Diagnostics write_esi_file(const std::filesystem::path& path, const EsiDocument& document, const WriteOptions& options) {
    return write_file_atomically(path, write_esi(document, options));
}

}  // namespace esi
