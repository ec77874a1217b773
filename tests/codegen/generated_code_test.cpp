// The generated code compiles with strict flags, and what it holds is checked by the compiler
// (static_asserts) and at run time. Each check also has a wrong twin that must fail, so a check
// that silently stopped checking would be noticed.

#include <gtest/gtest.h>

#include "codegen_test_support.hpp"

namespace {

namespace tc = esi::test::codegen;
using esi::test::read_text;
using esi::test::TempDir;
using esi::test::write_text;

// Generates the rich fixture once for the whole suite.
class GeneratedCode : public ::testing::Test {
protected:
    static void SetUpTestSuite() {
        dir_ = new TempDir;
        const auto r = tc::esi_gen(tc::rich_esi(), out(), {"--only", "cpp,c,soes,structs"});
        ASSERT_EQ(r.exit_code, 0) << r.err;
    }
    static void TearDownTestSuite() { delete dir_; }
    static std::filesystem::path out() { return dir_->path() / "out"; }
    static std::filesystem::path work() { return dir_->path(); }
    static TempDir* dir_;
};
TempDir* GeneratedCode::dir_ = nullptr;

const char* cpp_checks = R"(#include <cstdint>
#include <limits>
#include "object_dictionary.hpp"
namespace od = rich_1::od;
static_assert(od::object_count == 14);
static_assert(od::index::device_type == 0x1000);
static_assert(od::index::default_ == 0x2001);
static_assert(od::index::gains_2005 == 0x2005);
static_assert(od::find_object(od::index::gains)->code == od::ObjectCode::record);
static_assert(od::find_object(0x2000)->max_subindex == 2);
static_assert(od::find_object(0x3000)->code == od::ObjectCode::array);
static_assert(od::find_entry(0x1000, 0)->default_value.u == 0x1389);
static_assert(od::find_entry(0x2000, 0)->default_value.u == 2);
static_assert(od::find_entry(0x2000, 1)->default_value.r == 1.5);
static_assert(od::find_entry(0x2000, 1)->data_type == 0x0008);
static_assert(od::find_entry(0x2000, 2)->default_value.i == -1);
static_assert(od::find_entry(0x2000, 2)->min.i == -100 && od::find_entry(0x2000, 2)->max.i == 100);
static_assert(od::find_entry(0x2001, 0)->min.i == std::numeric_limits<std::int64_t>::min());
static_assert(od::find_entry(0x2001, 0)->access_word == (od::access_bits::read_preop | od::access_bits::read_safeop |
                                                         od::access_bits::read_op | od::access_bits::write_preop));
static_assert(od::find_entry(0x2002, 0)->default_value.u == std::numeric_limits<std::uint64_t>::max());
static_assert(od::find_entry(0x2002, 0)->bit_length == 64);
static_assert(od::find_entry(0x1008, 0)->default_value.s == "RICH-1");
static_assert(od::find_entry(0x2003, 0)->default_value.kind == od::ValueKind::bytes);
static_assert(od::find_entry(0x2003, 0)->default_value.s.size() == 3 && od::find_entry(0x2003, 0)->default_value.s[0] == '\0');
static_assert(od::find_entry(0x2005, 0)->default_value.i == -128);
static_assert(od::find_entry(0x6000, 3)->bit_length == 3 && od::find_entry(0x6000, 3)->type_name == "BIT3");
static_assert(od::find_entry(0x6000, 3)->tx_mappable && !od::find_entry(0x6000, 3)->rx_mappable);
static_assert(od::find_entry(0x7010, 0)->access == od::Access::rw);
static_assert(od::find_entry(0x1234, 0) == nullptr && od::find_entry(0x2000, 3) == nullptr);
int main() { return od::find_entry(0x3000, 3)->default_value.u == 30 ? 0 : 1; }
)";

TEST_F(GeneratedCode, CppHeaderCompilesAsCpp17AndHoldsTheValues) {
    ESI_REQUIRE_COMPILERS();
    write_text(work() / "od_check.cpp", cpp_checks);
    const auto exe = work() / "od_check";
    const auto c = tc::compile("c++", "c++17", {"-I" + out().string(), (work() / "od_check.cpp").string()}, exe);
    ASSERT_EQ(c.exit_code, 0) << c.err;
    EXPECT_EQ(esi::test::run({exe.string()}).exit_code, 0);
}

TEST_F(GeneratedCode, CppStaticAssertsCatchAWrongValue) {
    ESI_REQUIRE_COMPILERS();
    write_text(work() / "od_wrong.cpp", "#include \"object_dictionary.hpp\"\n"
                                        "static_assert(rich_1::od::find_entry(0x1000, 0)->default_value.u == 0x1388);\n");
    const auto c = tc::compile("c++", "c++17", {"-I" + out().string(), (work() / "od_wrong.cpp").string()});
    EXPECT_NE(c.exit_code, 0);
}

TEST_F(GeneratedCode, SampleCppHeaderCompiles) {
    ESI_REQUIRE_COMPILERS();
    TempDir dir;
    ASSERT_EQ(tc::esi_gen(tc::sample_esi(), dir.path(), {"--only", "cpp"}).exit_code, 0);
    write_text(dir / "check.cpp", "#include \"object_dictionary.hpp\"\n"
                                  "static_assert(ex_dio_8::od::index::digital_outputs == 0x7000);\n"
                                  "static_assert(ex_dio_8::od::find_entry(0x1018, 1)->default_value.u == 0xE4A);\n");
    const auto c = tc::compile("c++", "c++17", {"-I" + dir.path().string(), (dir / "check.cpp").string()});
    EXPECT_EQ(c.exit_code, 0) << c.err;
}

const char* c_checks = R"(#include <string.h>
#include "slave_tables.h"
int main(void)
{
   const rich_1_od_entry_t *e = rich_1_od_find_entry(0x2000, 2);
   size_t k;
   if (e == NULL || e->default_value.kind != RICH_1_VALUE_SIGNED_INTEGER || e->default_value.bits != 0xFFFFu) return 1;
   if (e->min.bits != 0xFF9Cu || e->max.bits != 100u) return 2;
   e = rich_1_od_find_entry(0x1008, 0);
   if (e == NULL || e->default_value.size != 6 || memcmp(e->default_value.data, "RICH-1", 6) != 0) return 3;
   if (rich_1_od_find_object(0x1234) != NULL || rich_1_od_find_entry(0x2000, 3) != NULL) return 4;
   if (rich_1_od_object_count != 14) return 5;
   for (k = 1; k < rich_1_od_object_count; ++k)
      if (rich_1_od_objects[k - 1].index >= rich_1_od_objects[k].index) return 6;
   if (rich_1_tx_pdo_count != 3 || rich_1_tx_pdos[2].sm != RICH_1_NO_SM || rich_1_tx_pdos[0].sm != 3) return 7;
   if (rich_1_rx_pdos[0].entries[0].mapping != 0x70000001u || rich_1_rx_pdos[0].entries[1].index != 0) return 8;
   if (rich_1_pdo_assignment_count != 2 || rich_1_pdo_assignments[1].object_index != 0x1C13) return 9;
   if (rich_1_pdo_assignments[1].pdo_count != 2 || rich_1_pdo_assignments[1].pdos[1] != 0x1A01) return 10;
   if (rich_1_sync_manager_count != 4 || rich_1_sync_managers[2].role != RICH_1_SM_OUTPUTS) return 11;
   if (rich_1_sync_managers[2].control_byte != 0x64 || rich_1_sync_managers[3].start_address != 0x1400) return 12;
   if (rich_1_esc_config.product_code != 0x4711 || rich_1_esc_config.mailbox_protocols != 0x0C) return 13;
   if (rich_1_esc_config.bootstrap_out_size != 256 || rich_1_esc_config.config_data_size != 10) return 14;
   if (rich_1_esc_config.config_data[1] != 0x0E || rich_1_dc_op_mode_count != 1 || rich_1_dc_op_modes[0].assign_activate != 0x300) return 15;
   return 0;
}
)";

TEST_F(GeneratedCode, CTablesCompileAsC99AndHoldTheValues) {
    ESI_REQUIRE_COMPILERS();
    write_text(work() / "tables_check.c", c_checks);
    const auto exe = work() / "tables_check";
    const auto c = tc::compile("cc", "c99", {"-I" + out().string(), (out() / "slave_tables.c").string(), (work() / "tables_check.c").string()}, exe);
    ASSERT_EQ(c.exit_code, 0) << c.err;
    const auto r = esi::test::run({exe.string()});
    EXPECT_EQ(r.exit_code, 0) << "failed check number " << r.exit_code;
}

TEST_F(GeneratedCode, CTablesHeaderIsUsableFromCpp) {
    ESI_REQUIRE_COMPILERS();
    write_text(work() / "tables_cpp.cpp", "#include \"slave_tables.h\"\nint main() { return rich_1_od_find_entry(0x1000, 0) ? 0 : 1; }\n");
    const auto c = tc::compile("c++", "c++17", {"-I" + out().string(), (work() / "tables_cpp.cpp").string()});
    EXPECT_EQ(c.exit_code, 0) << c.err;
}

const char* soes_checks = R"(#include <stddef.h>
#include "esc_coe.h"
#include "utypes.h"
#include "ecat_options.h"
_Objects Obj;
extern const _objd SDO2000[];
int main(void)
{
   int n;
   const _objd *setpoint = NULL;
   for (n = 0; SDOobjects[n].index != 0xffff; ++n)
   {
      if (n > 0 && SDOobjects[n - 1].index >= SDOobjects[n].index) return 1;
      if (SDOobjects[n].index == 0x7010) setpoint = SDOobjects[n].objdesc;
   }
   if (n != 14) return 2;
   if (setpoint == NULL || setpoint[0].data != &Obj.setpoint || setpoint[0].flags != (ATYPE_RW | ATYPE_RXPDO)) return 3;
   if (SDO2000[0].value != 2 || SDO2000[1].datatype != DTYPE_REAL32 || SDO2000[1].value != 0x3FC00000u) return 4;
   if (SDO2000[1].data != &Obj.gains.gain) return 5;
   if (MBX0_sma != 0x1000 || MBX1_sml != 128 || MBX0_sml_b != 256 || SM2_smc != 0x64 || SM3_sma != 0x1400) return 6;
   if (USE_FOE != 1 || USE_EOE != 0 || MAX_MAPPINGS_SM2 != 3 || MAX_MAPPINGS_SM3 != 8) return 7;
   return 0;
}
)";

TEST_F(GeneratedCode, SoesSetCompilesAgainstTheStandInAndIsSorted) {
    ESI_REQUIRE_COMPILERS();
    write_text(work() / "soes_check.c", soes_checks);
    const auto exe = work() / "soes_check";
    const auto c = tc::compile("cc", "c99",
                               {"-I" + out().string(), "-I" + tc::soes_stand_in_dir().string(), (out() / "objectlist.c").string(),
                                (work() / "soes_check.c").string()},
                               exe);
    ASSERT_EQ(c.exit_code, 0) << c.err;
    const auto r = esi::test::run({exe.string()});
    EXPECT_EQ(r.exit_code, 0) << "failed check number " << r.exit_code;
}

const char* image_checks = R"(#include <string.h>
#include "process_image.h"
int main(void)
{
   rich_1_txpdo_t tx;
   rich_1_rxpdo_t rx;
   unsigned char b[sizeof tx];
   memset(&tx, 0, sizeof tx);
   tx.input_1 = 1;
   tx.mode = 5;
   tx.counter = 0xABCD; /* bits 5..20 */
   tx.position = 0x11223344;
   tx.counter_1a01 = 0xBEEF;
   memcpy(b, &tx, sizeof tx);
   /* byte 0: input_1 (bit 0), mode (bits 2..4), counter bits 0..2 in bits 5..7 */
   if (b[0] != (1u | (5u << 2) | ((0xABCDu & 7u) << 5))) return 1;
   if (b[1] != ((0xABCDu >> 3) & 0xFFu) || b[2] != ((0xABCDu >> 11) & 0x1Fu)) return 2;
   if (b[4] != 0x44 || b[5] != 0x33 || b[6] != 0x22 || b[7] != 0x11) return 3;
   if (b[8] != 0xEF || b[9] != 0xBE) return 4;
   memset(&rx, 0, sizeof rx);
   rx.output = 1;
   rx.setpoint = -2;
   memcpy(b, &rx, sizeof rx);
   if (b[0] != 1 || b[1] != 0xFE || b[2] != 0xFF) return 5;
   return 0;
}
)";

TEST_F(GeneratedCode, ProcessImageBitsLandWhereThePdoPutsThem) {
    ESI_REQUIRE_COMPILERS();
    write_text(work() / "image_check.c", image_checks);
    const auto exe = work() / "image_check";
    const auto c = tc::compile("cc", "c99", {"-I" + out().string(), (work() / "image_check.c").string()}, exe);
    ASSERT_EQ(c.exit_code, 0) << c.err;
    const auto r = esi::test::run({exe.string()});
    EXPECT_EQ(r.exit_code, 0) << "failed check number " << r.exit_code;
}

TEST_F(GeneratedCode, ProcessImageCompilesAsCpp17) {
    ESI_REQUIRE_COMPILERS();
    write_text(work() / "image_cpp.cpp", "#include \"process_image.h\"\nint main() { rich_1_txpdo_t t{}; return t.position; }\n");
    const auto c = tc::compile("c++", "c++17", {"-I" + out().string(), (work() / "image_cpp.cpp").string()});
    EXPECT_EQ(c.exit_code, 0) << c.err;
}

TEST_F(GeneratedCode, ProcessImageStaticAssertsCatchAWrongLayout) {
    ESI_REQUIRE_COMPILERS();
    // The same header with one asserted offset off by one must not compile, in C99 and C++.
    std::string header = read_text(out() / "process_image.h");
    const std::string good = "offsetof(rich_1_txpdo_t, position) == 4";
    const auto at = header.find(good);
    ASSERT_NE(at, std::string::npos);
    header.replace(at, good.size(), "offsetof(rich_1_txpdo_t, position) == 5");
    TempDir dir;
    write_text(dir / "process_image.h", header);
    write_text(dir / "use.c", "#include \"process_image.h\"\n");
    EXPECT_NE(tc::compile("cc", "c99", {"-I" + dir.path().string(), (dir / "use.c").string()}).exit_code, 0);
    EXPECT_NE(tc::compile("c++", "c++17", {"-x", "c++", "-I" + dir.path().string(), (dir / "use.c").string()}).exit_code, 0);
}

// A device with no dictionary, no PDOs and no mailbox still yields code that compiles.
TEST(GeneratedCodeEdge, BareDeviceCompiles) {
    ESI_REQUIRE_COMPILERS();
    TempDir dir;
    write_text(dir / "bare.xml", R"(<EtherCATInfo><Vendor><Id>2</Id><Name>V</Name></Vendor><Descriptions><Devices><Device>
<Type ProductCode="7" RevisionNo="1">Bare</Type><Name>Bare coupler</Name></Device></Devices></Descriptions></EtherCATInfo>)");
    const auto out = dir.path() / "out";
    const auto r = tc::esi_gen(dir / "bare.xml", out, {"--only", "cpp,c,soes,structs"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    write_text(dir / "use.cpp", "#include \"object_dictionary.hpp\"\n#include \"process_image.h\"\nstatic_assert(bare::od::object_count == 0);\n"
                                "static_assert(bare::od::find_object(0x1000) == nullptr);\n");
    EXPECT_EQ(tc::compile("c++", "c++17", {"-I" + out.string(), (dir / "use.cpp").string()}).exit_code, 0);
    EXPECT_EQ(tc::compile("cc", "c99", {"-I" + out.string(), (out / "slave_tables.c").string()}).exit_code, 0);
    EXPECT_EQ(tc::compile("cc", "c99", {"-I" + out.string(), "-I" + tc::soes_stand_in_dir().string(), (out / "objectlist.c").string()}).exit_code, 0);
}

}  // namespace
