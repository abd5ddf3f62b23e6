// The length of a straight edge in a metric known only at its two ends, the metric varying
// geometrically along the edge (mmg's formula): with la = sqrt(e^T Ma e) and lb = sqrt(e^T Mb e),
// l = (la - lb) / log(la / lb), the logarithmic mean of la and lb (la when they are equal). A first
// measure for `hocav stats`; the curve module's log-Euclidean Riemannian length supersedes it.
#pragma once

#include <span>

#include "geom/vec.hpp"

namespace hocav {

// sqrt(e^T M e) for a symmetric matrix stored as its lower triangle row by row (the .sol order:
// m11 m12 m22 in 2D; m11 m12 m22 m13 m23 m33 in 3D).
template <int D>
double metric_norm(const Vec<D>& e, std::span<const double> lower_triangle);

// The logarithmic mean (la - lb) / log(la / lb), accurate when la and lb are close.
double logarithmic_mean(double la, double lb);

template <int D>
double straight_edge_length(const Vec<D>& a, const Vec<D>& b, std::span<const double> metric_a,
                            std::span<const double> metric_b) {
  Vec<D> e = b - a;
  return logarithmic_mean(metric_norm(e, metric_a), metric_norm(e, metric_b));
}

}  // namespace hocav
