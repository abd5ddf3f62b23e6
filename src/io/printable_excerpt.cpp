#include "io/printable_excerpt.hpp"

#include <cstdio>

namespace hocav {

std::string printable_excerpt(std::string_view text, std::size_t longest) {
  std::string excerpt;
  for (unsigned char byte : text.substr(0, longest)) {
    if (byte >= 0x20 && byte < 0x7f) {
      excerpt += static_cast<char>(byte);
    } else {
      char escaped[5];
      std::snprintf(escaped, sizeof escaped, "\\x%02x", byte);
      excerpt += escaped;
    }
  }
  if (text.size() > longest) excerpt += "... (" + std::to_string(text.size()) + " bytes)";
  return excerpt;
}

}  // namespace hocav
