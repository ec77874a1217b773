#include "image_diff.hpp"

#include <fmt/format.h>

#include <map>
#include <set>

#include "esi/sii/encode.hpp"
#include "esi/sii/text.hpp"

namespace esi::test {

namespace {

using sii::Image;

class Differ {
public:
    Differ(const Image& a, const Image& b) : a_(a), b_(b) {}

    std::vector<ImageDifference> run() {
        header();
        strings();
        general();
        fmmus();
        sync_managers();
        pdos(sii::category::tx_pdo);
        pdos(sii::category::rx_pdo);
        dc();
        other_categories();
        return std::move(out_);
    }

private:
    template <typename T>
    void field(const std::string& name, const T& x, const T& y) {
        if (x != y) out_.push_back({name, fmt::format("{}", x), fmt::format("{}", y)});
    }
    void hex(const std::string& name, unsigned x, unsigned y) {
        if (x != y) out_.push_back({name, fmt::format("0x{:X}", x), fmt::format("0x{:X}", y)});
    }
    static std::string text(const Image& image, std::uint8_t index) {
        if (index == 0) return "(none)";
        const auto s = image.string_at(index);
        return s ? sii::sii_text_to_utf8(*s) : fmt::format("(index {} missing)", index);
    }

    void header() {
        const auto wa = sii::encode_header(a_.header, false);
        const auto wb = sii::encode_header(b_.header, false);
        for (std::size_t w = 0; w < 0x40; ++w) {
            const unsigned x = wa[2 * w] | (wa[2 * w + 1] << 8);
            const unsigned y = wb[2 * w] | (wb[2 * w + 1] << 8);
            hex(fmt::format("header word 0x{:02X}", w), x, y);
        }
    }
    void strings() {
        std::set<std::string> x, y;
        if (a_.strings())
            for (const auto& s : a_.strings()->items) x.insert(sii::sii_text_to_utf8(s));
        if (b_.strings())
            for (const auto& s : b_.strings()->items) y.insert(sii::sii_text_to_utf8(s));
        for (const auto& s : x)
            if (!y.count(s)) out_.push_back({"Strings", s, "-"});
        for (const auto& s : y)
            if (!x.count(s)) out_.push_back({"Strings", "-", s});
    }
    void general() {
        const sii::General* x = a_.general();
        const sii::General* y = b_.general();
        if (!x || !y) {
            if (x || y) out_.push_back({"General", x ? "present" : "-", y ? "present" : "-"});
            return;
        }
        field("General.group", text(a_, x->group_idx), text(b_, y->group_idx));
        field("General.image", text(a_, x->image_idx), text(b_, y->image_idx));
        field("General.order", text(a_, x->order_idx), text(b_, y->order_idx));
        field("General.name", text(a_, x->name_idx), text(b_, y->name_idx));
        hex("General.reserved_4", x->reserved_4, y->reserved_4);
        hex("General.coe_details", x->coe_details, y->coe_details);
        hex("General.foe_details", x->foe_details, y->foe_details);
        hex("General.eoe_details", x->eoe_details, y->eoe_details);
        field("General.soe_channels", +x->soe_channels, +y->soe_channels);
        field("General.ds402_channels", +x->ds402_channels, +y->ds402_channels);
        field("General.sysman_class", +x->sysman_class, +y->sysman_class);
        hex("General.flags", x->flags, y->flags);
        field("General.current_on_ebus", x->current_on_ebus, y->current_on_ebus);
        field("General.byte14", text(a_, x->group_idx_duplicate), text(b_, y->group_idx_duplicate));
        hex("General.physical_ports", x->physical_ports, y->physical_ports);
        hex("General.physical_memory_address", x->physical_memory_address, y->physical_memory_address);
    }
    void fmmus() {
        auto trimmed = [](const sii::Fmmus* f) {
            std::vector<unsigned> out;
            if (f)
                for (const auto u : f->usages) out.push_back(u);
            while (!out.empty() && (out.back() == 0 || out.back() == 0xFF)) out.pop_back();
            return out;
        };
        const auto x = trimmed(a_.fmmus());
        const auto y = trimmed(b_.fmmus());
        if (x != y) out_.push_back({"FMMU", fmt::format("{}", fmt::join(x, " ")), fmt::format("{}", fmt::join(y, " "))});
    }
    void sync_managers() {
        const sii::SyncManagers* x = a_.sync_managers();
        const sii::SyncManagers* y = b_.sync_managers();
        const std::size_t nx = x ? x->items.size() : 0, ny = y ? y->items.size() : 0;
        field("SyncM.count", nx, ny);
        for (std::size_t i = 0; i < nx && i < ny; ++i) {
            const auto& p = x->items[i];
            const auto& q = y->items[i];
            const std::string sm = fmt::format("SyncM {}", i);
            hex(sm + ".start", p.start_address, q.start_address);
            field(sm + ".length", p.length, q.length);
            hex(sm + ".control", p.control, q.control);
            hex(sm + ".status", p.status, q.status);
            hex(sm + ".enable", p.enable, q.enable);
            field(sm + ".type", +p.type, +q.type);
        }
    }
    void pdos(std::uint16_t type) {
        const sii::Pdos* x = a_.pdos(type);
        const sii::Pdos* y = b_.pdos(type);
        const std::string cat(sii::category_name(type));
        if (!x || !y) {
            if (x || y) out_.push_back({cat, x ? fmt::format("{} PDOs", x->items.size()) : "-", y ? fmt::format("{} PDOs", y->items.size()) : "-"});
            return;
        }
        field(cat + ".count", x->items.size(), y->items.size());
        for (std::size_t i = 0; i < x->items.size() && i < y->items.size(); ++i) {
            const auto& p = x->items[i];
            const auto& q = y->items[i];
            const std::string pdo = fmt::format("{} 0x{:04X}", cat, p.index);
            hex(pdo + ".index", p.index, q.index);
            field(pdo + ".sm", +p.sync_manager, +q.sync_manager);
            field(pdo + ".dc_sync", +p.dc_sync, +q.dc_sync);
            field(pdo + ".name", text(a_, p.name_idx), text(b_, q.name_idx));
            hex(pdo + ".flags", p.flags, q.flags);
            field(pdo + ".entries", p.entries.size(), q.entries.size());
            for (std::size_t k = 0; k < p.entries.size() && k < q.entries.size(); ++k) {
                const auto& e = p.entries[k];
                const auto& f = q.entries[k];
                const std::string entry = fmt::format("{} entry {}", pdo, k);
                hex(entry + ".index", e.index, f.index);
                hex(entry + ".subindex", e.subindex, f.subindex);
                field(entry + ".name", text(a_, e.name_idx), text(b_, f.name_idx));
                hex(entry + ".data_type", e.data_type, f.data_type);
                field(entry + ".bit_len", +e.bit_len, +f.bit_len);
                hex(entry + ".flags", e.flags, f.flags);
            }
        }
    }
    void dc() {
        const sii::DcOpModes* x = a_.dc();
        const sii::DcOpModes* y = b_.dc();
        if (!x || !y) {
            if (x || y) out_.push_back({"DC", x ? fmt::format("{} op modes", x->items.size()) : "-", y ? fmt::format("{} op modes", y->items.size()) : "-"});
            return;
        }
        field("DC.count", x->items.size(), y->items.size());
        for (std::size_t i = 0; i < x->items.size() && i < y->items.size(); ++i) {
            const auto& p = x->items[i];
            const auto& q = y->items[i];
            const std::string op = fmt::format("DC {}", i);
            field(op + ".name", text(a_, p.name_idx), text(b_, q.name_idx));
            field(op + ".desc", text(a_, p.desc_idx), text(b_, q.desc_idx));
            hex(op + ".assign_activate", p.assign_activate, q.assign_activate);
            field(op + ".cycle_time0", p.cycle_time0, q.cycle_time0);
            field(op + ".shift_time0", p.shift_time0, q.shift_time0);
            field(op + ".shift_time1", p.shift_time1, q.shift_time1);
            field(op + ".sync0_factor", p.sync0_cycle_factor, q.sync0_cycle_factor);
            field(op + ".sync1_factor", p.sync1_cycle_factor, q.sync1_cycle_factor);
        }
    }
    void other_categories() {
        static const std::set<std::uint16_t> typed = {sii::category::strings, sii::category::general, sii::category::fmmu,
                                                      sii::category::sync_manager, sii::category::tx_pdo, sii::category::rx_pdo,
                                                      sii::category::dc};
        std::map<std::uint16_t, std::vector<std::uint8_t>> x, y;
        for (const auto& c : a_.categories)
            if (!typed.count(c.type)) x.emplace(c.type, sii::encode_content(c.content));
        for (const auto& c : b_.categories)
            if (!typed.count(c.type)) y.emplace(c.type, sii::encode_content(c.content));
        for (const auto& [type, bytes] : x) {
            const auto it = y.find(type);
            if (it == y.end()) out_.push_back({fmt::format("category {}", type), "present", "-"});
            else if (it->second != bytes) out_.push_back({fmt::format("category {}", type), "differs", "differs"});
        }
        for (const auto& [type, bytes] : y)
            if (!x.count(type)) out_.push_back({fmt::format("category {}", type), "-", "present"});
    }

    const Image& a_;
    const Image& b_;
    std::vector<ImageDifference> out_;
};

}  // namespace

std::vector<ImageDifference> diff_images(const sii::Image& built, const sii::Image& real) { return Differ(built, real).run(); }

}  // namespace esi::test
