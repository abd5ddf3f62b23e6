#include "metric/hessian_recovery.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

#include "base/error.hpp"
#include "mesh/vertex_graph.hpp"

namespace hocav {
namespace {

// min |A x − b| for a full-rank m×n A (column-major, m ≥ n), by Householder QR with the columns
// scaled to unit length first. Returns false when a column is (numerically) dependent on the others.
bool solve_least_squares(std::vector<double>& a, std::vector<double>& b, int rows, int columns, std::span<double> x) {
  auto at = [&a, rows](int i, int j) -> double& { return a[static_cast<std::size_t>(j * rows + i)]; };
  std::vector<double> column_scale(static_cast<std::size_t>(columns));
  for (int j = 0; j < columns; ++j) {
    double length = 0;
    for (int i = 0; i < rows; ++i) length += at(i, j) * at(i, j);
    length = std::sqrt(length);
    if (length == 0) return false;
    column_scale[static_cast<std::size_t>(j)] = 1 / length;
    for (int i = 0; i < rows; ++i) at(i, j) /= length;
  }
  for (int k = 0; k < columns; ++k) {
    double length = 0;
    for (int i = k; i < rows; ++i) length += at(i, k) * at(i, k);
    length = std::sqrt(length);
    // Unit columns: a pivot this small means column k lies (almost) in the span of the previous ones.
    if (length < 1e-8) return false;
    double alpha = at(k, k) > 0 ? -length : length;
    at(k, k) -= alpha;  // the Householder vector is column k below the diagonal, with this head
    double vector_norm2 = 0;
    for (int i = k; i < rows; ++i) vector_norm2 += at(i, k) * at(i, k);
    auto reflect = [&](auto&& entry) {
      double projection = 0;
      for (int i = k; i < rows; ++i) projection += at(i, k) * entry(i);
      projection *= 2 / vector_norm2;
      for (int i = k; i < rows; ++i) entry(i) -= projection * at(i, k);
    };
    for (int j = k + 1; j < columns; ++j) reflect([&](int i) -> double& { return at(i, j); });
    reflect([&](int i) -> double& { return b[static_cast<std::size_t>(i)]; });
    at(k, k) = alpha;  // R's diagonal; the part below it is no longer needed
  }
  for (int k = columns - 1; k >= 0; --k) {
    double value = b[static_cast<std::size_t>(k)];
    for (int j = k + 1; j < columns; ++j) value -= at(k, j) * x[static_cast<std::size_t>(j)];
    x[static_cast<std::size_t>(k)] = value / at(k, k);
  }
  for (int j = 0; j < columns; ++j) x[static_cast<std::size_t>(j)] *= column_scale[static_cast<std::size_t>(j)];
  return true;
}

// The vertices within `rings` edges of v (v excluded), appended to `stencil`; `mark` is kNoIndex
// everywhere before and after, and v while the call collects. (Marks left from a call for fewer
// rings of the same v would hide the inner rings from the outer ones: until the fifty-fifth
// session no 3-ring fit ever succeeded.)
void collect_rings(const VertexGraph& graph, Index v, int rings, std::vector<Index>& stencil, std::vector<Index>& mark) {
  stencil.clear();
  mark[static_cast<std::size_t>(v)] = v;
  std::size_t ring_begin = 0;
  for (Index u : graph.neighbors_of(v)) {
    mark[static_cast<std::size_t>(u)] = v;
    stencil.push_back(u);
  }
  for (int ring = 2; ring <= rings; ++ring) {
    std::size_t ring_end = stencil.size();
    for (std::size_t s = ring_begin; s < ring_end; ++s)
      for (Index u : graph.neighbors_of(stencil[s]))
        if (mark[static_cast<std::size_t>(u)] != v) {
          mark[static_cast<std::size_t>(u)] = v;
          stencil.push_back(u);
        }
    ring_begin = ring_end;
  }
  mark[static_cast<std::size_t>(v)] = kNoIndex;
  for (Index u : stencil) mark[static_cast<std::size_t>(u)] = kNoIndex;
}

}  // namespace

template <int D>
std::optional<SymMat<D>> fit_hessian(const Vec<D>& point, double value, std::span<const Vec<D>> stencil_points,
                                     std::span<const double> stencil_values) {
  constexpr int kUnknowns = D + SymMat<D>::kEntryCount;  // g, then H
  const int rows = static_cast<int>(stencil_points.size());
  if (rows < kUnknowns) return std::nullopt;
  // Offsets scaled by the stencil's radius, so every column is of order one.
  double radius = 0;
  for (const Vec<D>& x : stencil_points) radius = std::max(radius, norm(x - point));
  if (!(radius > 0)) return std::nullopt;
  std::vector<double> matrix(static_cast<std::size_t>(rows * kUnknowns), 0.0), right(static_cast<std::size_t>(rows));
  for (int row = 0; row < rows; ++row) {
    Vec<D> d = (1 / radius) * (stencil_points[static_cast<std::size_t>(row)] - point);
    auto entry = [&](int column) -> double& { return matrix[static_cast<std::size_t>(column * rows + row)]; };
    for (int i = 0; i < D; ++i) entry(i) = d[i];
    // ½ dᵀHd = Σ_i ½ H_ii d_i² + Σ_{i>j} H_ij d_i d_j, columns in the SymMat entry order.
    for (int i = 0; i < D; ++i)
      for (int j = 0; j <= i; ++j) entry(D + SymMat<D>::index(i, j)) = (i == j ? 0.5 : 1.0) * d[i] * d[j];
    right[static_cast<std::size_t>(row)] = stencil_values[static_cast<std::size_t>(row)] - value;
  }
  std::array<double, kUnknowns> solution{};
  if (!solve_least_squares(matrix, right, rows, kUnknowns, solution)) return std::nullopt;
  SymMat<D> hessian;
  for (int e = 0; e < SymMat<D>::kEntryCount; ++e)
    hessian.entries[static_cast<std::size_t>(e)] = solution[static_cast<std::size_t>(D + e)] / (radius * radius);
  return hessian;
}

template <int D>
std::vector<SymMat<D>> recover_hessians(const Mesh<D>& mesh, std::span<const double> vertex_values) {
  if (vertex_values.size() != static_cast<std::size_t>(mesh.vertex_count()))
    throw Error("hessian recovery: " + std::to_string(vertex_values.size()) + " values for " + std::to_string(mesh.vertex_count()) +
                " vertices");
  const VertexGraph graph = vertex_graph(mesh);
  std::vector<SymMat<D>> hessians(vertex_values.size());
  std::vector<Index> stencil, mark(vertex_values.size(), kNoIndex);
  std::vector<Vec<D>> points;
  std::vector<double> values;
  for (Index v = 0; v < mesh.vertex_count(); ++v) {
    std::optional<SymMat<D>> fitted;
    for (int rings = 1; rings <= kHessianMaxRings && !fitted; ++rings) {
      collect_rings(graph, v, rings, stencil, mark);
      points.clear();
      values.clear();
      for (Index u : stencil) {
        points.push_back(mesh.vertex(u));
        values.push_back(vertex_values[static_cast<std::size_t>(u)]);
      }
      fitted = fit_hessian<D>(mesh.vertex(v), vertex_values[static_cast<std::size_t>(v)], points, values);
    }
    if (!fitted)
      throw Error("hessian recovery: the neighbours of vertex " + one_based(v) + " within " + std::to_string(kHessianMaxRings) +
                  " edges do not determine a quadratic");
    hessians[static_cast<std::size_t>(v)] = *fitted;
  }
  return hessians;
}

template std::optional<SymMat<2>> fit_hessian(const Vec<2>&, double, std::span<const Vec<2>>, std::span<const double>);
template std::optional<SymMat<3>> fit_hessian(const Vec<3>&, double, std::span<const Vec<3>>, std::span<const double>);
template std::vector<SymMat<2>> recover_hessians(const Mesh<2>&, std::span<const double>);
template std::vector<SymMat<3>> recover_hessians(const Mesh<3>&, std::span<const double>);

}  // namespace hocav
