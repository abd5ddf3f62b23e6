// Vertex normals per smooth side (docs/method.md §9).
#include "surface/vertex_normals.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <numeric>

#include "surface/quadric_fit.hpp"

namespace hocav {
namespace {

// A fitted normal that turns further than this from the weighted one is a failed fit.
const double kMaxFitTurn = 30 * std::numbers::pi / 180;

// Union-find over facet corners (corner = D * facet + local vertex), path halving.
class CornerSets {
 public:
  explicit CornerSets(std::size_t count) : parent_(count) { std::iota(parent_.begin(), parent_.end(), Index{0}); }
  Index find(Index c) {
    while (parent_[c] != c) c = parent_[c] = parent_[parent_[c]];
    return c;
  }
  void unite(Index a, Index b) {
    a = find(a);
    b = find(b);
    if (a != b) parent_[std::max(a, b)] = std::min(a, b);
  }

 private:
  std::vector<Index> parent_;
};

// The contribution of facet f to the normal at its local vertex i.
template <int D>
Vec<D> weighted_facet_normal(const Mesh<D>& mesh, Index f, int i, NormalWeights weights) {
  const Vec<D> area_normal = facet_area_normal(mesh, f);
  const double measure = norm(area_normal);
  if (measure == 0 || weights == NormalWeights::kArea) return area_normal;
  const auto& facet = mesh.facet(f);
  if constexpr (D == 2) {
    return weights == NormalWeights::kMax ? area_normal * (1 / (measure * measure)) : area_normal * (1 / measure);
  } else {
    const Vec3 e1 = mesh.vertex(facet[(i + 1) % 3]) - mesh.vertex(facet[i]);
    const Vec3 e2 = mesh.vertex(facet[(i + 2) % 3]) - mesh.vertex(facet[i]);
    if (weights == NormalWeights::kMax) return area_normal * (1 / (dot(e1, e1) * dot(e2, e2)));
    const double angle = std::atan2(measure, dot(e1, e2));  // |e1 × e2| = measure
    return area_normal * (angle / measure);
  }
}

// Groups the corners by the root of their set and gives each group the unit weighted mean of its
// facets' normals (or, when they cancel out in a degenerate fold, its first facet's own normal).
template <int D>
VertexNormals<D> weighted_side_normals(const Mesh<D>& mesh, CornerSets& sets, NormalWeights weights) {
  const Index corner_count = D * mesh.facet_count();
  VertexNormals<D> result;
  result.corner_sides.resize(mesh.facet_count());
  std::vector<Index> side_of_root(static_cast<std::size_t>(corner_count), kNoIndex);
  std::vector<Index> first_facet;
  for (Index c = 0; c < corner_count; ++c) {
    const Index root = sets.find(c);
    if (side_of_root[root] == kNoIndex) {
      side_of_root[root] = static_cast<Index>(result.normals.size());
      result.normals.emplace_back();
      first_facet.push_back(c / D);
    }
    const Index side = side_of_root[root];
    result.corner_sides[c / D][c % D] = side;
    result.normals[side] += weighted_facet_normal(mesh, c / D, c % D, weights);
  }
  for (std::size_t side = 0; side < result.normals.size(); ++side) {
    Vec<D>& normal = result.normals[side];
    if (norm(normal) == 0) normal = facet_area_normal(mesh, first_facet[side]);
    normal *= 1 / norm(normal);
  }
  return result;
}

// Replaces each side's normal by the quadric fitted to its neighbourhood: the vertices of the
// side's facets and of the facets next to them on the same side (sharing a normal at a vertex of
// the side between them).
template <int D>
void fit_quadric_normals(const Mesh<D>& mesh, const SurfaceTopology<D>& topology, VertexNormals<D>& normals) {
  // The facet corners of each side, in compressed rows.
  const std::size_t side_count = normals.normals.size();
  std::vector<Index> offsets(side_count + 1, 0), corners(static_cast<std::size_t>(D) * mesh.facet_count());
  for (const auto& sides : normals.corner_sides)
    for (Index side : sides) ++offsets[side + 1];
  for (std::size_t side = 0; side < side_count; ++side) offsets[side + 1] += offsets[side];
  std::vector<Index> fill(offsets.begin(), offsets.end() - 1);
  for (Index c = 0; c < static_cast<Index>(corners.size()); ++c)
    corners[fill[normals.corner_sides[c / D][c % D]]++] = c;

  std::vector<Index> vertices;
  std::vector<Vec<D>> neighbors;
  for (std::size_t side = 0; side < side_count; ++side) {
    vertices.clear();
    const Index vertex = mesh.facet(corners[offsets[side]] / D)[corners[offsets[side]] % D];
    auto add_facet_vertices = [&](Index f) {
      for (Index v : mesh.facet(f))
        if (v != vertex) vertices.push_back(v);
    };
    for (Index k = offsets[side]; k < offsets[side + 1]; ++k) {
      const Index f = corners[k] / D;
      add_facet_vertices(f);
      for (int s = 0; s < D; ++s) {
        const Index g = topology.neighbors[f][s];
        if (g == kNoIndex) continue;
        const int i = (s + 1) % D;  // a vertex of side s
        if (normals.corner_sides[f][i] == normals.corner_sides[g][facet_local_vertex(mesh, g, mesh.facet(f)[i])])
          add_facet_vertices(g);
      }
    }
    std::sort(vertices.begin(), vertices.end());
    vertices.erase(std::unique(vertices.begin(), vertices.end()), vertices.end());
    neighbors.clear();
    for (Index v : vertices) neighbors.push_back(mesh.vertex(v));
    normals.normals[side] =
        quadric_fitted_normal<D>(mesh.vertex(vertex), neighbors, normals.normals[side], kMaxFitTurn);
  }
}

}  // namespace

template <int D>
VertexNormals<D> compute_vertex_normals(const Mesh<D>& mesh, const SurfaceTopology<D>& topology,
                                        const VertexNormalOptions<D>& options) {
  const Index facet_count = mesh.facet_count();
  const Index corner_count = checked_index(static_cast<std::size_t>(facet_count) * D, "facet corners");
  CornerSets sets(static_cast<std::size_t>(corner_count));
  // Calls visit(corner of f, corner of g) for the corners of the vertices that side s of facet f shares with g.
  auto for_shared_corners = [&mesh](Index f, int s, Index g, auto&& visit) {
    for (int i = 0; i < D; ++i)
      if (i != s) visit(D * f + i, D * g + facet_local_vertex(mesh, g, mesh.facet(f)[i]));
  };
  for (Index f = 0; f < facet_count; ++f)
    for (int s = 0; s < D; ++s)
      if (const Index g = topology.neighbors[f][s]; g != kNoIndex && !topology.ridges[f][s])
        for_shared_corners(f, s, g, [&sets](Index a, Index b) { sets.unite(a, b); });

  // Sides that meet at a ridge with nearly the same normal (a ref boundary or a tagged ridge across
  // a smooth part) share one normal, computed over both, as on any smooth part.
  const VertexNormals<D> separate = weighted_side_normals(mesh, sets, options.weights);
  const double cos_smooth_angle = std::cos(options.smooth_ridge_angle_degrees * std::numbers::pi / 180);
  for (Index f = 0; f < facet_count; ++f)
    for (int s = 0; s < D; ++s)
      if (const Index g = topology.neighbors[f][s]; g != kNoIndex && topology.ridges[f][s])
        for_shared_corners(f, s, g, [&](Index a, Index b) {
          if (dot(separate.at(a / D, a % D), separate.at(b / D, b % D)) >= cos_smooth_angle) sets.unite(a, b);
        });
  VertexNormals<D> result = weighted_side_normals(mesh, sets, options.weights);
  if (options.quadric_fit) fit_quadric_normals(mesh, topology, result);

  if (options.normal_source != nullptr) {
    const double cos_feature_angle = std::cos(options.feature_angle_degrees * std::numbers::pi / 180);
    std::vector<bool> done(result.normals.size(), false);
    for (Index c = 0; c < corner_count; ++c) {
      const Index f = c / D, side = result.corner_sides[f][c % D];
      if (done[side]) continue;
      done[side] = true;
      Vec<D>& normal = result.normals[side];
      Vec<D> given = options.normal_source->normal(mesh.vertex(mesh.facet(f)[c % D]), {.ref = mesh.facet_ref(f)});
      if (dot(given, normal) < 0) given = -given;
      if (dot(given, normal) >= cos_feature_angle * norm(given)) normal = given * (1 / norm(given));
    }
  }
  return result;
}

template VertexNormals<2> compute_vertex_normals(const Mesh<2>&, const SurfaceTopology<2>&,
                                                 const VertexNormalOptions<2>&);
template VertexNormals<3> compute_vertex_normals(const Mesh<3>&, const SurfaceTopology<3>&,
                                                 const VertexNormalOptions<3>&);

}  // namespace hocav
