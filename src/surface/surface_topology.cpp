// Facet neighbours and ridges of the boundary (docs/method.md §9).
#include "surface/surface_topology.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace hocav {
namespace {

// The key of side s of facet f: its edge's vertex pair (3D) or its vertex (2D).
template <int D>
std::uint64_t side_key(const Mesh<D>& mesh, Index f, int s) {
  const auto& facet = mesh.facet(f);
  if constexpr (D == 2)
    return static_cast<std::uint64_t>(facet[1 - s]);
  else
    return Mesh<3>::edge_key(facet[(s + 1) % 3], facet[(s + 2) % 3]);
}

// Sides the mesh tags as ridges (3D Ridges, 2D Corners), by side key.
template <int D>
IndexHashMap tagged_ridges(const Mesh<D>& mesh) {
  IndexHashMap tagged;
  if constexpr (D == 2) {
    for (Index v : mesh.corners()) tagged.insert(static_cast<std::uint64_t>(v), 0);
  } else {
    for (Index line : mesh.ridges())
      if (line >= 0 && line < mesh.line_count()) tagged.insert(Mesh<3>::edge_key(mesh.line(line)[0], mesh.line(line)[1]), 0);
  }
  return tagged;
}

}  // namespace

template <int D>
Vec<D> facet_area_normal(const Mesh<D>& mesh, Index f) {
  const auto& facet = mesh.facet(f);
  if constexpr (D == 2) {
    const Vec2 edge = mesh.vertex(facet[1]) - mesh.vertex(facet[0]);
    return {{edge[1], -edge[0]}};
  } else {
    return cross(mesh.vertex(facet[1]) - mesh.vertex(facet[0]), mesh.vertex(facet[2]) - mesh.vertex(facet[0]));
  }
}

template <int D>
int facet_local_vertex(const Mesh<D>& mesh, Index f, Index v) {
  const auto& facet = mesh.facet(f);
  for (int i = 0; i < D; ++i)
    if (facet[i] == v) return i;
  return -1;
}

template <int D>
SurfaceTopology<D> build_surface_topology(const Mesh<D>& mesh, double feature_angle_degrees) {
  const Index facet_count = mesh.facet_count();
  SurfaceTopology<D> topology;
  topology.neighbors.assign(facet_count, {});
  topology.ridges.assign(facet_count, {});
  for (auto& neighbors : topology.neighbors) neighbors.fill(kNoIndex);
  for (auto& ridges : topology.ridges) ridges.fill(true);

  // Group the sides by key; a group of exactly two sides joins two facets.
  struct Side {
    std::uint64_t key;
    Index facet;
    int side;
  };
  std::vector<Side> sides;
  sides.reserve(static_cast<std::size_t>(facet_count) * D);
  for (Index f = 0; f < facet_count; ++f)
    for (int s = 0; s < D; ++s) sides.push_back({side_key(mesh, f, s), f, s});
  std::sort(sides.begin(), sides.end(), [](const Side& a, const Side& b) { return a.key < b.key; });

  const IndexHashMap tagged = tagged_ridges(mesh);
  const double cos_feature_angle = std::cos(feature_angle_degrees * std::numbers::pi / 180);
  for (std::size_t first = 0; first < sides.size();) {
    std::size_t end = first + 1;
    while (end < sides.size() && sides[end].key == sides[first].key) ++end;
    if (end - first == 2) {
      const Side &a = sides[first], &b = sides[first + 1];
      topology.neighbors[a.facet][a.side] = b.facet;
      topology.neighbors[b.facet][b.side] = a.facet;
      const Vec<D> normal_a = facet_area_normal(mesh, a.facet), normal_b = facet_area_normal(mesh, b.facet);
      const double lengths = norm(normal_a) * norm(normal_b);
      const bool folds = lengths > 0 && dot(normal_a, normal_b) < cos_feature_angle * lengths;
      const bool ridge = folds || mesh.facet_ref(a.facet) != mesh.facet_ref(b.facet) || tagged.find(a.key) != kNoIndex;
      topology.ridges[a.facet][a.side] = topology.ridges[b.facet][b.side] = ridge;
    }
    first = end;
  }
  return topology;
}

template SurfaceTopology<2> build_surface_topology(const Mesh<2>&, double);
template SurfaceTopology<3> build_surface_topology(const Mesh<3>&, double);
template Vec2 facet_area_normal(const Mesh<2>&, Index);
template Vec3 facet_area_normal(const Mesh<3>&, Index);
template int facet_local_vertex(const Mesh<2>&, Index, Index);
template int facet_local_vertex(const Mesh<3>&, Index, Index);

}  // namespace hocav
