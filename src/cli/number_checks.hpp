// Checks of floating options. CLI11's Range and PositiveNumber let NaN through (every comparison
// with NaN is false), and no option of hocav means anything with NaN or an infinity: these refuse
// both, then check the range.
#pragma once

#include <CLI/CLI.hpp>

#include <cmath>
#include <limits>
#include <string>

namespace hocav {

inline CLI::Validator finite_range(double min, double max, const std::string& description) {
  return CLI::Validator(
      [min, max](std::string& input) -> std::string {
        double value = 0;
        if (!CLI::detail::lexical_cast(input, value) || !std::isfinite(value)) return "'" + input + "' is not a finite number";
        if (value < min || value > max)
          return "'" + input + "' is not in " + CLI::detail::to_string(min) + " to " + CLI::detail::to_string(max);
        return "";
      },
      description);
}

inline CLI::Validator finite_number() {
  return finite_range(std::numeric_limits<double>::lowest(), std::numeric_limits<double>::max(), "FINITE");
}

inline CLI::Validator finite_positive() {
  return finite_range(std::numeric_limits<double>::denorm_min(), std::numeric_limits<double>::max(), "POSITIVE");
}

}  // namespace hocav
