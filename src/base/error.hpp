// The one exception type of hocav: a clear, one-line message for the user.
// The command line turns it into "hocav: <message>" on stderr and exit code 2.
#pragma once

#include <stdexcept>
#include <string>

namespace hocav {

class Error : public std::runtime_error {
 public:
  explicit Error(const std::string& message) : std::runtime_error(message) {}
};

}  // namespace hocav
