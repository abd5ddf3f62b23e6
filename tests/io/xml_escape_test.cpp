#include "io/xml_escape.hpp"

#include <gtest/gtest.h>

namespace hocav {
namespace {

TEST(XmlEscape, ReplacesEveryXmlSpecialCharacter) {
  EXPECT_EQ(xml_escaped("<&>\"' ok"), "&lt;&amp;&gt;&quot;&apos; ok");
  EXPECT_EQ(xml_escaped("plain text, é"), "plain text, é");
  EXPECT_EQ(xml_escaped(""), "");
}

}  // namespace
}  // namespace hocav
