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
ImpliedShare<D> implied_share(const Mesh<D>& mesh, Index k, Index number) {
  const auto& element = mesh.element(k);
  SimplexPoints<D> points;
  for (int i = 0; i <= D; ++i) points[static_cast<std::size_t>(i)] = mesh.vertex(element[i]);
  double weight = std::abs(element_measure(mesh, k));
  SymMat<D> metric = element_implied_metric<D>(points);
  if (!(weight > 0) || !is_spd(metric))
    throw Error("implied metric: element " + std::to_string(number) + " is flat, so it implies no metric");
  return {weight, weight * log_spd(metric)};
}

template <int D>
SymMat<D> implied_vertex_metric(const ImpliedShare<D>& sum) {
  return exp_sym((1 / sum.weight) * sum.weighted_log);
}

template <int D>
std::vector<SymMat<D>> implied_metric_at_vertices(const Mesh<D>& mesh) {
  std::vector<ImpliedShare<D>> sums(static_cast<std::size_t>(mesh.vertex_count()));
  for (Index k = 0; k < mesh.element_count(); ++k) {
    const ImpliedShare<D> share = implied_share(mesh, k, k + 1);
    for (Index v : mesh.element(k)) sums[static_cast<std::size_t>(v)] += share;
  }
  std::vector<SymMat<D>> metrics(sums.size());
  for (std::size_t v = 0; v < sums.size(); ++v) {
    if (sums[v].weight == 0) throw Error("implied metric: vertex " + one_based(v) + " belongs to no element, so it has no metric");
    metrics[v] = implied_vertex_metric(sums[v]);
  }
  return metrics;
}

template SymMat<2> element_implied_metric(const SimplexPoints<2>&);
template SymMat<3> element_implied_metric(const SimplexPoints<3>&);
template ImpliedShare<2> implied_share(const Mesh<2>&, Index, Index);
template ImpliedShare<3> implied_share(const Mesh<3>&, Index, Index);
template SymMat<2> implied_vertex_metric(const ImpliedShare<2>&);
template SymMat<3> implied_vertex_metric(const ImpliedShare<3>&);
template std::vector<SymMat<2>> implied_metric_at_vertices(const Mesh<2>&);
template std::vector<SymMat<3>> implied_metric_at_vertices(const Mesh<3>&);

}  // namespace hocav
