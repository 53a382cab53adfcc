// JsonWriter (output/json_writer.hpp): whatever it is given, the text is one
// JSON value that a real parser (nlohmann_json) reads back to the same
// structure, keys in the order given, strings byte for byte, doubles bit for
// bit, and non-finite numbers as null.
#include "rackopt/output/json_writer.hpp"

#include <gtest/gtest.h>

#include <bit>
#include <climits>
#include <cstdint>
#include <cstdlib>
#include <limits>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace rackopt {
namespace {

using ordered = nlohmann::ordered_json;

TEST(JsonWriter, NestingSeparatorsAndKeyOrder) {
  JsonWriter w;
  w.begin_object();
  w.key("z").value(1);
  w.key("a").begin_array().value(true).value(false).null().value("x").begin_array().end_array().end_array();
  w.key("m").begin_object().end_object();
  w.key("n").begin_object().key("inner").begin_object().key("k").value(2L).end_object().end_object();
  w.key("last").value(std::string("s"));
  w.end_object();
  const ordered j = ordered::parse(w.str());  // throws unless exactly one JSON value
  const ordered want = {{"z", 1},
                        {"a", {true, false, nullptr, "x", ordered::array()}},
                        {"m", ordered::object()},
                        {"n", {{"inner", {{"k", 2}}}}},
                        {"last", "s"}};
  EXPECT_EQ(j, want) << w.str();
  std::vector<std::string> keys;
  for (const auto& [k, v] : j.items()) keys.push_back(k);
  EXPECT_EQ(keys, (std::vector<std::string>{"z", "a", "m", "n", "last"}));  // as given, not sorted
}

TEST(JsonWriter, TopLevelArraysAndEmptyContainers) {
  JsonWriter a;
  a.begin_array().end_array();
  EXPECT_EQ(nlohmann::json::parse(a.str()), nlohmann::json::array());
  JsonWriter o;
  o.begin_object().end_object();
  EXPECT_EQ(nlohmann::json::parse(o.str()), nlohmann::json::object());
  JsonWriter rows;
  rows.begin_array();
  for (int i = 0; i < 3; ++i) rows.begin_object().key("i").value(i).end_object();
  rows.end_array();
  EXPECT_EQ(nlohmann::json::parse(rows.str()), nlohmann::json::parse(R"([{"i":0},{"i":1},{"i":2}])"));
}

TEST(JsonWriter, StringsRoundTripWithEveryControlCharacterEscaped) {
  std::string all_controls;
  for (int c = 1; c < 0x20; ++c) all_controls += static_cast<char>(c);
  const std::vector<std::string> texts = {"",
                                          "plain",
                                          "quote \" and backslash \\ and slash /",
                                          "line\nbreak\r\ttab",
                                          all_controls,
                                          std::string("nul \0 inside", 12),
                                          "\x7f delete",
                                          "UTF-8: \xc3\xa9 \xe6\xbc\xa2 \xf0\x9f\x94\xa7",
                                          "C:\\path\\file.yaml:3:7: pinion.module: \"x\""};
  for (const std::string& t : texts) {
    JsonWriter w;
    w.begin_object().key(t).value(t).end_object();
    const std::string& out = w.str();
    for (unsigned char c : out) EXPECT_GE(c, 0x20) << "raw control character in " << out;
    const nlohmann::json j = nlohmann::json::parse(out);
    ASSERT_EQ(j.size(), 1u) << out;
    EXPECT_EQ(j.begin().key(), t) << out;
    EXPECT_EQ(j.begin().value().get<std::string>(), t) << out;
    // escape() alone is a JSON string literal of the same text.
    EXPECT_EQ(nlohmann::json::parse(JsonWriter::escape(t)).get<std::string>(), t);
  }
}

// The number text of `v` written alone.
std::string number_text(double v) {
  JsonWriter w;
  w.value(v);
  return w.str();
}

TEST(JsonWriter, DoublesReadBackBitForBit) {
  const std::vector<double> values = {0.0,
                                      -0.0,
                                      1.0,
                                      -2.5,
                                      0.1,
                                      0.1 + 0.2,
                                      1.0 / 3.0,
                                      2.0 / 3.0 * 1e-7,
                                      6.02214076e23,
                                      1e21,
                                      123456789012345678.0,
                                      std::numeric_limits<double>::max(),
                                      std::numeric_limits<double>::lowest(),
                                      std::numeric_limits<double>::min(),
                                      std::numeric_limits<double>::denorm_min(),
                                      std::numeric_limits<double>::epsilon()};
  for (double v : values) {
    const std::string text = number_text(v);
    EXPECT_EQ(std::bit_cast<std::uint64_t>(std::strtod(text.c_str(), nullptr)), std::bit_cast<std::uint64_t>(v))
        << text;
    // Valid JSON number syntax: the parser takes it as a number.
    const nlohmann::json j = nlohmann::json::parse(text);
    EXPECT_TRUE(j.is_number()) << text;
    EXPECT_EQ(j.get<double>(), v) << text;
  }
}

TEST(JsonWriter, NonFiniteNumbersAreNull) {
  JsonWriter w;
  w.begin_object();
  w.key("inf").value(std::numeric_limits<double>::infinity());
  w.key("-inf").value(-std::numeric_limits<double>::infinity());
  w.key("nan").value(std::numeric_limits<double>::quiet_NaN());
  w.key("after").value(1.5);
  w.end_object();
  const nlohmann::json j = nlohmann::json::parse(w.str());
  EXPECT_TRUE(j["inf"].is_null());
  EXPECT_TRUE(j["-inf"].is_null());
  EXPECT_TRUE(j["nan"].is_null());
  EXPECT_EQ(j["after"].get<double>(), 1.5);
}

TEST(JsonWriter, IntegersAreExact) {
  JsonWriter w;
  w.begin_array().value(INT_MIN).value(INT_MAX).value(LONG_MIN).value(LONG_MAX).value(0L).end_array();
  const nlohmann::json j = nlohmann::json::parse(w.str());
  EXPECT_EQ(j[0].get<long long>(), INT_MIN);
  EXPECT_EQ(j[1].get<long long>(), INT_MAX);
  EXPECT_EQ(j[2].get<long long>(), LONG_MIN);
  EXPECT_EQ(j[3].get<long long>(), LONG_MAX);
  EXPECT_EQ(j[4].get<long long>(), 0);
}

TEST(JsonWriter, RawValuesGoInAsTheyAreWithSeparators) {
  JsonWriter inner;
  inner.begin_object().key("k").value(1).end_object();
  JsonWriter w;
  w.begin_object();
  w.key("first").raw(inner.str());
  w.key("list").begin_array().raw("[1,2]").raw("{}").value(3).end_array();
  w.end_object();
  const nlohmann::json j = nlohmann::json::parse(w.str());
  EXPECT_EQ(j, nlohmann::json::parse(R"({"first":{"k":1},"list":[[1,2],{},3]})")) << w.str();
}

}  // namespace
}  // namespace rackopt
