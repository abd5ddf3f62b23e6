// The tags of a mesh's entities (corners, required vertices, facets and lines, ridges) as flags per
// entity, for copying them entity by entity into a part (docs/distributed.md §Parts).
#pragma once

#include <vector>

#include "mesh/mesh.hpp"

namespace hocav {

inline std::vector<char> flags_of(const std::vector<Index>& ids, Index count) {
  std::vector<char> flags(static_cast<std::size_t>(count), 0);
  for (Index id : ids)
    if (id != kNoIndex) flags[id] = 1;
  return flags;
}

// The list of required facets: the Edges keyword's in 2D, the triangles' in 3D.
template <int D>
std::vector<Index>& required_facets(Mesh<D>& mesh) {
  if constexpr (D == 2) return mesh.required_edges();
  return mesh.required_triangles();
}
template <int D>
const std::vector<Index>& required_facets(const Mesh<D>& mesh) {
  if constexpr (D == 2) return mesh.required_edges();
  return mesh.required_triangles();
}

// The tags of a mesh as flags per entity, for copying them entity by entity.
template <int D>
struct EntityTags {
  std::vector<char> corner, required_vertex, required_facet, ridge_facet, ridge_line, required_line;

  explicit EntityTags(const Mesh<D>& mesh)
      : corner(flags_of(mesh.corners(), mesh.vertex_count())),
        required_vertex(flags_of(mesh.required_vertices(), mesh.vertex_count())),
        required_facet(flags_of(required_facets(mesh), mesh.facet_count())),
        ridge_facet(D == 2 ? flags_of(mesh.ridges(), mesh.facet_count())
                           : std::vector<char>(static_cast<std::size_t>(mesh.facet_count()), 0)),
        ridge_line(D == 3 ? flags_of(mesh.ridges(), mesh.line_count()) : std::vector<char>()),
        required_line(D == 3 ? flags_of(mesh.required_edges(), mesh.line_count()) : std::vector<char>()) {}
};

// Adds facet `vertices` to `out` with the tags facet f has in `tags`.
template <int D>
void add_tagged_facet(Mesh<D>& out, const typename Mesh<D>::Facet& vertices, int ref, const EntityTags<D>& tags, Index f) {
  const Index id = out.add_facet(vertices, ref);
  if (tags.required_facet[f]) required_facets(out).push_back(id);
  if (tags.ridge_facet[f]) out.ridges().push_back(id);
}

template <int D>
void add_tagged_line(Mesh<D>& out, const typename Mesh<D>::Line& vertices, int ref, const EntityTags<D>& tags, Index l) {
  const Index id = out.add_line(vertices, ref);
  if (tags.ridge_line[l]) out.ridges().push_back(id);
  if (tags.required_line[l]) out.required_edges().push_back(id);
}

}  // namespace hocav
