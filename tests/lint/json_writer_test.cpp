// esi-lint's JSON report is written straight into a string (report/json_writer.hpp), in the bytes
// nlohmann::json's dump(2) with error_handler_t::replace writes, which the report was written with
// before and which users' scripts read: the same layout, the same escapes and the same U+FFFD
// where a path or message is not valid UTF-8. nlohmann is the oracle here.

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <random>
#include <string>
#include <vector>

#include "report/json_writer.hpp"

namespace {

using ordered_json = nlohmann::ordered_json;

std::string dumped(const ordered_json& j) { return j.dump(2, ' ', false, nlohmann::detail::error_handler_t::replace); }

std::string written(std::string_view s) {
    esi::report::JsonWriter json;
    json.value(s);
    return json.take();
}

TEST(JsonWriter, StringsAreEscapedAsNlohmannEscapesThem) {
    const std::vector<std::string> strings = {
        "", "plain", "quote \" and backslash \\", "tab\tnew line\ncarriage return\rform feed\fbackspace\b",
        std::string("nul \0 and \x01\x1f\x7f", 13), "\xC3\xA9t\xC3\xA9 \xE2\x82\xAC \xF0\x9F\x98\x80",
        // Invalid UTF-8: a lone continuation byte, an overlong form, a surrogate, beyond U+10FFFF,
        // a sequence broken by ASCII, one cut off at the end, 0xFF.
        "\x80", "a\xC0\xAF" "b", "\xED\xA0\x80", "\xF4\x90\x80\x80", "\xE1\x80" "A", "x\xE2\x82", "\xFF\xFE", "\xE0\x80\x80",
        "\xF0\x9F\x98", "\xC3\xC3\xA9",
    };
    for (const auto& s : strings) EXPECT_EQ(written(s), dumped(ordered_json(s))) << s;
}

// Random bytes, mostly from the characters that matter (ASCII, control characters, lead and
// continuation bytes of every length).
TEST(JsonWriter, RandomBytesAreWrittenAsNlohmannWritesThem) {
    std::mt19937 random(25);
    const std::string alphabet = std::string("aZ\"\\\t\n\x01\x7f", 8) + "\x80\xBF\xC2\xDF\xE0\xED\xEF\xF0\xF4\xF5\xC0\xA0\x90\x8F\x9F";
    for (int i = 0; i < 20000; ++i) {
        std::string s(random() % 12, ' ');
        for (char& c : s) c = alphabet[random() % alphabet.size()];
        ASSERT_EQ(written(s), dumped(ordered_json(s))) << i;
    }
}

// Long plain runs (read 16 bytes a step) with an escape, a control character or a non-ASCII
// byte at every offset, as diagnostic messages and paths have them.
TEST(JsonWriter, LongStringsWithAnEscapeAtAnyOffsetAreWrittenAsNlohmannWritesThem) {
    const std::vector<std::string> specials = {"\"", "\\", "\n", std::string("\0", 1), "\x1f", "\x7f", "\xC3\xA9", "\xE2\x82\xAC", "\xFF", "\xE2\x82"};
    for (std::size_t length = 0; length <= 70; ++length)
        for (std::size_t at = 0; at <= length; ++at)
            for (const auto& special : specials) {
                std::string s(length, 'x');
                for (std::size_t i = 0; i < length; ++i) s[i] = static_cast<char>('a' + i % 26);
                s.insert(at, special);
                ASSERT_EQ(written(s), dumped(ordered_json(s))) << length << " " << at;
            }
}

TEST(JsonWriter, ObjectsAndArraysAreLaidOutAsDump2LaysThemOut) {
    esi::report::JsonWriter json;
    json.begin_object();
    json.key("empty array");
    json.begin_array();
    json.end_array();
    json.key("empty object");
    json.begin_object();
    json.end_object();
    json.key("items");
    json.begin_array();
    json.begin_object();
    json.member("n", std::uint64_t{18446744073709551615u});
    json.member("s", "x");
    json.key("nothing");
    json.null();
    json.end_object();
    json.value("last");
    json.begin_array();
    json.value(std::uint64_t{0});
    json.end_array();
    json.end_array();
    json.end_object();
    const ordered_json expected{{"empty array", ordered_json::array()},
                                {"empty object", ordered_json::object()},
                                {"items", {{{"n", std::uint64_t{18446744073709551615u}}, {"s", "x"}, {"nothing", nullptr}}, "last", {0}}}};
    EXPECT_EQ(json.text(), dumped(expected));
}

}  // namespace
