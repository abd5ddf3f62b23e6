#include "metric/hessian_metric.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "base/error.hpp"
#include "geom/sym_eigen.hpp"
#include "mesh/measure.hpp"

namespace hocav {

template <int D>
std::vector<double> vertex_volumes(const Mesh<D>& mesh) {
  std::vector<double> volumes(static_cast<std::size_t>(mesh.vertex_count()), 0.0);
  for (Index k = 0; k < mesh.element_count(); ++k) {
    double share = std::abs(element_measure(mesh, k)) / (D + 1);
    for (Index v : mesh.element(k)) volumes[static_cast<std::size_t>(v)] += share;
  }
  return volumes;
}

template <int D>
double metric_complexity(std::span<const double> volumes, std::span<const SymMat<D>> metrics) {
  double complexity = 0;
  for (std::size_t v = 0; v < volumes.size(); ++v) complexity += volumes[v] * std::sqrt(determinant(metrics[v]));
  return complexity;
}

template <int D>
double metric_complexity(const Mesh<D>& mesh, const std::vector<SymMat<D>>& metrics) {
  const std::vector<double> volumes = vertex_volumes(mesh);
  return metric_complexity<D>(volumes, metrics);
}

void check_lp_options(const LpMetricOptions& options) {
  if (!(options.complexity > 0) || !std::isfinite(options.complexity)) throw Error("hessian metric: the complexity must be positive");
  if (!(options.norm > 0) || !std::isfinite(options.norm)) throw Error("hessian metric: the norm p must be positive");
  if (!(options.h_min > 0) || !(options.h_min <= options.h_max) || !std::isfinite(options.h_max))
    throw Error("hessian metric: sizes must satisfy 0 < h-min <= h-max");
}

template <int D>
LpVertex<D> lp_vertex(const SymMat<D>& hessian, const LpMetricOptions& options, Index vertex_number) {
  const double smallest = 1 / (options.h_max * options.h_max), largest = 1 / (options.h_min * options.h_min);
  SymEigen<D> eigen = sym_eigen(hessian);
  double det = 1;
  for (int k = 0; k < D; ++k) {
    eigen.values[k] = std::clamp(std::abs(eigen.values[k]), smallest, largest);
    det *= eigen.values[k];
  }
  if (!std::isfinite(det)) throw Error("hessian metric: the Hessian at vertex " + std::to_string(vertex_number) + " is not finite");
  const double exponent = -1 / (2 * options.norm + D);  // of det(|H|) in M
  return {std::pow(det, exponent) * SymMat<D>::from_eigen(eigen.vectors, eigen.values),
          std::pow(det, options.norm / (2 * options.norm + D))};
}

template <int D>
double lp_scale(const LpMetricOptions& options, double density_integral) {
  if (!(density_integral > 0)) throw Error("hessian metric: the mesh has no volume");
  return std::pow(options.complexity / density_integral, 2.0 / D);
}

template <int D>
std::vector<SymMat<D>> lp_metric(const Mesh<D>& mesh, const std::vector<SymMat<D>>& hessians, const LpMetricOptions& options) {
  check_lp_options(options);
  if (hessians.size() != static_cast<std::size_t>(mesh.vertex_count()))
    throw Error("hessian metric: " + std::to_string(hessians.size()) + " Hessians for " + std::to_string(mesh.vertex_count()) +
                " vertices");
  std::vector<SymMat<D>> metrics(hessians.size());
  std::vector<double> densities(hessians.size());
  for (std::size_t v = 0; v < hessians.size(); ++v) {
    const LpVertex<D> vertex = lp_vertex(hessians[v], options, static_cast<Index>(v + 1));
    metrics[v] = vertex.metric;
    densities[v] = vertex.density;
  }
  std::vector<double> volumes = vertex_volumes(mesh);
  double integral = 0;
  for (std::size_t v = 0; v < volumes.size(); ++v) integral += volumes[v] * densities[v];
  const double scale = lp_scale<D>(options, integral);  // D_N
  for (SymMat<D>& metric : metrics) metric *= scale;
  return metrics;
}

template std::vector<double> vertex_volumes(const Mesh<2>&);
template std::vector<double> vertex_volumes(const Mesh<3>&);
template double metric_complexity<2>(std::span<const double>, std::span<const SymMat<2>>);
template double metric_complexity<3>(std::span<const double>, std::span<const SymMat<3>>);
template double metric_complexity(const Mesh<2>&, const std::vector<SymMat<2>>&);
template double metric_complexity(const Mesh<3>&, const std::vector<SymMat<3>>&);
template LpVertex<2> lp_vertex(const SymMat<2>&, const LpMetricOptions&, Index);
template LpVertex<3> lp_vertex(const SymMat<3>&, const LpMetricOptions&, Index);
template double lp_scale<2>(const LpMetricOptions&, double);
template double lp_scale<3>(const LpMetricOptions&, double);
template std::vector<SymMat<2>> lp_metric(const Mesh<2>&, const std::vector<SymMat<2>>&, const LpMetricOptions&);
template std::vector<SymMat<3>> lp_metric(const Mesh<3>&, const std::vector<SymMat<3>>&, const LpMetricOptions&);

}  // namespace hocav
