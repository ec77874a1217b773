#include "esi/sii/image.hpp"

namespace esi::sii {

namespace {

template <typename T>
const T* first_content(const Image& image, std::uint16_t type) {
    const Category* c = image.find(type);
    return c ? std::get_if<T>(&c->content) : nullptr;
}

}  // namespace

const Category* Image::find(std::uint16_t type) const {
    for (const auto& c : categories)
        if (c.type == type) return &c;
    return nullptr;
}

const Strings* Image::strings() const { return first_content<Strings>(*this, category::strings); }
const General* Image::general() const { return first_content<General>(*this, category::general); }
const Fmmus* Image::fmmus() const { return first_content<Fmmus>(*this, category::fmmu); }
const SyncManagers* Image::sync_managers() const { return first_content<SyncManagers>(*this, category::sync_manager); }
const Pdos* Image::pdos(std::uint16_t type) const { return first_content<Pdos>(*this, type); }
const DcOpModes* Image::dc() const { return first_content<DcOpModes>(*this, category::dc); }

std::optional<std::string> Image::string_at(std::uint8_t index) const {
    const Strings* s = strings();
    if (!s || index == 0 || index > s->items.size()) return std::nullopt;
    return s->items[index - 1u];
}

}  // namespace esi::sii
