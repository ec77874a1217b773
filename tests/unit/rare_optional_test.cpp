// RareOptional (esi/model/rare_optional.hpp): the model's out-of-line optional behaves like
// std::optional for the code that reads and writes model fields: absent by default, set by
// assignment or emplace, cleared by nullopt, copied by value (a copy never shares with its
// source), compared by value, and handed to code written against std::optional as a copy.

#include <gtest/gtest.h>

#include <optional>
#include <string>
#include <utility>

#include "esi/model.hpp"
#include "esi/model/rare_optional.hpp"

namespace {

using esi::RareOptional;

TEST(RareOptional, CostsOnePointerWhateverItHolds) {
    EXPECT_EQ(sizeof(RareOptional<std::string>), sizeof(void*));
    EXPECT_EQ(sizeof(RareOptional<esi::HexData>), sizeof(void*));
    EXPECT_LT(sizeof(RareOptional<esi::Number>), sizeof(std::optional<esi::Number>));
}

TEST(RareOptional, IsAbsentUntilSet) {
    RareOptional<std::string> field;
    EXPECT_FALSE(field.has_value());
    EXPECT_FALSE(field);
    EXPECT_TRUE(field == std::nullopt);
    EXPECT_EQ(field.value_or("none"), "none");
    EXPECT_THROW((void)field.value(), std::bad_optional_access);
}

TEST(RareOptional, AssignmentSetsReplacesAndClears) {
    RareOptional<std::string> field;
    field = "ro";
    ASSERT_TRUE(field);
    EXPECT_EQ(*field, "ro");
    EXPECT_EQ(field->size(), 2u);
    field = std::string("rw");
    EXPECT_EQ(field.value(), "rw");
    field = std::nullopt;
    EXPECT_FALSE(field);
    field.emplace(3, 'x');
    EXPECT_EQ(*field, "xxx");
    field.reset();
    EXPECT_FALSE(field.has_value());
}

TEST(RareOptional, CopiesAreIndependent) {
    RareOptional<std::string> original = std::string("PREOP");
    RareOptional<std::string> copy = original;
    *copy += ",SAFEOP";
    EXPECT_EQ(*original, "PREOP");
    EXPECT_EQ(*copy, "PREOP,SAFEOP");

    RareOptional<std::string> assigned;
    assigned = original;
    original = std::nullopt;
    ASSERT_TRUE(assigned);
    EXPECT_EQ(*assigned, "PREOP");

    RareOptional<std::string> moved = std::move(assigned);
    EXPECT_EQ(*moved, "PREOP");
}

TEST(RareOptional, ComparesByValue) {
    RareOptional<esi::Number> a = esi::Number{5, false};
    RareOptional<esi::Number> b = esi::Number{5, false};
    RareOptional<esi::Number> minus_five = esi::Number{5, true};
    RareOptional<esi::Number> none;
    EXPECT_TRUE(a == b);
    EXPECT_FALSE(a == minus_five);
    EXPECT_FALSE(a == none);
    EXPECT_TRUE(none == RareOptional<esi::Number>{});
    EXPECT_TRUE(a == (esi::Number{5, false}));
    EXPECT_FALSE(none == (esi::Number{5, false}));

    const std::optional<esi::Number> std_five = esi::Number{5, false};
    const std::optional<esi::Number> std_none;
    EXPECT_TRUE(a == std_five);
    EXPECT_FALSE(a == std_none);
    EXPECT_TRUE(none == std_none);  // both absent: equal, as two empty std::optionals are
    EXPECT_FALSE(none == std_five);
}

TEST(RareOptional, ConvertsToAndFromStdOptional) {
    const std::optional<std::string> from = std::string("T");
    RareOptional<std::string> field = from;
    EXPECT_EQ(*field, "T");
    field = std::optional<std::string>{};
    EXPECT_FALSE(field);

    field = "R";
    const std::optional<std::string> copy = field;
    ASSERT_TRUE(copy);
    EXPECT_EQ(*copy, "R");
    const std::optional<std::string> empty = RareOptional<std::string>{};
    EXPECT_FALSE(empty);
}

TEST(RareOptional, ModelElementsCopyTheirRareFields) {
    esi::ObjectInfo info;
    info.min_value = esi::Number{1, false};
    info.max_data = esi::HexData{"FF00", {}};
    info.display_name = "Gain";
    esi::ObjectInfo copy = info;
    copy.min_value = esi::Number{2, false};
    copy.display_name = std::nullopt;
    EXPECT_EQ(info.min_value->magnitude, 1u);
    EXPECT_EQ(*info.display_name, "Gain");
    EXPECT_EQ(copy.max_data->text, "FF00");
    EXPECT_FALSE(copy.display_name);
}

}  // namespace
