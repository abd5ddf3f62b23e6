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

template <int D>
std::vector<SymMat<D>> lp_metric(const Mesh<D>& mesh, const std::vector<SymMat<D>>& hessians, const LpMetricOptions& options) {
  if (!(options.complexity > 0) || !std::isfinite(options.complexity)) throw Error("hessian metric: the complexity must be positive");
  if (!(options.norm > 0) || !std::isfinite(options.norm)) throw Error("hessian metric: the norm p must be positive");
  if (!(options.h_min > 0) || !(options.h_min <= options.h_max) || !std::isfinite(options.h_max))
    throw Error("hessian metric: sizes must satisfy 0 < h-min <= h-max");
  if (hessians.size() != static_cast<std::size_t>(mesh.vertex_count()))
    throw Error("hessian metric: " + std::to_string(hessians.size()) + " Hessians for " + std::to_string(mesh.vertex_count()) +
                " vertices");
  const double smallest = 1 / (options.h_max * options.h_max), largest = 1 / (options.h_min * options.h_min);
  const double exponent = -1 / (2 * options.norm + D);  // of det(|H|) in M
  std::vector<SymMat<D>> metrics(hessians.size());
  std::vector<double> densities(hessians.size());  // det(|H|)^{p/(2p+d)}
  for (std::size_t v = 0; v < hessians.size(); ++v) {
    SymEigen<D> eigen = sym_eigen(hessians[v]);
    double det = 1;
    for (int k = 0; k < D; ++k) {
      eigen.values[k] = std::clamp(std::abs(eigen.values[k]), smallest, largest);
      det *= eigen.values[k];
    }
    if (!std::isfinite(det)) throw Error("hessian metric: the Hessian at vertex " + std::to_string(v + 1) + " is not finite");
    metrics[v] = std::pow(det, exponent) * SymMat<D>::from_eigen(eigen.vectors, eigen.values);
    densities[v] = std::pow(det, options.norm / (2 * options.norm + D));
  }
  std::vector<double> volumes = vertex_volumes(mesh);
  double integral = 0;
  for (std::size_t v = 0; v < volumes.size(); ++v) integral += volumes[v] * densities[v];
  if (!(integral > 0)) throw Error("hessian metric: the mesh has no volume");
  const double scale = std::pow(options.complexity / integral, 2.0 / D);  // D_N
  for (SymMat<D>& metric : metrics) metric *= scale;
  return metrics;
}

template std::vector<double> vertex_volumes(const Mesh<2>&);
template std::vector<double> vertex_volumes(const Mesh<3>&);
template double metric_complexity<2>(std::span<const double>, std::span<const SymMat<2>>);
template double metric_complexity<3>(std::span<const double>, std::span<const SymMat<3>>);
template double metric_complexity(const Mesh<2>&, const std::vector<SymMat<2>>&);
template double metric_complexity(const Mesh<3>&, const std::vector<SymMat<3>>&);
template std::vector<SymMat<2>> lp_metric(const Mesh<2>&, const std::vector<SymMat<2>>&, const LpMetricOptions&);
template std::vector<SymMat<3>> lp_metric(const Mesh<3>&, const std::vector<SymMat<3>>&, const LpMetricOptions&);

}  // namespace hocav
