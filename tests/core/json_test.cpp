#include "core/json/json.h"

#include <gtest/gtest.h>

#include <limits>

using namespace cutcell;

TEST(Json, RoundTripKeepsValuesAndOrder) {
    const std::string text =
        R"({"b": 1.5, "a": [1, 2, {"x": "y\n\"q\""}], "t": true, "n": null, "u": "\u00e9"})";
    const json::Value v = json::parse(text);
    const json::Value back = json::parse(json::write(v));
    ASSERT_TRUE(back.isObject());
    EXPECT_EQ(back.asObject()[0].first, "b");
    EXPECT_DOUBLE_EQ(back.find("b")->asNumber(), 1.5);
    EXPECT_EQ(back.find("a")->asArray()[2].find("x")->asString(), "y\n\"q\"");
    EXPECT_TRUE(back.find("t")->asBool());
    EXPECT_TRUE(back.find("n")->isNull());
    EXPECT_EQ(back.find("u")->asString(), "\xc3\xa9");
}

// A negative indent writes one line (JSON Lines): the only line break is the last character,
// a string's own line break is escaped, and it reads back to the same document.
TEST(Json, OneLineWritingHasOneLineBreakAndRoundTrips) {
    const json::Value v = json::parse(
        R"({"b": 1.5, "a": [1, {"x": "y\nz"}, [2, [3]]], "o": {"p": {}}, "e": [], "n": null})");
    const std::string line = json::write(v, -1);
    ASSERT_FALSE(line.empty());
    EXPECT_EQ(line.find('\n'), line.size() - 1) << line;
    EXPECT_EQ(json::write(json::parse(line)), json::write(v));
}

TEST(Json, NumbersSurviveAtFullPrecision) {
    // Bit for bit (EXPECT_DOUBLE_EQ would let 4 ulps through). 0.1 + 0.2, 1 + 2^-52 and
    // 1/3 need 16 or 17 significant digits; the extremes must not overflow or flush to zero.
    for (double d :
         {0.1, 1.0 / 3.0, -2.5e-9, 123456.789012345, 4.397, 0.1 + 0.2,
          1.0 + std::numeric_limits<double>::epsilon(), std::numeric_limits<double>::max(),
          std::numeric_limits<double>::min(), std::numeric_limits<double>::denorm_min()}) {
        const json::Value v = json::parse(json::write(json::Value(json::Array{d})));
        EXPECT_EQ(v.asArray()[0].asNumber(), d) << json::write(json::Value(json::Array{d}));
    }
}

TEST(Json, SyntaxErrorsNameLineAndColumn) {
    try {
        json::parse("{\n  \"a\": 1,\n  \"b\": ]\n}");
        FAIL() << "no error";
    } catch (const json::ParseError& e) {
        EXPECT_EQ(e.line, 3);
        EXPECT_NE(std::string(e.what()).find("line 3"), std::string::npos);
    }
    EXPECT_THROW(json::parse("{\"a\": 1} x"), json::ParseError);
    EXPECT_THROW(json::parse("{\"a\": 1, \"a\": 2}"), json::ParseError);
    EXPECT_THROW(json::parse("[1, 2"), json::ParseError);
    EXPECT_THROW(json::parse(""), json::ParseError);
}
