#include "doc/process_data.hpp"

#include <map>

#include "doc/markup.hpp"
#include "esi/model/language.hpp"

namespace esi::doc {

std::string entry_address(const PdoEntry& entry) {
    return entry.is_padding() ? std::string() : index_text(entry.index, entry.effective_subindex());
}

namespace {

void append_fields(const Pdo& pdo, std::uint32_t lcid, std::uint32_t group, std::uint64_t offset, std::vector<LayoutField>& out) {
    for (const PdoEntry& e : pdo.entries) {
        LayoutField f;
        f.name = localized_text(e.names, lcid);
        f.bit_offset = offset;
        f.bit_size = e.bit_len;
        f.type = e.data_type.value_or("");
        f.address = entry_address(e);
        f.padding = e.is_padding();
        f.group = group;
        out.push_back(std::move(f));
        offset += e.bit_len;
    }
}

}  // namespace

std::vector<LayoutField> pdo_fields(const Pdo& pdo, std::uint32_t lcid, std::uint32_t group) {
    std::vector<LayoutField> out;
    out.reserve(pdo.entries.size());
    append_fields(pdo, lcid, group, 0, out);
    return out;
}

std::vector<SmImage> sm_images(const Device& device, std::uint32_t lcid) {
    std::map<std::uint32_t, SmImage> by_sm;
    for (const auto* list : {&device.rx_pdos, &device.tx_pdos})
        for (const Pdo& pdo : *list)
            if (pdo.sm) by_sm[*pdo.sm].pdos.push_back(&pdo);
    std::vector<SmImage> out;
    out.reserve(by_sm.size());
    for (auto& [sm, image] : by_sm) {
        image.sm = sm;
        for (std::size_t i = 0; i < image.pdos.size(); ++i) {
            append_fields(*image.pdos[i], lcid, static_cast<std::uint32_t>(i), image.bit_size, image.fields);
            image.bit_size += image.pdos[i]->bit_size();
        }
        out.push_back(std::move(image));
    }
    return out;
}

}  // namespace esi::doc
