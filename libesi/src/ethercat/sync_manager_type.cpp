// SyncManager types (sync_manager_type.hpp).

#include "esi/ethercat/sync_manager_type.hpp"

#include <array>

namespace esi::ethercat {

namespace {

constexpr std::array<std::string_view, 5> names = {"", "MBoxOut", "MBoxIn", "Outputs", "Inputs"};

}  // namespace

std::string_view sync_manager_type_name(SyncManagerType type) { return names[static_cast<std::size_t>(type)]; }

std::optional<SyncManagerType> parse_sync_manager_type(std::string_view esi_text) {
    for (std::size_t i = 1; i < names.size(); ++i)
        if (names[i] == esi_text) return static_cast<SyncManagerType>(i);
    return std::nullopt;
}

std::optional<SyncManagerType> sync_manager_type_from_code(std::uint8_t code) {
    if (code >= names.size()) return std::nullopt;
    return static_cast<SyncManagerType>(code);
}

}  // namespace esi::ethercat
