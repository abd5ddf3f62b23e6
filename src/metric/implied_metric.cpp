#include "metric/implied_metric.hpp"

#include <cmath>
#include <string>

#include "base/error.hpp"
#include "geom/sym_functions.hpp"
#include "mesh/measure.hpp"

namespace hocav {

template <int D>
SymMat<D> element_implied_metric(const SimplexPoints<D>& points) {
  SymMat<D> metric;
  for (const Vec<D>& gradient : barycentric_gradients<D>(points)) metric += 0.5 * outer(gradient);
  return metric;
}

template <int D>
std::vector<SymMat<D>> implied_metric_at_vertices(const Mesh<D>& mesh) {
  const auto vertex_count = static_cast<std::size_t>(mesh.vertex_count());
  std::vector<SymMat<D>> log_sums(vertex_count);
  std::vector<double> weights(vertex_count, 0.0);
  for (Index k = 0; k < mesh.element_count(); ++k) {
    const auto& element = mesh.element(k);
    SimplexPoints<D> points;
    for (int i = 0; i <= D; ++i) points[static_cast<std::size_t>(i)] = mesh.vertex(element[i]);
    double weight = std::abs(element_measure(mesh, k));
    SymMat<D> metric = element_implied_metric<D>(points);
    if (!(weight > 0) || !is_spd(metric))
      throw Error("implied metric: element " + std::to_string(k + 1) + " is flat, so it implies no metric");
    SymMat<D> weighted_log = weight * log_spd(metric);
    for (Index v : element) {
      log_sums[static_cast<std::size_t>(v)] += weighted_log;
      weights[static_cast<std::size_t>(v)] += weight;
    }
  }
  std::vector<SymMat<D>> metrics(vertex_count);
  for (std::size_t v = 0; v < vertex_count; ++v) {
    if (weights[v] == 0) throw Error("implied metric: vertex " + std::to_string(v + 1) + " belongs to no element, so it has no metric");
    metrics[v] = exp_sym((1 / weights[v]) * log_sums[v]);
  }
  return metrics;
}

template SymMat<2> element_implied_metric(const SimplexPoints<2>&);
template SymMat<3> element_implied_metric(const SimplexPoints<3>&);
template std::vector<SymMat<2>> implied_metric_at_vertices(const Mesh<2>&);
template std::vector<SymMat<3>> implied_metric_at_vertices(const Mesh<3>&);

}  // namespace hocav
