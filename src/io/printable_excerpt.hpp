// Input bytes as they may appear in a message: a file's tokens can hold terminal escape sequences,
// binary garbage or megabytes without a space, none of which belongs on a user's terminal.
#pragma once

#include <string>
#include <string_view>

namespace hocav {

// At most `longest` bytes of `text`, printable ASCII kept, every other byte as \xNN; a longer text
// ends with "... (N bytes)". An excerpt of an excerpt with a larger `longest` is the same text.
std::string printable_excerpt(std::string_view text, std::size_t longest = 40);

}  // namespace hocav
