#include "io/text_scanner.hpp"

#include <charconv>
#include <cmath>
#include <fstream>
#include <sstream>

#include "base/error.hpp"
#include "io/printable_excerpt.hpp"

namespace hocav {

TextScanner::TextScanner(std::string path, char comment_char) : path_(std::move(path)), comment_char_(comment_char) {
  std::ifstream in(path_, std::ios::binary);
  if (!in) throw Error(path_ + ": cannot open for reading");
  std::ostringstream buffer;
  buffer << in.rdbuf();
  text_ = std::move(buffer).str();
}

TextScanner::TextScanner(std::string path, std::string text, char comment_char)
    : path_(std::move(path)), text_(std::move(text)), comment_char_(comment_char) {}

void TextScanner::skip_space_and_comments() {
  while (position_ < text_.size()) {
    char c = text_[position_];
    if (c == '\n') {
      ++current_line_;
      ++position_;
    } else if (c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v') {
      ++position_;
    } else if (comment_char_ != '\0' && c == comment_char_) {
      while (position_ < text_.size() && text_[position_] != '\n') ++position_;
    } else {
      break;
    }
  }
}

bool TextScanner::at_end() {
  skip_space_and_comments();
  return position_ >= text_.size();
}

std::string_view TextScanner::next_token() {
  skip_space_and_comments();
  token_line_ = current_line_;
  std::size_t start = position_;
  while (position_ < text_.size()) {
    char c = text_[position_];
    if (c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\f' || c == '\v') break;
    ++position_;
  }
  return std::string_view(text_).substr(start, position_ - start);
}

std::int64_t TextScanner::next_integer(std::string_view what) {
  std::string_view token = next_token();
  if (token.empty()) fail(what, "unexpected end of file");
  std::int64_t value = 0;
  auto [end, error] = std::from_chars(token.data(), token.data() + token.size(), value);
  if (error == std::errc::result_out_of_range) fail(what, "integer out of range '" + printable_excerpt(token) + "'");
  if (error != std::errc() || end != token.data() + token.size())
    fail(what, "expected an integer, found '" + printable_excerpt(token) + "'");
  return value;
}

double TextScanner::next_real(std::string_view what) {
  std::string_view token = next_token();
  if (token.empty()) fail(what, "unexpected end of file");
  double value = 0;
  auto [end, error] = std::from_chars(token.data(), token.data() + token.size(), value);
  if (error == std::errc::result_out_of_range) {
    // Underflow to a denormal or zero is harmless; overflow is not.
    std::string copy(token);
    value = std::strtod(copy.c_str(), nullptr);
    if (std::isinf(value)) fail(what, "real out of range '" + printable_excerpt(copy) + "'");
    return value;
  }
  if (error != std::errc() || end != token.data() + token.size()) fail(what, "expected a real, found '" + printable_excerpt(token) + "'");
  if (!std::isfinite(value)) fail(what, "value is not finite '" + printable_excerpt(token) + "'");
  return value;
}

void TextScanner::fail(std::string_view what, std::string_view message) const {
  throw Error(path_ + ": " + printable_excerpt(what, 80) + ": " + std::string(message) + ", line " + std::to_string(token_line_));
}

}  // namespace hocav
