// P1 measures in a metric known at the vertices (docs/adaptation.md §Measures), the figures the
// adaptation loop's decisions are made on:
// - the length of a straight edge with metrics M_a, M_b at its ends: with l_a = |ab|_{M_a},
//   l_b = |ab|_{M_b}, l = (l_a − l_b) / ln(l_a / l_b) (the size varying geometrically along the edge);
// - the metric mean ratio of a simplex in the mean M̄ of its vertex metrics:
//   3D: 36/3^(1/3) (√det M̄ V)^(2/3) / Σ l²,  2D: 4√3 √det M̄ A / Σ l², l measured in M̄;
//   1 for a simplex that is regular in M̄, 0 for a flat one, negative for an inverted one.
#pragma once

#include <array>
#include <cmath>

#include "geom/sym_mat.hpp"
#include "mesh/measure.hpp"

namespace hocav {

template <int D>
double metric_edge_length(const Vec<D>& a, const Vec<D>& b, const SymMat<D>& metric_a, const SymMat<D>& metric_b) {
  const Vec<D> e = b - a;
  const double la = std::sqrt(quadratic_form(metric_a, e)), lb = std::sqrt(quadratic_form(metric_b, e));
  if (std::abs(la - lb) <= 1e-6 * (la + lb)) return 0.5 * (la + lb);
  return (la - lb) / std::log(la / lb);
}

template <int D>
double metric_mean_ratio(const std::array<Vec<D>, D + 1>& p, const std::array<SymMat<D>, D + 1>& metrics) {
  SymMat<D> mean;
  for (const auto& m : metrics)
    for (std::size_t i = 0; i < mean.entries.size(); ++i) mean.entries[i] += m.entries[i] / (D + 1);
  double squared_lengths = 0;
  for (int i = 0; i <= D; ++i)
    for (int j = 0; j < i; ++j) squared_lengths += quadratic_form(mean, p[i] - p[j]);
  const double root_det = std::sqrt(determinant(mean));
  if constexpr (D == 2) {
    return 4 * std::sqrt(3.0) * root_det * signed_measure(p[0], p[1], p[2]) / squared_lengths;
  } else {
    const double volume = root_det * signed_measure(p[0], p[1], p[2], p[3]);
    return 36 / std::cbrt(3.0) * std::copysign(std::cbrt(volume * volume), volume) / squared_lengths;
  }
}

}  // namespace hocav
