// Default ridge projection and edge proposal of every boundary geometry (docs/method.md §9).
#include "surface/boundary_geometry.hpp"

#include <algorithm>
#include <cmath>

namespace hocav {
namespace {

constexpr int kMaxAlternations = 100;
constexpr double kRelativeTolerance = 1e-14;

}  // namespace

template <int D>
Vec<D> BoundaryGeometry<D>::project_on_intersection(const Vec<D>& x, int ref_a, int ref_b) const {
  Vec<D> point = x;
  double scale = 1;
  for (int i = 0; i < D; ++i) scale = std::max(scale, std::abs(x[i]));
  for (int alternation = 0; alternation < kMaxAlternations; ++alternation) {
    const Vec<D> next = project(project(point, {.ref = ref_a}).point, {.ref = ref_b}).point;
    const double change = norm(next - point);
    point = next;
    if (change <= kRelativeTolerance * scale) break;
  }
  return point;
}

template <int D>
Vec<D> BoundaryGeometry<D>::project_on_ridge(const Vec<D>& x, int ref_a, int ref_b) const {
  if (ref_a != ref_b) return project_on_intersection(x, ref_a, ref_b);
  return project(x, {.ref = ref_a}).point;
}

template <int D>
Vec<D> BoundaryGeometry<D>::propose_edge_node(const BoundaryEdge<D>& edge) const {
  if (edge.refs[0] != edge.refs[1]) return project_on_intersection(edge.node, edge.refs[0], edge.refs[1]);
  return project(edge.node, {.ref = edge.refs[0]}).point;
}

template class BoundaryGeometry<2>;
template class BoundaryGeometry<3>;

}  // namespace hocav
