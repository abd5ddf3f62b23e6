#include "picture/color_map.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>

namespace hocav {

std::string Color::hex() const {
  auto byte = [](double channel) { return static_cast<int>(std::lround(255 * std::clamp(channel, 0.0, 1.0))); };
  char text[8];
  std::snprintf(text, sizeof text, "#%02x%02x%02x", byte(red), byte(green), byte(blue));
  return text;
}

Color viridis(double t) {
  // Viridis (matplotlib's default map, CC0) at t = 0, 1/8, ..., 1 (as R's viridis(9)); linear between.
  static constexpr std::array<std::array<int, 3>, 9> kStops{{{0x44, 0x01, 0x54},
                                                             {0x47, 0x2d, 0x7b},
                                                             {0x3b, 0x52, 0x8b},
                                                             {0x2c, 0x72, 0x8e},
                                                             {0x21, 0x90, 0x8c},
                                                             {0x27, 0xad, 0x81},
                                                             {0x5d, 0xc8, 0x63},
                                                             {0xaa, 0xdc, 0x32},
                                                             {0xfd, 0xe7, 0x25}}};
  const double position = std::clamp(std::isnan(t) ? 0.0 : t, 0.0, 1.0) * (kStops.size() - 1);
  const auto below = std::min(static_cast<std::size_t>(position), kStops.size() - 2);
  const double weight = position - static_cast<double>(below);
  auto channel = [&](std::size_t c) { return ((1 - weight) * kStops[below][c] + weight * kStops[below + 1][c]) / 255; };
  return {channel(0), channel(1), channel(2)};
}

double ColorScale::fraction(double value) const { return std::clamp((value - lower) / (upper - lower), 0.0, 1.0); }

}  // namespace hocav
