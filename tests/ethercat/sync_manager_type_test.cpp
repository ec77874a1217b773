// SyncManager types: the ESI texts and the SII/0x1C00 codes of one numbering.

#include <gtest/gtest.h>

#include "esi/ethercat/sync_manager_type.hpp"

namespace esi::ethercat {
namespace {

TEST(SyncManagerTypes, EsiTextsAndCodesAreOneNumbering) {
    const std::pair<const char*, std::uint8_t> known[] = {{"MBoxOut", 1}, {"MBoxIn", 2}, {"Outputs", 3}, {"Inputs", 4}};
    for (const auto& [text, code] : known) {
        const std::optional<SyncManagerType> t = parse_sync_manager_type(text);
        ASSERT_TRUE(t) << text;
        EXPECT_EQ(static_cast<std::uint8_t>(*t), code) << text;
        EXPECT_EQ(sync_manager_type_from_code(code), t);
        EXPECT_EQ(sync_manager_type_name(*t), text);
    }
    EXPECT_EQ(sync_manager_type_from_code(0), SyncManagerType::unused);
    EXPECT_FALSE(sync_manager_type_from_code(5));
    EXPECT_FALSE(parse_sync_manager_type("outputs"));
    EXPECT_FALSE(parse_sync_manager_type(""));
}

}  // namespace
}  // namespace esi::ethercat
