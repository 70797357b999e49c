// csv_lines: the line and field reading that stability.csv and bench.csv share.
#include "measure/csv_lines.h"

#include <gtest/gtest.h>

#include "base/input_error.h"

namespace pcf {
namespace {

TEST(CsvLines, NumbersLinesDropsCarriageReturnsAndKeepsALastLineWithoutNewline) {
    std::vector<CsvLine> lines = csvLines("a,b\r\n\nc,d");
    ASSERT_EQ(lines.size(), 3u);
    EXPECT_EQ(lines[0].number, 1);
    EXPECT_EQ(lines[0].text, "a,b");
    EXPECT_EQ(lines[1].number, 2);
    EXPECT_EQ(lines[1].text, "");
    EXPECT_EQ(lines[2].number, 3);
    EXPECT_EQ(lines[2].text, "c,d");
    EXPECT_TRUE(csvLines("").empty());
    EXPECT_EQ(csvLines("x\n").size(), 1u);
}

TEST(CsvFields, SplitsAtEveryCommaKeepingEmptyFields) {
    CsvFields f("1,,2.5,", "f.csv", 4);
    ASSERT_EQ(f.size(), 4u);
    EXPECT_EQ(f.text(1), "");
    EXPECT_EQ(f.text(3), "");
    EXPECT_DOUBLE_EQ(f.number(2), 2.5);
    EXPECT_EQ(f.integer(0), 1);
    EXPECT_TRUE(f.flag(0));
}

// Each reader blames the file and line it was given, with the field's 1-based position.
TEST(CsvFields, BadFieldsNameTheFileLineAndField) {
    CsvFields f("x,2.5,1e30,2,inf", "runs/bench.csv", 7);
    auto problemOf = [](auto read) {
        try {
            read();
        } catch (const InputError& e) {
            EXPECT_EQ(e.source(), "runs/bench.csv");
            EXPECT_EQ(e.line(), 7);
            return e.problem();
        }
        return std::string("no error");
    };
    EXPECT_EQ(problemOf([&] { f.number(0); }), "field 1 'x' is not a number");
    EXPECT_EQ(problemOf([&] { f.integer(1); }), "field 2 '2.5' is not a whole number");
    EXPECT_EQ(problemOf([&] { f.integer(2); }), "field 3 '1e30' is not a whole number");
    EXPECT_EQ(problemOf([&] { f.flag(3); }), "field 4 '2' is not 0 or 1");
    EXPECT_EQ(problemOf([&] { f.number(4); }), "field 5 'inf' is not a number");
}

}  // namespace
}  // namespace pcf
