// Mesh<D>: the front mesh of hocav — triangles (D = 2) or tetrahedra (D = 3), P1 or P2.
//
// Storage is data-oriented (arrays of fixed-size records, 32-bit indices, no per-entity heap
// objects). P2 mid nodes live on edges: an edge table gives every edge an id, found in O(1) from its
// two vertices (hash) or from an element's local edge (element_edges), and holds its node.
// Topology (face adjacency, vertex -> element, boundary facet <-> element face) is derived data,
// built by build_topology() and kept right by the one editing interface, the cavity operator
// (src/cavity/cavity_operator.hpp): it alone reaches the low-level mutators below.
//
// Built for change (docs/mesh-model.md): the cavity operator removes vertices, boundary facets and
// lines by marking them removed (their ids stay valid and unused until compact()), so ids held by a
// pass stay stable while it runs; compact() renumbers between passes. Vertex attributes (rows of
// doubles per vertex, e.g. a log-metric) live with the mesh and follow every insertion and
// compaction; element attributes (a double per element, e.g. a cached quality) follow every move.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "base/index.hpp"
#include "base/index_hash_map.hpp"
#include "geom/vec.hpp"
#include "mesh/simplex.hpp"

namespace hocav {

template <int D>
class Mesh {
 public:
  static constexpr int kElementVertices = D + 1;
  static constexpr int kFacetVertices = D;
  static constexpr int kElementEdges = Simplex<D>::kEdges;
  using Point = Vec<D>;
  using Element = std::array<Index, D + 1>;
  using Facet = std::array<Index, D>;
  using Line = std::array<Index, 2>;
  using ElementEdges = std::array<Index, Simplex<D>::kEdges>;

  // ---- vertices (element corners; P2 mid nodes are not vertices, they live on edges) ----
  Index vertex_count() const { return static_cast<Index>(vertices_.size()); }
  const Point& vertex(Index v) const { return vertices_[v]; }
  Point& vertex(Index v) { return vertices_[v]; }
  int vertex_ref(Index v) const { return vertex_refs_[v]; }
  std::span<const Point> vertices() const { return vertices_; }
  std::span<const int> vertex_refs() const { return vertex_refs_; }
  // A new vertex; its attribute rows start at zero.
  Index add_vertex(const Point& point, int ref = 0);
  // Removes the last vertex (an insertion that was refused); no element may use it.
  void pop_vertex();
  // A vertex the cavity operator removed (a collapse): no element uses it until compact() drops it.
  bool vertex_removed(Index v) const { return !removed_vertices_.empty() && removed_vertices_[v]; }
  // Vertices not removed.
  Index live_vertex_count() const { return vertex_count() - removed_vertex_count_; }

  // ---- vertex attributes: `width` doubles per vertex that follow every change ----
  int add_vertex_attribute(int width);
  int vertex_attribute_width(int attribute) const { return attribute_widths_[attribute]; }
  std::span<double> vertex_attribute(int attribute, Index v) {
    const auto w = static_cast<std::size_t>(attribute_widths_[attribute]);
    return {attributes_[attribute].data() + w * static_cast<std::size_t>(v), w};
  }
  std::span<const double> vertex_attribute(int attribute, Index v) const {
    const auto w = static_cast<std::size_t>(attribute_widths_[attribute]);
    return {attributes_[attribute].data() + w * static_cast<std::size_t>(v), w};
  }

  // ---- elements (triangles in 2D, tetrahedra in 3D) ----
  Index element_count() const { return static_cast<Index>(elements_.size()); }
  const Element& element(Index k) const { return elements_[k]; }
  int element_ref(Index k) const { return element_refs_[k]; }
  std::span<const Element> elements() const { return elements_; }
  std::span<const int> element_refs() const { return element_refs_; }
  Index add_element(const Element& vertices, int ref = 0);

  // ---- element attributes: one double per element that follows the element through every move;
  // a slot that gets a new element (add, or set_element in a cavity's commit) starts again at the
  // attribute's initial value ----
  int add_element_attribute(double initial);
  double element_attribute(int attribute, Index k) const { return element_attributes_[attribute].values[k]; }
  void set_element_attribute(int attribute, Index k, double value) { element_attributes_[attribute].values[k] = value; }

  // ---- boundary facets (edges in 2D, triangles in 3D) ----
  Index facet_count() const { return static_cast<Index>(facets_.size()); }
  const Facet& facet(Index f) const { return facets_[f]; }
  int facet_ref(Index f) const { return facet_refs_[f]; }
  std::span<const Facet> facets() const { return facets_; }
  std::span<const int> facet_refs() const { return facet_refs_; }
  Index add_facet(const Facet& vertices, int ref = 0);
  bool facet_removed(Index f) const { return facets_[f][0] == kNoIndex; }

  // ---- feature lines: the Edges keyword of a 3D mesh (in 2D the Edges are the facets) ----
  Index line_count() const { return static_cast<Index>(lines_.size()); }
  const Line& line(Index l) const { return lines_[l]; }
  int line_ref(Index l) const { return line_refs_[l]; }
  std::span<const Line> lines() const { return lines_; }
  std::span<const int> line_refs() const { return line_refs_; }
  Index add_line(const Line& vertices, int ref = 0);
  bool line_removed(Index l) const { return lines_[l][0] == kNoIndex; }
  // Marks line l removed: a line is a tag on element edges, linked to nothing, so any caller may drop
  // one; compact() then drops it and renumbers the tags that list lines.
  void remove_line(Index l);
  // Whether line l is listed in ridges() (in 2D, facet l).
  bool is_ridge(Index l) const;

  // ---- geometric tags carried through (Corners, RequiredVertices: vertex ids; Ridges and
  // RequiredEdges: ids of the entities of the Edges keyword, i.e. facets in 2D and lines in 3D;
  // RequiredTriangles: 3D facet ids) ----
  std::vector<Index>& corners() { return corners_; }
  const std::vector<Index>& corners() const { return corners_; }
  std::vector<Index>& ridges() { return ridges_; }
  const std::vector<Index>& ridges() const { return ridges_; }
  std::vector<Index>& required_vertices() { return required_vertices_; }
  const std::vector<Index>& required_vertices() const { return required_vertices_; }
  std::vector<Index>& required_edges() { return required_edges_; }
  const std::vector<Index>& required_edges() const { return required_edges_; }
  std::vector<Index>& required_triangles() { return required_triangles_; }
  const std::vector<Index>& required_triangles() const { return required_triangles_; }

  // ---- P2: edges and their mid nodes ----
  int order() const { return order_; }
  bool is_p2() const { return order_ == 2; }
  // Builds the edge table of all element, facet and line edges; nodes start at the straight
  // midpoints. Makes the mesh P2. Idempotent on an unchanged mesh.
  void make_p2();
  // Forgets the P2 nodes (the mesh becomes P1); the edge table stays.
  void make_p1();
  // Forgets the P2 nodes and the edge table (the mesh becomes a plain P1 mesh, as a remesher wants).
  void forget_edges();
  // Builds (or rebuilds) the edge table without changing the order (for edge loops on P1 meshes).
  void build_edges();
  bool has_edges() const { return !edge_vertices_.empty() || elements_.empty(); }
  Index edge_count() const { return static_cast<Index>(edge_vertices_.size()); }
  const Line& edge_vertices(Index e) const { return edge_vertices_[e]; }
  Index find_edge(Index a, Index b) const { return edge_ids_.find(edge_key(a, b)); }
  Index element_edge(Index k, int local_edge) const { return element_edges_[k][local_edge]; }
  const ElementEdges& element_edges(Index k) const { return element_edges_[k]; }
  const Point& edge_node(Index e) const { return edge_nodes_[e]; }
  Point& edge_node(Index e) { return edge_nodes_[e]; }
  // The same as arrays (views for Python): every edge's vertices and node, every element's edge ids.
  std::span<const Line> edges() const { return edge_vertices_; }
  std::span<const Point> edge_nodes() const { return edge_nodes_; }
  std::span<const ElementEdges> element_edge_table() const { return element_edges_; }

  // ---- topology (derived) ----
  // Face adjacency, vertex -> element and boundary facet <-> element face. Throws Error on a face
  // shared by more than two elements or a facet that is no element face.
  void build_topology();
  // With the topology built: links the facets added since (add_facet) to their element faces, as
  // build_topology would, without building the adjacency again. Throws Error for a facet that is no
  // element face.
  void link_facets();
  bool has_topology() const { return adjacency_.size() == elements_.size() && !elements_.empty(); }
  // Orders every facet on the domain's boundary (no element across its face) as that face of its
  // element: outward, the elements being positive; and every interface facet (elements of two refs
  // across it) as a face of the side with the smaller ref; and each patch of baffle facets (one ref
  // on both sides) like its first facet (mesh/baffle_orientation.hpp). The file formats leave a
  // facet's orientation free, and gmsh's surfaces come either way; the operators orient the facets
  // they make the same way.
  // Needs the topology.
  void orient_boundary_facets_outward();
  // The element facet f faces away from under that rule: its element on the domain's boundary, the
  // side of the smaller ref on an interface; kNoIndex on a baffle (its patch decides). Needs the topology.
  Index outward_element(Index f) const;
  // Orders facet f as face `face` of element k (outward from k, the elements being positive), or the
  // other way round when `inward`.
  void orient_facet_as_face(Index f, Index k, int face, bool inward = false);
  // Reverses facet f's orientation.
  void turn_facet(Index f) { std::swap(facets_[f][0], facets_[f][1]); }
  // The element across face `face` of element k, or kNoIndex on the boundary of the domain.
  Index neighbor(Index k, int face) const { return adjacency_[k][face]; }
  // An element incident to vertex v (kNoIndex for a vertex no element uses).
  Index vertex_element(Index v) const { return vertex_element_[v]; }
  // The element face a facet lies on, encoded as element * (D + 1) + local face.
  Index facet_element_face(Index f) const { return facet_element_face_[f]; }
  // The boundary facet on face `face` of element k, or kNoIndex.
  Index element_face_facet(Index k, int face) const {
    // Most faces carry no facet: their bit answers without probing the hash (a cache miss).
    if (static_cast<std::size_t>(k) >= faces_with_facet_.size() || !((faces_with_facet_[k] >> face) & 1)) return kNoIndex;
    return element_face_facets_.find(face_key(k, face));
  }
  // Whether a facet lies on face `face` of element k, linked from k or from the element across
  // (a facet inside the domain is linked from one of its sides only).
  bool face_has_facet(Index k, int face) const {
    if (element_face_facet(k, face) != kNoIndex) return true;
    const Index across = neighbor(k, face);
    if (across == kNoIndex || static_cast<std::size_t>(across) >= faces_with_facet_.size() || faces_with_facet_[across] == 0) return false;
    for (int back = 0; back <= D; ++back)
      if (adjacency_[across][back] == k) return element_face_facet(across, back) != kNoIndex;
    return false;
  }

  // Asks the memory for element k's records (vertices, ref, neighbours, facet bits, edge ids)
  // before they are read: a cavity's first touch of its elements is mostly cache misses, and
  // requesting them together overlaps them. (Inlined: else the compiler, seeing a function
  // without effects, drops the calls.)
  [[gnu::always_inline]] void prefetch_element(Index k) const {
    const auto row = static_cast<std::size_t>(k);
    __builtin_prefetch(&elements_[row]);
    __builtin_prefetch(&element_refs_[row]);
    if (row < adjacency_.size()) __builtin_prefetch(&adjacency_[row]);
    if (row < faces_with_facet_.size()) __builtin_prefetch(&faces_with_facet_[row]);
    if (row < element_edges_.size()) __builtin_prefetch(&element_edges_[row]);
  }

  // Replaces an element's vertices and ref: for building a mesh, before build_topology().
  void set_element(Index k, const Element& vertices, int ref) {
    elements_[k] = vertices;
    element_refs_[k] = ref;
    for (ElementAttribute& attribute : element_attributes_) attribute.values[k] = attribute.initial;
  }

  // Drops removed vertices, facets and lines and renumbers what remains in its order (elements are
  // always compact); attributes, tags, topology and the edge table follow. Returns each old vertex's
  // new id (kNoIndex for a removed one).
  std::vector<Index> compact();
  // Renumbers the vertices and elements of a compact mesh: vertex v becomes new_vertex_id[v] and
  // element k new_element_id[k] (both permutations); attributes, tags, facets, lines, the edge table
  // and the topology follow (docs/mesh-model.md §Spatial order).
  void renumber(std::span<const Index> new_vertex_id, std::span<const Index> new_element_id);
  // Renumbers the edges alone so their ids are 0..edge_count()-1 again (a curving run, which
  // removes no vertex, needs no more).
  void compact_edges();
  // True when nothing removed waits for compact() (file writers need it).
  bool is_compact() const {
    return removed_vertex_count_ == 0 && removed_facet_count_ == 0 && removed_line_count_ == 0 && free_edges_.empty();
  }

  // Bytes held by the mesh's arrays (capacity, not size), for the memory figures in the docs.
  std::size_t memory_bytes() const;

  static std::uint64_t edge_key(Index a, Index b) {
    auto lo = static_cast<std::uint64_t>(a < b ? a : b), hi = static_cast<std::uint64_t>(a < b ? b : a);
    return (lo << 32) | hi;
  }

 private:
  // ---- local changes, for the cavity operator alone: each keeps only the invariant it names; the
  // operator restores the others before it returns ----
  template <int>
  friend class CavityOperator;
  // Appends an element with no neighbours and (when the edge table exists) no edges yet.
  Index append_element(const Element& vertices, int ref);
  // Moves element `from` into slot `to` (whose old content is dropped), re-pointing its
  // neighbours, its vertices, its facets and its edge ids at the new slot.
  void move_element(Index from, Index to);
  // Drops the last element (after move_element has emptied it).
  void pop_element();
  void set_neighbor(Index k, int face, Index neighbor) { adjacency_[k][face] = neighbor; }
  void set_vertex_element(Index v, Index k) { vertex_element_[v] = k; }
  // Puts facet f on face `face` of element k (both directions of the link).
  void attach_facet(Index f, Index k, int face);
  // A new edge (reusing a removed edge's id) with its P2 node (ignored on a P1 mesh).
  Index add_edge(Index a, Index b, const Point& node);
  // Removes an edge from the table; its id is reused by the next add_edge.
  void remove_edge(Index e);
  void set_element_edge(Index k, int local_edge, Index e) { element_edges_[k][local_edge] = e; }
  // Marks a vertex no element uses any more as removed.
  void remove_vertex(Index v);
  // Marks a facet removed, unlinking it from its element face.
  void remove_facet(Index f);
  // A new facet on face `face` of element k, linked both ways.
  Index add_attached_facet(const Facet& vertices, int ref, Index k, int face);

  Index insert_edge(Index a, Index b);
  // After compact(): the hashes keyed by vertex or facet ids, rebuilt from the renumbered arrays.
  void rekey_after_renumbering();
  // The element face (element * (D + 1) + face) of `facet` among the elements around its vertex
  // `center`, walked from that vertex's element across the faces that hold it; kNoIndex if none.
  Index facet_face_near(const Facet& facet, Index center, std::vector<Index>& ball, std::vector<Index>& stack) const;
  // The element face of `facet` (as facet_face_near gives it), searched around each of its vertices,
  // then among every element; Error naming facet f when no element has it.
  Index facet_face(Index f, std::vector<Index>& ball, std::vector<Index>& stack) const;
  // Links again, by their own records only, the facets whose element face no longer holds them: a
  // facet that shares its face with another (an inner facet on a distributed part's interface) is
  // reached from that face by the other one, so the operators that move its elements do not update it.
  void relink_facets_off_their_faces();
  static std::uint64_t face_key(Index k, int face) { return static_cast<std::uint64_t>(k) * (D + 1) + static_cast<std::uint64_t>(face); }
  // The element-face -> facet map and its per-element bits change together.
  void link_face_facet(Index k, int face, Index f);
  void unlink_face_facet(Index k, int face);

  std::vector<Point> vertices_;
  std::vector<int> vertex_refs_;
  std::vector<Element> elements_;
  std::vector<int> element_refs_;
  std::vector<Facet> facets_;
  std::vector<int> facet_refs_;
  std::vector<Line> lines_;
  std::vector<int> line_refs_;
  std::vector<Index> corners_, ridges_, required_vertices_, required_edges_, required_triangles_;
  std::vector<std::uint8_t> removed_vertices_;  // per vertex once one is removed, else empty
  Index removed_vertex_count_ = 0, removed_facet_count_ = 0, removed_line_count_ = 0;
  std::vector<int> attribute_widths_;
  std::vector<std::vector<double>> attributes_;
  struct ElementAttribute {
    double initial;
    std::vector<double> values;
  };
  std::vector<ElementAttribute> element_attributes_;

  int order_ = 1;
  std::vector<Line> edge_vertices_;
  std::vector<Point> edge_nodes_;
  std::vector<ElementEdges> element_edges_;
  IndexHashMap edge_ids_;
  std::vector<Index> free_edges_;  // ids of removed edges, reused first

  std::vector<Element> adjacency_;
  std::vector<Index> vertex_element_;
  std::vector<Index> facet_element_face_;
  IndexHashMap element_face_facets_;
  std::vector<std::uint8_t> faces_with_facet_;  // per element, bit `face` set when the face has a facet
};

extern template class Mesh<2>;
extern template class Mesh<3>;

}  // namespace hocav
