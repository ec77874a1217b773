#include "igh_names.hpp"

#include <fmt/format.h>
#include <cctype>
#include <set>

namespace esi::net {

namespace {

// Lower case ASCII letters and digits, runs of anything else as one '_', none at the ends.
std::string c_word(std::string_view text) {
    std::string out;
    bool underscore = false;
    for (char c : text) {
        const unsigned char u = static_cast<unsigned char>(c);
        if (std::isalnum(u) && u < 0x80) {
            out += static_cast<char>(std::tolower(u));
            underscore = false;
        } else if (!underscore && !out.empty()) {
            out += '_';
            underscore = true;
        }
    }
    while (!out.empty() && out.back() == '_') out.pop_back();
    return out;
}

}  // namespace

std::string c_identifier(std::string_view text) {
    std::string out = c_word(text);
    if (out.empty()) return "s";
    if (std::isdigit(static_cast<unsigned char>(out.front()))) out = "s_" + out;
    return out;
}

namespace {

// One registered entry of a slave, in SM order.
struct Registered {
    std::size_t number;  // entry number in SM order, padding included
    const ConfiguredEntry* entry;
    const ConfiguredPdo* pdo;
    bool bit_aligned;
};

std::vector<Registered> registered_entries(const NetworkSlave& s) {
    std::vector<Registered> out;
    std::set<std::pair<std::uint32_t, std::uint32_t>> seen;
    std::size_t number = 0;
    for (const SmSetup& sm : s.sms)
        for (std::size_t p : sm.pdos) {
            std::uint32_t bit = 0;
            for (const ConfiguredEntry& e : s.pdos[p].entries) {
                const std::size_t k = number++;
                const bool aligned = bit % 8 == 0 && e.bit_len % 8 == 0;
                bit += e.bit_len;
                if (e.is_padding() || !seen.insert({e.index, e.subindex}).second) continue;
                out.push_back({k, &e, &s.pdos[p], aligned});
            }
        }
    return out;
}

// An empty name, or one without a letter or digit, is replaced by the entry's or PDO's numbers.
bool nameless(std::string_view name) {
    for (char c : name)
        if (std::isalnum(static_cast<unsigned char>(c)) && static_cast<unsigned char>(c) < 0x80) return false;
    return true;
}

std::string entry_word(const ConfiguredEntry& e) {
    return nameless(e.name) ? fmt::format("{:04x}_{:02x}", e.index, e.subindex) : c_word(e.name);
}

std::string pdo_word(const ConfiguredPdo& p) { return nameless(p.name) ? fmt::format("{:04x}", p.index) : c_word(p.name); }

}  // namespace

IghNames igh_names(const Network& n) {
    IghNames names;
    names.network = c_identifier(n.name);
    // Every name the files declare, so that no variable takes one of them.
    std::set<std::string> taken = {names.network + "_domain_regs", names.network + "_configure", names.network + "_dc_sync"};
    std::set<std::string> slave_bases;
    for (const NetworkSlave& s : n.slaves) {
        std::string base = c_identifier(s.name);
        if (!slave_bases.insert(base).second) base += "_" + std::to_string(s.position);
        slave_bases.insert(base);
        names.slave.push_back(base);
        for (const char* array : {"_pdo_entries", "_pdos", "_syncs"}) taken.insert(base + array);
    }
    for (const NetworkSlave& s : n.slaves) {
        const std::string& base = names.slave[s.position];
        const std::vector<Registered> entries = registered_entries(s);
        std::map<std::string, int> uses;
        for (const Registered& r : entries) ++uses[entry_word(*r.entry)];
        for (const Registered& r : entries) {
            const std::string word = entry_word(*r.entry);
            std::string var = uses[word] > 1 ? base + "_" + pdo_word(*r.pdo) + "_" + word : base + "_" + word;
            // A "_bit" companion must be free too: "x_bit" of one entry is not another's "x".
            auto free = [&](const std::string& v) { return !taken.count(v) && (r.bit_aligned || !taken.count(v + "_bit")); };
            if (!free(var)) var += fmt::format("_{:04x}_{:02x}", r.entry->index, r.entry->subindex);
            const std::string stem = var;
            for (int k = 2; !free(var); ++k) var = stem + "_" + std::to_string(k);
            taken.insert(var);
            if (!r.bit_aligned) taken.insert(var + "_bit");
            names.entry[{s.position, r.number}] = var;
            names.bit_entry[{s.position, r.number}] = !r.bit_aligned;
        }
    }
    return names;
}

}  // namespace esi::net
