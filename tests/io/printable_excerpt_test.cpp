#include "io/printable_excerpt.hpp"

#include <gtest/gtest.h>

#include <string>

namespace hocav {
namespace {

TEST(PrintableExcerpt, EscapesControlAndNonAsciiBytes) {
  EXPECT_EQ(printable_excerpt("Vertices"), "Vertices");
  EXPECT_EQ(printable_excerpt("\033[2J\033[31mX"), "\\x1b[2J\\x1b[31mX");
  EXPECT_EQ(printable_excerpt(std::string("a\0b\xff", 4)), "a\\x00b\\xff");
}

TEST(PrintableExcerpt, CutsALongTokenAndSaysHowLongItWas) {
  const std::string token(20'000'000, 'x');
  EXPECT_EQ(printable_excerpt(token), std::string(40, 'x') + "... (20000000 bytes)");
  const std::string excerpt = printable_excerpt(std::string(50, 'y'), 10);
  EXPECT_EQ(printable_excerpt(excerpt, 80), excerpt);  // an excerpt stays as it is
}

}  // namespace
}  // namespace hocav
