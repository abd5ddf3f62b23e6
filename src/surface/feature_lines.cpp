// Feature line tangents (docs/surface.md, "Feature lines").
#include "surface/feature_lines.hpp"

#include <array>

namespace hocav {
namespace {

// The vertices joined to each vertex by an edge whose two facets are on different sides there.
std::vector<std::vector<Index>> feature_neighbours(const Mesh<3>& mesh, const SurfaceTopology<3>& topology,
                                                   const VertexNormals<3>& normals) {
  std::vector<std::vector<Index>> neighbours(static_cast<std::size_t>(mesh.vertex_count()));
  for (Index f = 0; f < mesh.facet_count(); ++f)
    for (int s = 0; s < 3; ++s) {
      const Index g = topology.neighbors[f][s];
      if (g == kNoIndex || g < f) continue;  // each edge once
      const std::array<int, 2> ends{(s + 1) % 3, (s + 2) % 3};
      for (int k = 0; k < 2; ++k) {
        const Index vertex = mesh.facet(f)[ends[k]], other = mesh.facet(f)[ends[1 - k]];
        if (normals.corner_sides[f][ends[k]] != normals.corner_sides[g][facet_local_vertex(mesh, g, vertex)])
          neighbours[vertex].push_back(other);
      }
    }
  return neighbours;
}

// The tangent at x of the circle through p, x, q (the line when they are aligned): for a circle,
// |p − x|² (q − x) − |q − x|² (p − x) is parallel to it.
Vec3 circle_tangent(const Vec3& p, const Vec3& x, const Vec3& q) {
  const Vec3 to_p = p - x, to_q = q - x;
  return dot(to_p, to_p) * to_q - dot(to_q, to_q) * to_p;
}

}  // namespace

template <int D>
std::vector<Vec<D>> feature_line_tangents(const Mesh<D>& mesh, [[maybe_unused]] const SurfaceTopology<D>& topology,
                                          [[maybe_unused]] VertexNormals<D>& normals) {
  std::vector<Vec<D>> tangents(static_cast<std::size_t>(mesh.vertex_count()), Vec<D>{});
  if constexpr (D == 3) {
    const auto neighbours = feature_neighbours(mesh, topology, normals);
    for (Index v = 0; v < mesh.vertex_count(); ++v) {
      if (neighbours[v].size() != 2) continue;
      const Vec3 tangent = circle_tangent(mesh.vertex(neighbours[v][0]), mesh.vertex(v), mesh.vertex(neighbours[v][1]));
      if (norm(tangent) > 0) tangents[v] = tangent * (1 / norm(tangent));
    }
    for (Index f = 0; f < mesh.facet_count(); ++f)
      for (int i = 0; i < 3; ++i) {
        const Vec3& tangent = tangents[mesh.facet(f)[i]];
        Vec3& normal = normals.normals[normals.corner_sides[f][i]];
        const Vec3 orthogonal = normal - dot(normal, tangent) * tangent;
        if (norm(orthogonal) > 0) normal = orthogonal * (1 / norm(orthogonal));
      }
  }
  return tangents;
}

template std::vector<Vec2> feature_line_tangents(const Mesh<2>&, const SurfaceTopology<2>&, VertexNormals<2>&);
template std::vector<Vec3> feature_line_tangents(const Mesh<3>&, const SurfaceTopology<3>&, VertexNormals<3>&);

}  // namespace hocav
