// P1 measures in a metric known at the vertices (docs/adaptation.md §Measures), the figures the
// adaptation loop's decisions are made on:
// - the length of a straight edge with metrics M_a, M_b at its ends: with l_a = |ab|_{M_a},
//   l_b = |ab|_{M_b}, l = (l_a − l_b) / ln(l_a / l_b) (the size varying geometrically along the edge);
// - the metric mean ratio of a simplex in the mean of its vertex metrics.
#pragma once

#include <array>
#include <cmath>

#include "geom/barycentric.hpp"
#include "geom/sym_mat.hpp"
#include "metric/metric_quality.hpp"

namespace hocav {

template <int D>
double metric_edge_length(const Vec<D>& a, const Vec<D>& b, const SymMat<D>& metric_a, const SymMat<D>& metric_b) {
  const Vec<D> e = b - a;
  const double la = std::sqrt(quadratic_form(metric_a, e)), lb = std::sqrt(quadratic_form(metric_b, e));
  if (std::abs(la - lb) <= 1e-6 * (la + lb)) return 0.5 * (la + lb);
  return (la - lb) / std::log(la / lb);
}

// The loop's element quality: the metric mean ratio (metric/metric_quality.hpp) in the mean of
// the vertex metrics, which needs no exponential (the reported quality takes the metric at the
// centroid, log-Euclidean; the two agree where the metric varies little over an element).
template <int D>
double mean_metric_ratio(const SimplexPoints<D>& points, const std::array<SymMat<D>, D + 1>& metrics) {
  SymMat<D> mean;
  for (const auto& m : metrics)
    for (std::size_t i = 0; i < mean.entries.size(); ++i) mean.entries[i] += m.entries[i] / (D + 1);
  return metric_mean_ratio<D>(points, mean);
}

}  // namespace hocav
