// Colours for values: the viridis colour map (perceptually uniform, readable in grey and by most
// colour-blind readers) over a value range, for cells coloured by a quality measure.
#pragma once

#include <string>

namespace hocav {

struct Color {
  double red = 0, green = 0, blue = 0;  // in [0, 1]

  // "#rrggbb"
  std::string hex() const;
};

// Viridis at t in [0, 1] (clamped): dark purple at 0, yellow at 1.
Color viridis(double t);

// Values over [lower, upper] (lower < upper) to viridis; values outside take the end colours.
struct ColorScale {
  double lower = 0, upper = 1;

  double fraction(double value) const;
  Color operator()(double value) const { return viridis(fraction(value)); }
};

}  // namespace hocav
