#include "metric/straight_edge_length.hpp"

#include <cmath>

namespace hocav {

template <int D>
double metric_norm(const Vec<D>& e, std::span<const double> lower_triangle) {
  double squared = 0;
  std::size_t entry = 0;
  for (int row = 0; row < D; ++row)
    for (int column = 0; column <= row; ++column)
      squared += (row == column ? 1.0 : 2.0) * lower_triangle[entry++] * e[row] * e[column];
  return std::sqrt(squared);
}

double logarithmic_mean(double la, double lb) {
  if (la == lb) return la;  // also a zero-length edge
  // With x = lb / la - 1: (la - lb) / log(la / lb) = la * x / log1p(x), free of cancellation.
  double x = (lb - la) / la;
  return la * x / std::log1p(x);
}

template double metric_norm(const Vec<2>&, std::span<const double>);
template double metric_norm(const Vec<3>&, std::span<const double>);

}  // namespace hocav
