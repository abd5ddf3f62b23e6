#include "parallel/part_message.hpp"

#include <cstring>
#include <span>
#include <type_traits>

#include "base/error.hpp"
#include "parallel/byte_stream.hpp"

namespace hocav {
namespace {

template <typename T>
std::span<const T> view(const std::vector<T>& values) {
  return values;
}

// Calls visit(edge) for each edge of a P2 mesh once, in the order of the elements and their local
// edges: an order both ends of a message know, whatever the ids of the edge table.
template <int D, typename Visit>
void for_each_element_edge_once(const Mesh<D>& mesh, Visit&& visit) {
  std::vector<char> seen(static_cast<std::size_t>(mesh.edge_count()), 0);
  for (Index k = 0; k < mesh.element_count(); ++k)
    for (Index edge : mesh.element_edges(k))
      if (!seen[edge]) {
        seen[edge] = 1;
        visit(edge);
      }
}

// The P2 nodes, one per element edge (none for a P1 mesh).
template <int D>
std::vector<Vec<D>> edge_nodes_of(const Mesh<D>& mesh) {
  std::vector<Vec<D>> nodes;
  if (mesh.is_p2()) for_each_element_edge_once(mesh, [&](Index edge) { nodes.push_back(mesh.edge_node(edge)); });
  return nodes;
}

template <int D>
void set_edge_nodes(Mesh<D>& mesh, const std::vector<Vec<D>>& nodes) {
  if (nodes.empty()) return;
  mesh.make_p2();
  std::size_t next = 0;
  for_each_element_edge_once(mesh, [&](Index edge) {
    if (next == nodes.size()) throw Error("a mesh part message has fewer P2 nodes than edges");
    mesh.edge_node(edge) = nodes[next++];
  });
  if (next != nodes.size()) throw Error("a mesh part message has more P2 nodes than edges");
}

}  // namespace

template <int D>
std::vector<std::byte> pack_part(const Mesh<D>& mesh, std::span<const Index> global_ids) {
  ByteWriter out;
  const int dimension = D;
  out.put(std::span<const int>(&dimension, 1));
  out.put(mesh.vertices());
  out.put(mesh.vertex_refs());
  out.put(global_ids);
  out.put(mesh.elements());
  out.put(mesh.element_refs());
  out.put(mesh.facets());
  out.put(mesh.facet_refs());
  out.put(mesh.lines());
  out.put(mesh.line_refs());
  for (const auto* tags : {&mesh.corners(), &mesh.ridges(), &mesh.required_vertices(), &mesh.required_edges(), &mesh.required_triangles()})
    out.put(view(*tags));
  out.put(view(edge_nodes_of(mesh)));
  return std::move(out.bytes);
}

int packed_dimension(const std::vector<std::byte>& bytes) {
  ByteReader in(bytes);
  const std::vector<int> dimension = in.take<int>();
  if (dimension.size() != 1) throw Error("a mesh part message has no dimension");
  return dimension[0];
}

template <int D>
MeshPart<D> unpack_part(const std::vector<std::byte>& bytes) {
  ByteReader in(bytes);
  if (in.take<int>() != std::vector<int>{D}) throw Error("a mesh part message is not of dimension " + std::to_string(D));
  MeshPart<D> part;
  Mesh<D>& mesh = part.mesh;
  const auto vertices = in.take<Vec<D>>();
  const auto vertex_refs = in.take<int>();
  part.global_ids = in.take<Index>();
  const auto elements = in.take<typename Mesh<D>::Element>();
  const auto element_refs = in.take<int>();
  const auto facets = in.take<typename Mesh<D>::Facet>();
  const auto facet_refs = in.take<int>();
  const auto lines = in.take<typename Mesh<D>::Line>();
  const auto line_refs = in.take<int>();
  const bool ids_fit = part.global_ids.empty() || part.global_ids.size() == vertices.size();
  if (vertex_refs.size() != vertices.size() || !ids_fit || element_refs.size() != elements.size() || facet_refs.size() != facets.size() ||
      line_refs.size() != lines.size())
    throw Error("a mesh part message has arrays of different lengths");
  for (std::size_t v = 0; v < vertices.size(); ++v) mesh.add_vertex(vertices[v], vertex_refs[v]);
  for (std::size_t k = 0; k < elements.size(); ++k) mesh.add_element(elements[k], element_refs[k]);
  for (std::size_t f = 0; f < facets.size(); ++f) mesh.add_facet(facets[f], facet_refs[f]);
  for (std::size_t l = 0; l < lines.size(); ++l) mesh.add_line(lines[l], line_refs[l]);
  for (auto* tags : {&mesh.corners(), &mesh.ridges(), &mesh.required_vertices(), &mesh.required_edges(), &mesh.required_triangles()})
    *tags = in.take<Index>();
  set_edge_nodes(mesh, in.take<Vec<D>>());
  if (!in.at_end()) throw Error("a mesh part message has bytes past its end");
  return part;
}

template std::vector<std::byte> pack_part(const Mesh<2>&, std::span<const Index>);
template std::vector<std::byte> pack_part(const Mesh<3>&, std::span<const Index>);
template MeshPart<2> unpack_part(const std::vector<std::byte>&);
template MeshPart<3> unpack_part(const std::vector<std::byte>&);

}  // namespace hocav
