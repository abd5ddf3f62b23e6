#include "metric/metric_quality.hpp"

#include <cmath>

#include "geom/sym_functions.hpp"
#include "mesh/measure.hpp"
#include "mesh/simplex.hpp"

namespace hocav {

template <int D>
double metric_mean_ratio(const SimplexPoints<D>& points, const SymMat<D>& metric) {
  double squared_lengths = 0;
  for (int e = 0; e < Simplex<D>::kEdges; ++e) {
    auto [a, b] = edge_vertices<D>(e);
    squared_lengths += quadratic_form(metric, points[static_cast<std::size_t>(b)] - points[static_cast<std::size_t>(a)]);
  }
  const double measure = std::sqrt(determinant(metric)) * signed_measure<D>(points);
  if constexpr (D == 2) {
    return 4 * std::sqrt(3.0) * measure / squared_lengths;
  } else {
    // V^(2/3) with the sign of V, so that an inverted element scores below 0.
    return 36 / std::cbrt(3.0) * std::copysign(std::cbrt(measure * measure), measure) / squared_lengths;
  }
}

template <int D>
double centroid_metric_mean_ratio(const SimplexPoints<D>& points, const std::array<SymMat<D>, D + 1>& vertex_log_metrics) {
  SymMat<D> log_sum;
  for (const SymMat<D>& log_metric : vertex_log_metrics) log_sum += log_metric;
  return metric_mean_ratio<D>(points, exp_sym((1.0 / (D + 1)) * log_sum));
}

template double metric_mean_ratio(const SimplexPoints<2>&, const SymMat<2>&);
template double metric_mean_ratio(const SimplexPoints<3>&, const SymMat<3>&);
template double centroid_metric_mean_ratio(const SimplexPoints<2>&, const std::array<SymMat<2>, 3>&);
template double centroid_metric_mean_ratio(const SimplexPoints<3>&, const std::array<SymMat<3>, 4>&);

}  // namespace hocav
