// Wall time since a moment, in seconds: the figures of reports and progress lines.
#pragma once

#include <chrono>

namespace hocav {

inline double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace hocav
