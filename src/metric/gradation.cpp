#include "metric/gradation.hpp"

#include <cmath>
#include <deque>
#include <string>

#include "base/error.hpp"
#include "geom/metric_intersection.hpp"
#include "geom/sym_eigen.hpp"
#include "geom/sym_functions.hpp"
#include "mesh/vertex_graph.hpp"

namespace hocav {

double gradation_factor(double length, double growth) {
  double scale = 1 + length * std::log(growth);
  return 1 / (scale * scale);
}

template <int D>
double largest_relative_eigenvalue(const SymMat<D>& a, const SymMat<D>& b) {
  // B = L Lᵀ (Cholesky); the eigenvalues of L⁻¹ A L⁻ᵀ are those of B^{-1/2} A B^{-1/2}.
  Mat<D> lower;
  for (int j = 0; j < D; ++j) {
    double pivot = b(j, j);
    for (int k = 0; k < j; ++k) pivot -= lower(j, k) * lower(j, k);
    if (!(pivot > 0)) throw Error("gradation: a metric is not positive definite");
    lower(j, j) = std::sqrt(pivot);
    for (int i = j + 1; i < D; ++i) {
      double entry = b(i, j);
      for (int k = 0; k < j; ++k) entry -= lower(i, k) * lower(j, k);
      lower(i, j) = entry / lower(j, j);
    }
  }
  // X = L⁻¹ A by forward substitution, column by column; then C = L⁻¹ Xᵀ, symmetric since A is.
  auto solve_lower = [&lower](const Mat<D>& right) {
    Mat<D> x;
    for (int column = 0; column < D; ++column)
      for (int i = 0; i < D; ++i) {
        double entry = right(i, column);
        for (int k = 0; k < i; ++k) entry -= lower(i, k) * x(k, column);
        x(i, column) = entry / lower(i, i);
      }
    return x;
  };
  Mat<D> full_a;
  for (int i = 0; i < D; ++i)
    for (int j = 0; j < D; ++j) full_a(i, j) = a(i, j);
  Mat<D> reduced = solve_lower(transpose(solve_lower(full_a)));
  SymMat<D> symmetric;
  for (int i = 0; i < D; ++i)
    for (int j = 0; j <= i; ++j) symmetric(i, j) = 0.5 * (reduced(i, j) + reduced(j, i));
  return sym_eigen(symmetric).values[D - 1];
}

template <int D>
GradationReport grade_metrics(const Mesh<D>& mesh, std::vector<SymMat<D>>& metrics, const GradationOptions& options) {
  if (!(options.growth > 1) || !std::isfinite(options.growth)) throw Error("gradation: the growth factor must be > 1");
  if (!(options.tolerance >= 0)) throw Error("gradation: the tolerance must be >= 0");
  if (metrics.size() != static_cast<std::size_t>(mesh.vertex_count()))
    throw Error("gradation: " + std::to_string(metrics.size()) + " metrics for " + std::to_string(mesh.vertex_count()) + " vertices");
  for (std::size_t v = 0; v < metrics.size(); ++v)
    if (!is_spd(metrics[v])) throw Error("gradation: the metric at vertex " + one_based(v) + " is not positive definite");

  const VertexGraph graph = vertex_graph(mesh);
  const double update_limit = 1000.0 * static_cast<double>(metrics.size());
  GradationReport report;
  // Every vertex spreads its metric once; a vertex whose metric grows spreads it again.
  std::deque<Index> queue;
  std::vector<bool> queued(metrics.size(), true);
  for (Index v = 0; v < mesh.vertex_count(); ++v) queue.push_back(v);
  while (!queue.empty()) {
    Index p = queue.front();
    queue.pop_front();
    queued[static_cast<std::size_t>(p)] = false;
    for (Index q : graph.neighbors_of(p)) {
      const SymMat<D>& source = metrics[static_cast<std::size_t>(p)];
      SymMat<D>& target = metrics[static_cast<std::size_t>(q)];
      double length = std::sqrt(quadratic_form(source, mesh.vertex(q) - mesh.vertex(p)));
      SymMat<D> grown = gradation_factor(length, options.growth) * source;
      if (largest_relative_eigenvalue(grown, target) <= 1 + options.tolerance) continue;
      target = intersect_metrics(target, grown);
      if (++report.updates > update_limit) throw Error("gradation: no fixed point after " + std::to_string(report.updates) + " updates");
      if (!queued[static_cast<std::size_t>(q)]) {
        queued[static_cast<std::size_t>(q)] = true;
        queue.push_back(q);
      }
    }
  }
  return report;
}

template double largest_relative_eigenvalue(const SymMat<2>&, const SymMat<2>&);
template double largest_relative_eigenvalue(const SymMat<3>&, const SymMat<3>&);
template GradationReport grade_metrics(const Mesh<2>&, std::vector<SymMat<2>>&, const GradationOptions&);
template GradationReport grade_metrics(const Mesh<3>&, std::vector<SymMat<3>>&, const GradationOptions&);

}  // namespace hocav
