// Malformed JSON (io/JsonText.hpp) in plain words with file, line and column, never the JSON
// library's exception text ("[json.exception.parse_error.101] ... last read: '[N'").

#include "io/JsonText.hpp"

#include <gtest/gtest.h>

using namespace mcdda;

namespace {

/// The one message parsing `text` gives.
std::string message(const std::string& text) {
    std::vector<Diagnostic> d;
    EXPECT_FALSE(parse_json_text(text, "f.json", d).has_value()) << text;
    EXPECT_EQ(d.size(), 1u) << text;
    const std::string m = d.empty() ? std::string() : d[0].message;
    EXPECT_EQ(m.find("json.exception"), std::string::npos) << m;
    EXPECT_EQ(m.find("last read"), std::string::npos) << m;
    return m;
}

}  // namespace

TEST(JsonText, SaysWhatIsWrongWhere) {
    EXPECT_EQ(message("{\"values\": [NaN]}"),
              "f.json:1:13: malformed JSON: NaN is not a number in JSON, which has no NaN or infinity: write a finite "
              "number");
    EXPECT_NE(message("[1, -Infinity]").find("-Infinity is not a number in JSON"), std::string::npos);
    EXPECT_EQ(message("{\n  \"a\": 1e400\n}"), "f.json:2:8: number 1e400 is too large (beyond ±1.8e308)");
    EXPECT_EQ(message("{\n  oops\n}"), "f.json:2:3: malformed JSON: a key must be text in double quotes, got oops");
    EXPECT_NE(message("[tru]").find("f.json:1:2: malformed JSON: tru is not a JSON value"), std::string::npos);
    EXPECT_EQ(message("[1e]"),
              "f.json:1:2: malformed JSON: 1e is not a number (expected '+', '-', or digit after exponent)");
    EXPECT_EQ(message("{\"a\": 1,}"), "f.json:1:9: malformed JSON: found '}' where text in double quotes was expected");
    EXPECT_NE(message("[1, 2").find("ends before the JSON does"), std::string::npos);
    EXPECT_NE(message(" \n").find("the file is empty"), std::string::npos);
    EXPECT_NE(message("[\"\xff\"]").find("not UTF-8"), std::string::npos);
    std::vector<Diagnostic> d;
    EXPECT_TRUE(parse_json_text("{\"a\": [1, -1.5e3]}", "f.json", d).has_value());
    EXPECT_TRUE(d.empty());
}
