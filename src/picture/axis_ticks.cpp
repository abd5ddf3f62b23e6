#include "picture/axis_ticks.hpp"

#include <cmath>
#include <cstdio>

namespace hocav {

std::vector<double> round_ticks(double lower, double upper, int target) {
  if (!std::isfinite(lower) || !std::isfinite(upper) || lower > upper) return {};
  if (lower == upper) return {lower};
  const double rough = (upper - lower) / std::max(1, target);
  const double power = std::pow(10.0, std::floor(std::log10(rough)));
  double step = power;  // the round step nearest to the rough one, in ratio
  for (double factor : {2.0, 5.0, 10.0})
    if (std::abs(std::log(factor * power / rough)) < std::abs(std::log(step / rough))) step = factor * power;
  std::vector<double> ticks;
  for (double k = std::ceil(lower / step - 1e-9); k * step <= upper + 1e-9 * step; ++k) {
    const double tick = k * step;
    ticks.push_back(std::abs(tick) < 1e-12 * step ? 0.0 : tick);
  }
  return ticks;
}

std::string tick_label(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", std::abs(value) < 1e-12 ? 0.0 : value);
  return text;
}

}  // namespace hocav
