// A small streaming JSON writer for machine-readable reports (`hocav stats --json`): objects,
// arrays, strings escaped per RFC 8259 (invalid UTF-8 becomes U+FFFD), numbers written so that they
// read back to the same double (shortest round trip), and null for NaN or infinity.
#pragma once

#include <concepts>
#include <cstdint>
#include <ostream>
#include <string>
#include <string_view>
#include <vector>

namespace hocav {

class JsonWriter {
 public:
  // indent 0 writes everything on one line; otherwise nested values are indented by that many spaces.
  explicit JsonWriter(std::ostream& out, int indent = 2) : out_(out), indent_(indent) {}

  JsonWriter& begin_object();
  JsonWriter& end_object();
  JsonWriter& begin_array();
  JsonWriter& end_array();
  // The key of the next member; only inside an object.
  JsonWriter& key(std::string_view name);

  JsonWriter& value(std::string_view text);
  JsonWriter& value(const char* text) { return value(std::string_view(text)); }
  JsonWriter& value(const std::string& text) { return value(std::string_view(text)); }
  JsonWriter& value(double number);
  JsonWriter& value(bool flag);
  JsonWriter& value(std::integral auto number) {
    if constexpr (std::same_as<decltype(number), bool>)
      return value(static_cast<bool>(number));
    else if constexpr (std::signed_integral<decltype(number)>)
      return write_integer(static_cast<std::int64_t>(number));
    else
      return write_unsigned(static_cast<std::uint64_t>(number));
  }
  JsonWriter& null();

  // key(name).value(v) in one call.
  template <class T>
  JsonWriter& member(std::string_view name, const T& v) {
    return key(name).value(v);
  }

 private:
  JsonWriter& write_integer(std::int64_t number);
  JsonWriter& write_unsigned(std::uint64_t number);
  void before_value();
  void open(char bracket, bool is_object);
  void close(char bracket, bool is_object);
  void new_line();

  struct Level {
    bool is_object;
    bool empty = true;
  };
  std::ostream& out_;
  int indent_;
  std::vector<Level> levels_;
  bool after_key_ = false;
};

// The JSON string literal for `text`, quotes included.
std::string json_quoted(std::string_view text);

}  // namespace hocav
