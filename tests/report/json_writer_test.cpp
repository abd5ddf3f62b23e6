#include "report/json_writer.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace hocav {
namespace {

TEST(Json, EscapesQuotesBackslashesAndControlCharacters) {
  EXPECT_EQ(json_quoted("plain"), "\"plain\"");
  EXPECT_EQ(json_quoted("a\"b\\c"), "\"a\\\"b\\\\c\"");
  EXPECT_EQ(json_quoted("\b\f\n\r\t"), "\"\\b\\f\\n\\r\\t\"");
  EXPECT_EQ(json_quoted(std::string("\x01\x1f", 2)), "\"\\u0001\\u001f\"");
  EXPECT_EQ(json_quoted(std::string("a\0b", 3)), "\"a\\u0000b\"");
  EXPECT_EQ(json_quoted("/"), "\"/\"");
}

TEST(Json, KeepsValidUtf8AndReplacesInvalidBytes) {
  EXPECT_EQ(json_quoted("maillage \xc3\xa9 \xe2\x82\xac \xf0\x9f\x98\x80"), "\"maillage \xc3\xa9 \xe2\x82\xac \xf0\x9f\x98\x80\"");
  EXPECT_EQ(json_quoted("\xff"), "\"\\ufffd\"");
  EXPECT_EQ(json_quoted("\xc0\xaf"), "\"\\ufffd\\ufffd\"");                        // overlong '/'
  EXPECT_EQ(json_quoted("\xed\xa0\x80"), "\"\\ufffd\\ufffd\\ufffd\"");             // a UTF-16 surrogate
  EXPECT_EQ(json_quoted("\xe2\x82"), "\"\\ufffd\\ufffd\"");                        // truncated sequence
  EXPECT_EQ(json_quoted("\xf4\x90\x80\x80"), "\"\\ufffd\\ufffd\\ufffd\\ufffd\"");  // above U+10FFFF
}

std::string compact(void (*write)(JsonWriter&)) {
  std::ostringstream out;
  JsonWriter json(out, 0);
  write(json);
  return out.str();
}

TEST(Json, NumbersReadBackExactlyAndNonFiniteBecomesNull) {
  EXPECT_EQ(compact([](JsonWriter& j) { j.value(0.1); }), "0.1");
  EXPECT_EQ(compact([](JsonWriter& j) { j.value(1.0 / 3.0); }), "0.3333333333333333");
  EXPECT_EQ(compact([](JsonWriter& j) { j.value(1e300); }), "1e+300");
  EXPECT_EQ(compact([](JsonWriter& j) { j.value(-2.5e-8); }), "-2.5e-08");
  EXPECT_EQ(compact([](JsonWriter& j) { j.value(3.0); }), "3");
  EXPECT_EQ(compact([](JsonWriter& j) { j.value(std::nan("")); }), "null");
  EXPECT_EQ(compact([](JsonWriter& j) { j.value(-std::numeric_limits<double>::infinity()); }), "null");
  EXPECT_EQ(compact([](JsonWriter& j) { j.value(std::numeric_limits<std::int64_t>::min()); }), "-9223372036854775808");
  EXPECT_EQ(compact([](JsonWriter& j) { j.value(std::numeric_limits<std::uint64_t>::max()); }), "18446744073709551615");
  EXPECT_EQ(compact([](JsonWriter& j) { j.value(true).value(false); }), "truefalse");  // top level takes no commas
  double value = 0.1 + 0.2;
  std::ostringstream out;
  JsonWriter(out, 0).value(value);
  EXPECT_EQ(std::stod(out.str()), value);
}

TEST(Json, NestsObjectsAndArraysCompactly) {
  EXPECT_EQ(compact([](JsonWriter& j) {
              j.begin_object().member("a", 1).key("b").begin_array().value("x").null().begin_object().end_object();
              j.begin_array().end_array().end_array().member("c", false).end_object();
            }),
            "{\"a\":1,\"b\":[\"x\",null,{},[]],\"c\":false}");
}

TEST(Json, IndentsNestedValues) {
  std::ostringstream out;
  JsonWriter json(out, 2);
  json.begin_object().member("n", 2).key("list").begin_array().value(1).value(2).end_array();
  json.key("empty").begin_object().end_object().end_object();
  EXPECT_EQ(out.str(), "{\n  \"n\": 2,\n  \"list\": [\n    1,\n    2\n  ],\n  \"empty\": {}\n}\n");
}

TEST(Json, RejectsMisuse) {
  std::ostringstream out;
  JsonWriter json(out, 0);
  json.begin_object();
  EXPECT_THROW(json.value(1), std::logic_error);  // a member needs a key
  EXPECT_THROW(json.end_array(), std::logic_error);
  json.key("k");
  EXPECT_THROW(json.key("again"), std::logic_error);
  EXPECT_THROW(json.end_object(), std::logic_error);  // the key has no value
}

}  // namespace
}  // namespace hocav
