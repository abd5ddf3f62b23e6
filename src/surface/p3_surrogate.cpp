// The P3 surrogate of the boundary: construction and projection (docs/method.md §9).
#include "surface/p3_surrogate.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "base/error.hpp"

namespace hocav {
namespace {

// Ridge sides whose normals are this close to parallel have no ridge tangent; their mean normal
// serves both (sides closer than the smooth-ridge angle are merged, so this is a degenerate case).
constexpr double kMinRidgeSine = 1e-6;
// Patches a hinted search may walk through before it falls back to the tree.
constexpr int kMaxWalk = 8;

template <int D>
Vec<D> unit(const Vec<D>& v) {
  return v * (1 / norm(v));
}

// The edge curves of the feature edges: their facets' refs differ, or their sides do at an end.
RidgeCurves ridge_curves_of(const Mesh<3>& mesh, const std::vector<CubicPatch<3>>& patches, const SurfaceTopology<3>& topology,
                            const VertexNormals<3>& normals) {
  std::vector<CubicCurve> curves;
  std::vector<std::array<int, 2>> refs;
  for (Index f = 0; f < mesh.facet_count(); ++f)
    for (int s = 0; s < 3; ++s) {
      const Index g = topology.neighbors[f][s];
      if (g == kNoIndex || g < f) continue;  // each edge once
      const int e = (s + 1) % 3;             // the patch edge opposite local vertex s
      const Index first = mesh.facet(f)[kPatchEdges<3>[e][0]], second = mesh.facet(f)[kPatchEdges<3>[e][1]];
      auto sides_differ = [&](Index v) {
        return normals.corner_sides[f][facet_local_vertex(mesh, f, v)] != normals.corner_sides[g][facet_local_vertex(mesh, g, v)];
      };
      if (mesh.facet_ref(f) == mesh.facet_ref(g) && !sides_differ(first) && !sides_differ(second)) continue;
      const CubicPatch<3>& patch = patches[f];
      curves.push_back({mesh.vertex(first), patch.edge_point(e, 0), patch.edge_point(e, 1), mesh.vertex(second)});
      refs.push_back({mesh.facet_ref(f), mesh.facet_ref(g)});
    }
  return RidgeCurves(std::move(curves), std::move(refs));
}

}  // namespace

template <int D>
P3Surrogate<D>::P3Surrogate(const Mesh<D>& mesh, const SurrogateOptions<D>& options)
    : topology_(build_surface_topology(mesh, options.normals.feature_angle_degrees)),
      normals_(compute_vertex_normals(mesh, topology_, options.normals)),
      lines_(find_feature_lines(mesh, topology_, normals_)) {
  const Index count = mesh.facet_count();
  patches_.resize(count);
  refs_.resize(count);
  boxes_.resize(count);
  edge_patches_.reserve(static_cast<std::size_t>(count) * CubicPatch<D>::kEdges);
  for (Index f = 0; f < count; ++f) {
    build_patch(mesh, f, options.tangent_length);
    refs_[f] = mesh.facet_ref(f);
    boxes_[f] = Box<D>::empty();
    for (const Vec<D>& point : patches_[f].control) boxes_[f].add(point);
    for (int e = 0; e < CubicPatch<D>::kEdges; ++e) {
      const auto& ends = kPatchEdges<D>[e];
      edge_patches_.insert(Mesh<D>::edge_key(mesh.facet(f)[ends[0]], mesh.facet(f)[ends[1]]), CubicPatch<D>::kEdges * f + e);
    }
  }
  tree_ = PatchTree<D>(boxes_);
  if constexpr (D == 3) ridge_curves_ = ridge_curves_of(mesh, patches_, topology_, normals_);
}

template <int D>
std::optional<Vec<D>> P3Surrogate<D>::closest_on_ridges(const Vec<D>& x, int ref_a, int ref_b) const {
  if constexpr (D == 3)
    return ridge_curves_.closest(x, ref_a, ref_b);
  else
    return std::nullopt;
}

template <int D>
Vec<D> P3Surrogate<D>::project_on_intersection(const Vec<D>& x, int ref_a, int ref_b) const {
  if (std::optional<Vec<D>> point = closest_on_ridges(x, ref_a, ref_b)) return *point;
  return BoundaryGeometry<D>::project_on_intersection(x, ref_a, ref_b);
}

template <int D>
Vec<D> P3Surrogate<D>::project_on_ridge(const Vec<D>& x, int ref_a, int ref_b) const {
  if (std::optional<Vec<D>> point = closest_on_ridges(x, ref_a, ref_b)) return *point;
  return BoundaryGeometry<D>::project_on_ridge(x, ref_a, ref_b);
}

template <int D>
void P3Surrogate<D>::build_patch(const Mesh<D>& mesh, Index f, TangentLength tangent_length) {
  const auto& facet = mesh.facet(f);
  CubicPatch<D>& patch = patches_[f];
  for (int i = 0; i < D; ++i) patch.control[i] = mesh.vertex(facet[i]);
  // The unit tangent of the patch edge from local vertex i toward local vertex j, at P_i.
  auto edge_tangent = [&](int i, int j) {
    const Vec<D>& from = patch.vertex(i);
    const Vec<D>& to = patch.vertex(j);
    const Vec<D>& normal = normals_.at(f, i);
    if constexpr (D == 3) {
      const Index neighbor = topology_.neighbors[f][3 - i - j];
      if (neighbor == kNoIndex) return unit(to - from);
      const int local_in_neighbor = facet_local_vertex(mesh, neighbor, facet[i]);
      if (normals_.corner_sides[neighbor][local_in_neighbor] != normals_.corner_sides[f][i]) {
        // A ridge: the curve follows its feature line where one passes through (feature_lines.hpp),
        // its own branch at an input corner, else (a corner) n_A × n_B, in both sides' tangent planes.
        const Vec3& feature_tangent = lines_.tangents[facet[i]];
        if (norm(feature_tangent) > 0) return tangent_on_line(from, to, feature_tangent);
        const Vec3& other_normal = normals_.at(neighbor, local_in_neighbor);
        const Vec3 ridge = cross(normal, other_normal);
        if (lines_.input_corners[facet[i]] && (lines_.turns[facet[i]] || norm(ridge) <= kSharpRidgeSine))
          return branch_tangent(mesh, lines_, facet[i], facet[j]);
        if (norm(ridge) > kMinRidgeSine) return tangent_on_line(from, to, unit(ridge));
        return tangent_in_plane(from, to, unit(normal + other_normal));
      }
    }
    return tangent_in_plane(from, to, normal);
  };
  for (int e = 0; e < CubicPatch<D>::kEdges; ++e) {
    const auto& [i, j] = kPatchEdges<D>[e];
    patch.edge_point(e, 0) = edge_control_point(patch.vertex(i), patch.vertex(j), edge_tangent(i, j), tangent_length);
    patch.edge_point(e, 1) = edge_control_point(patch.vertex(j), patch.vertex(i), edge_tangent(j, i), tangent_length);
  }
  if constexpr (D == 3) place_centre_control_point(patch);
}

template <int D>
std::optional<typename P3Surrogate<D>::Closest> P3Surrogate<D>::walk_from(Index patch, const Vec<D>& x,
                                                                          const ProjectionQuery& query) const {
  auto allowed = [&](Index p) { return !query.ref || refs_[p] == *query.ref; };
  if (!allowed(patch)) return std::nullopt;
  std::array<Index, kMaxWalk> visited{};
  std::optional<Closest> best;
  for (int step = 0; step < kMaxWalk; ++step) {
    visited[step] = patch;
    const PatchClosestPoint<D> on_patch = closest_point_on_patch(patches_[patch], x);
    if (!best || on_patch.distance2 < best->on_patch.distance2) best = Closest{patch, on_patch};
    const auto lambda = on_patch.barycentrics();
    const auto is_on_side = [](double l) { return l <= kOnPatchSide; };
    const auto side_count = std::count_if(lambda.begin(), lambda.end(), is_on_side);
    if (side_count > 1) return std::nullopt;  // at a vertex: which patch is next is not a single choice
    bool local_minimum = true;
    if (side_count == 1) {
      // Clamped to one side: go across it, unless nothing (allowed) is there or we came from there.
      const auto side = std::find_if(lambda.begin(), lambda.end(), is_on_side) - lambda.begin();
      const Index next = topology_.neighbors[patch][side];
      const auto walked_end = visited.begin() + step + 1;
      local_minimum = next == kNoIndex || !allowed(next) || std::find(visited.begin(), walked_end, next) != walked_end;
      patch = next;
    }
    if (local_minimum) {
      // A local minimum is the closest point for points near the surface; farther points use the tree.
      const Box<D>& box = boxes_[best->patch];
      const Vec<D> diagonal = box.upper - box.lower;
      if (best->on_patch.distance2 > dot(diagonal, diagonal)) return std::nullopt;
      return best;
    }
  }
  return std::nullopt;
}

template <int D>
typename P3Surrogate<D>::Closest P3Surrogate<D>::closest(const Vec<D>& x, const ProjectionQuery& query) const {
  if (query.hint >= 0 && query.hint < patch_count())
    if (std::optional<Closest> walked = walk_from(query.hint, x, query)) return *walked;
  Closest best;
  best.on_patch.distance2 = std::numeric_limits<double>::infinity();
  tree_.nearest(x, [&](Index p, double best2) {
    if ((query.ref && refs_[p] != *query.ref) || boxes_[p].distance2(x) >= best2) return std::numeric_limits<double>::infinity();
    const PatchClosestPoint<D> on_patch = closest_point_on_patch(patches_[p], x);
    if (on_patch.distance2 < best.on_patch.distance2) best = {p, on_patch};
    return on_patch.distance2;
  });
  if (best.patch == kNoIndex)
    throw Error(query.ref ? "the boundary surrogate has no patch with ref " + std::to_string(*query.ref)
                          : std::string("the boundary surrogate has no patch"));
  return best;
}

template <int D>
BoundaryPoint<D> P3Surrogate<D>::project(const Vec<D>& x, const ProjectionQuery& query) const {
  const Closest found = closest(x, query);
  return {found.on_patch.point, std::sqrt(found.on_patch.distance2), found.patch, refs_[found.patch]};
}

template <int D>
Vec<D> P3Surrogate<D>::normal(const Vec<D>& x, const ProjectionQuery& query) const {
  const Closest found = closest(x, query);
  const PatchJet<D> jet = evaluate_jet(patches_[found.patch], found.on_patch.parameters);
  if constexpr (D == 2)
    return unit(Vec2{{jet.first[0][1], -jet.first[0][0]}});
  else
    return unit(cross(jet.first[0], jet.first[1]));
}

template <int D>
std::optional<Vec<D>> P3Surrogate<D>::edge_midpoint(Index a, Index b) const {
  const Index id = edge_patches_.find(Mesh<D>::edge_key(a, b));
  if (id == kNoIndex) return std::nullopt;
  return edge_curve_midpoint(patches_[id / CubicPatch<D>::kEdges], id % CubicPatch<D>::kEdges);
}

template <int D>
Vec<D> P3Surrogate<D>::propose_edge_node(const BoundaryEdge<D>& edge) const {
  if (std::optional<Vec<D>> midpoint = edge_midpoint(edge.a, edge.b)) return *midpoint;
  return BoundaryGeometry<D>::propose_edge_node(edge);
}

template class P3Surrogate<2>;
template class P3Surrogate<3>;

}  // namespace hocav
