// A piece of a distributed mesh on its way to the process that builds a part of it (docs/distributed.md
// §Migration): elements by global vertex ids with what the part needs around them, as one message,
// and the part built from the pieces a process receives. The migration sends them; reading a file in
// pieces makes each process's own.
#pragma once

#include <functional>
#include <span>
#include <utility>
#include <vector>

#include "base/error.hpp"
#include "parallel/byte_stream.hpp"
#include "parallel/mesh_parts.hpp"

namespace hocav {

// Vertex flags (a corner, then the pinned flags shifted by one), and facet and line flags, in a message.
constexpr char kShippedCorner = 1;
constexpr char kShippedRequired = 1, kShippedRidge = 2;

// What one process sends another (or reads for itself): its elements by global vertex ids, with per element the faces that
// have a neighbour in the whole mesh (a bit per face), the vertices they use, the mesh's facets and
// lines on them, and their P2 nodes (each edge's once, in the order the elements first reach it).
template <int D>
struct Shipment {
  std::vector<Index> vertex_ids;
  std::vector<Vec<D>> points;
  std::vector<int> vertex_refs;
  std::vector<char> vertex_flags;
  std::vector<typename Mesh<D>::Element> elements;
  std::vector<int> element_refs;
  std::vector<char> inner_faces;
  std::vector<typename Mesh<D>::Facet> facets;
  std::vector<int> facet_refs;
  std::vector<char> facet_flags;
  std::vector<typename Mesh<D>::Line> lines;
  std::vector<int> line_refs;
  std::vector<char> line_flags;
  std::vector<Vec<D>> nodes;

  std::vector<std::byte> bytes() const {
    ByteWriter out;
    out.put(vertex_ids), out.put(points), out.put(vertex_refs), out.put(vertex_flags);
    out.put(elements), out.put(element_refs), out.put(inner_faces);
    out.put(facets), out.put(facet_refs), out.put(facet_flags);
    out.put(lines), out.put(line_refs), out.put(line_flags);
    out.put(nodes);
    return std::move(out.bytes);
  }

  static Shipment read(const std::vector<std::byte>& bytes) {
    ByteReader in(bytes);
    Shipment s;
    s.vertex_ids = in.take<Index>(), s.points = in.take<Vec<D>>(), s.vertex_refs = in.take<int>(), s.vertex_flags = in.take<char>();
    s.elements = in.take<typename Mesh<D>::Element>(), s.element_refs = in.take<int>(), s.inner_faces = in.take<char>();
    s.facets = in.take<typename Mesh<D>::Facet>(), s.facet_refs = in.take<int>(), s.facet_flags = in.take<char>();
    s.lines = in.take<typename Mesh<D>::Line>(), s.line_refs = in.take<int>(), s.line_flags = in.take<char>();
    s.nodes = in.take<Vec<D>>();
    const std::size_t n = s.vertex_ids.size(), k = s.elements.size();
    if (!in.at_end() || s.points.size() != n || s.vertex_refs.size() != n || s.vertex_flags.size() != n || s.element_refs.size() != k ||
        s.inner_faces.size() != k || s.facet_refs.size() != s.facets.size() || s.facet_flags.size() != s.facets.size() ||
        s.line_refs.size() != s.lines.size() || s.line_flags.size() != s.lines.size() || s.nodes.size() > k * Simplex<D>::kEdges)
      throw Error("a migration message has arrays of different lengths");
    return s;
  }
};

// The mesh's facets but the interfaces' (ref kInterfaceRef) as (element, facet) pairs, sorted: the
// order in which pack_shipments ships them (element by element). Throws Error for a facet that is
// no face of the elements.
template <int D>
std::vector<std::pair<Index, Index>> facets_by_element(const Mesh<D>& mesh);

// Packs every element of `part` (with its topology, global ids and pinned flags) for its destination,
// element k for destination[k] in [0, destinations): `take` gets each destination's shipment in
// destination order, one at a time (an empty one for a destination no element goes to).
template <int D>
void pack_shipments(const MeshPart<D>& part, std::span<const int> destination, int destinations,
                    const std::function<void(int, Shipment<D>)>& take);

// The shipment of `elements` of `part` (with its topology, global ids and pinned flags), as
// pack_shipments makes one: the part itself is left as it is (a copy of some of its elements).
template <int D>
Shipment<D> shipment_of(const MeshPart<D>& part, std::span<const Index> elements);

// The part a process builds from the pieces it receives, in rank order: its vertices in the order of
// their global ids, its elements piece by piece in each piece's order, the mesh's facets, then a
// required facet of ref kInterfaceRef on each face with a neighbour in the whole mesh but none in
// the part (its vertices required), the lines once each, P2 nodes when the pieces carry them, and
// its topology. Pieces without elements (a boundary's: boundary_of_parts.hpp) give their vertices,
// facets and lines, no topology. Throws Error when two pieces give one vertex different points, or
// P1 and P2 elements arrive together.
template <int D>
MeshPart<D> part_of_shipments(const std::vector<Shipment<D>>& arrived);

}  // namespace hocav
