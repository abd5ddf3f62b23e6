#include "adapt/vertex_classes.hpp"

#include <algorithm>
#include <array>
#include <unordered_map>
#include <unordered_set>

#include "surface/surface_topology.hpp"

namespace hocav {
namespace {

void tag_corner(std::vector<Index>& corners, std::vector<VertexClass>& classes, Index v) {
  if (classes[v] == VertexClass::kCorner) return;
  classes[v] = VertexClass::kCorner;
  if (std::find(corners.begin(), corners.end(), v) == corners.end()) corners.push_back(v);
}

// 3D: every ridge side becomes a tagged feature line, of the smallest ref of the facets along it
// (whatever their order: a mesh read in pieces gathers its boundary in another); a vertex with two
// line edges is a ridge vertex, with one or more than two a corner.
void classify_features(Mesh<3>& mesh, const SurfaceTopology<3>& surface, std::vector<VertexClass>& classes) {
  std::unordered_set<std::uint64_t> lines;
  for (Index l = 0; l < mesh.line_count(); ++l) lines.insert(Mesh<3>::edge_key(mesh.line(l)[0], mesh.line(l)[1]));
  std::vector<std::pair<Mesh<3>::Line, int>> found;      // the new lines with their refs, in the facets' order
  std::unordered_map<std::uint64_t, std::size_t> place;  // per new line's edge key, its place in `found`
  for (Index f = 0; f < mesh.facet_count(); ++f)
    for (int side = 0; side < 3; ++side) {
      if (!surface.ridges[f][side]) continue;
      const Index a = mesh.facet(f)[(side + 1) % 3], b = mesh.facet(f)[(side + 2) % 3];
      const std::uint64_t key = Mesh<3>::edge_key(a, b);
      if (lines.contains(key)) continue;
      if (const auto [at, added] = place.try_emplace(key, found.size()); added)
        found.push_back({{a, b}, mesh.facet_ref(f)});
      else
        found[at->second].second = std::min(found[at->second].second, mesh.facet_ref(f));
    }
  for (const auto& [ends, ref] : found) mesh.ridges().push_back(mesh.add_line(ends, ref));
  std::vector<int> line_edges(static_cast<std::size_t>(mesh.vertex_count()), 0);
  for (Index l = 0; l < mesh.line_count(); ++l)
    for (Index v : mesh.line(l)) ++line_edges[v];
  for (Index v = 0; v < mesh.vertex_count(); ++v) {
    if (line_edges[v] == 2 && classes[v] != VertexClass::kCorner)
      classes[v] = VertexClass::kRidge;
    else if (line_edges[v] > 0)
      tag_corner(mesh.corners(), classes, v);
  }
}

// 2D: a ridge side of a boundary edge is a vertex: a corner.
void classify_features(Mesh<2>& mesh, const SurfaceTopology<2>& surface, std::vector<VertexClass>& classes) {
  for (Index f = 0; f < mesh.facet_count(); ++f)
    for (int side = 0; side < 2; ++side)
      if (surface.ridges[f][side]) tag_corner(mesh.corners(), classes, mesh.facet(f)[1 - side]);
}

}  // namespace

template <int D>
std::vector<VertexClass> classify_vertices(Mesh<D>& mesh, double feature_angle_degrees, const NonManifoldPlaces& places) {
  std::vector<VertexClass> classes(static_cast<std::size_t>(mesh.vertex_count()), VertexClass::kInterior);
  for (const auto& facet : mesh.facets())
    for (Index v : facet) classes[v] = VertexClass::kSurface;
  for (Index v : mesh.corners()) classes[v] = VertexClass::kCorner;
  for (Index v : mesh.required_vertices()) classes[v] = VertexClass::kCorner;
  classify_features(mesh, build_surface_topology(mesh, feature_angle_degrees), classes);
  // Required edges and triangles keep their vertices; split_long_edges keeps their edges.
  for (Index e : mesh.required_edges()) {
    const std::array<Index, 2> ends = D == 2 ? std::array<Index, 2>{mesh.facet(e)[0], mesh.facet(e)[D - 1]} : mesh.line(e);
    for (Index v : ends) classes[v] = VertexClass::kCorner;
  }
  for (Index f : mesh.required_triangles())
    for (Index v : mesh.facet(f)) classes[v] = VertexClass::kCorner;
  for (Index v : places.every_vertex()) tag_corner(mesh.corners(), classes, v);
  return classes;
}

template <int D>
std::vector<VertexClass> classify_vertices(Mesh<D>& mesh, double feature_angle_degrees) {
  return classify_vertices(mesh, feature_angle_degrees, non_manifold_places(mesh));
}

template std::vector<VertexClass> classify_vertices(Mesh<2>&, double, const NonManifoldPlaces&);
template std::vector<VertexClass> classify_vertices(Mesh<3>&, double, const NonManifoldPlaces&);
template std::vector<VertexClass> classify_vertices(Mesh<2>&, double);
template std::vector<VertexClass> classify_vertices(Mesh<3>&, double);

}  // namespace hocav
