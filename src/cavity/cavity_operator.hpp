// The P1 cavity operator (the paper's §III.A): remove a set of elements (the cavity) and star the
// boundary of the hole from one vertex. Insertion, collapse, swap and reinsertion are all this one
// operation with different cavities and vertices (see cavity_operations.hpp).
//
// It works in two phases so a rejection leaves the mesh exactly as it was: plan() reads the mesh
// and decides (topology, refs, boundary facets, straight measures when asked), commit() writes.
// Between the two, the P2 operator curves the new inner edges and certifies the new elements.
#pragma once

#include <array>
#include <span>
#include <vector>

#include "base/index_hash_map.hpp"
#include "mesh/mesh.hpp"

namespace hocav {

struct CavityOptions {
  // P1 mode: every new element must have a straight measure above min_relative_measure ×
  // (longest edge)^D. Off in P2 mode, where a valid curved element may be an inverted P1 element.
  bool check_straight_measure = true;
  double min_relative_measure = 1e-12;
  // The one vertex inside the cavity that may disappear (collapse), or kNoIndex.
  Index removable_vertex = kNoIndex;
  // Boundary operations (P1 and P2 meshes): boundary facets on the cavity's boundary that the operation
  // replaces. They are re-starred from the vertex within each facet ref (the surface cavity), and in
  // 3D the feature lines among their edges that the operation replaces are re-starred from it too
  // (a split or collapse along a ridge). The caller names them: which boundary pieces an operation
  // changes is its geometry's decision, not the topology's. A facet inside the domain (an interface
  // between element refs, or a baffle) may be removed when the cavity holds the elements on both of
  // its sides: its surface cavity is re-starred the same way, each new facet between the two new
  // elements that share it, and each new element keeps the ref of its side (P1 meshes only).
  std::span<const Index> removed_facets{};
  std::span<const Index> removed_lines{};
  // Boundary operations that give up part of the domain (a cap's removal): a face through the
  // vertex on the cavity's boundary, with an element beyond it and no facet, may take a new facet
  // and become boundary (refused when an edge it does not share with a removed facet is on the
  // boundary already); the star may then have no element at all.
  bool exposes_faces = false;
};

enum class CavityStatus {
  kAccepted,
  kNotStarShaped,        // the star of the boundary from the vertex is not a closed, manifold set
  kCrossesBoundary,      // a boundary facet lies inside the cavity, or a removed facet is not on its boundary or has an element past it
  kMixedRefs,            // the cavity's elements carry different refs across a face that no removed facet holds
  kRemovesVertex,        // a vertex other than the removable one would disappear
  kNonPositiveMeasure,   // P1 mode: a new element is flat or inverted
  kRejectedByCurving,    // the P2 operator found no valid curved configuration
  kNoImprovement,        // the P2 operator's new elements are not better than the request asks
  kFlatStraightElement,  // the P2 operator: a new straight simplex below the request's quality floor
  kBoundaryGeometry,     // the P2 operator: the request's test of the new boundary facets failed
};
const char* to_string(CavityStatus status);

template <int D>
class CavityOperator {
 public:
  using Element = typename Mesh<D>::Element;
  using Point = Vec<D>;

  // Plans the star of `cavity` (element ids, no repeats) from `vertex`; reads the mesh only.
  CavityStatus plan(const Mesh<D>& mesh, std::span<const Index> cavity, Index vertex, const CavityOptions& options);

  // ---- the plan (valid until the next plan or commit) ----
  Index vertex() const { return vertex_; }
  std::span<const Element> new_elements() const { return new_elements_; }
  // Per new element, its ref: that of the cavity element whose boundary face it is starred from.
  std::span<const int> new_element_refs() const { return new_element_refs_; }
  // Inner edges (vertex, boundary vertex) the star creates, and for each the node it had when it
  // existed before (reinsertion) or the straight midpoint: the start of its curving.
  std::span<const std::array<Index, 2>> new_inner_edges() const { return new_inner_edges_; }
  std::span<const Point> new_inner_edge_start_nodes() const { return start_nodes_; }
  // Per new inner edge: the id of the edge it recreates (a reinsertion), or kNoIndex for a new one.
  std::span<const Index> new_inner_edge_recreated_ids() const { return recreated_ids_; }
  // After commit: the mesh id of each new inner edge, and of each new element (in new_elements()'s order).
  std::span<const Index> committed_inner_edge_ids() const { return inner_edge_ids_; }
  std::span<const Index> committed_element_ids() const { return new_element_ids_; }
  // Edges on the cavity's boundary, kept by the commit (P2: their nodes may be replaced), and the
  // id of one of them by its vertices (kNoIndex for an edge not on the cavity's boundary).
  std::span<const Index> boundary_edges() const { return boundary_edge_ids_; }
  Index boundary_edge(Index a, Index b) const;
  std::span<const Index> cavity() const { return cavity_; }
  // Boundary operations: the facets and lines the commit creates (vertices, ref).
  struct NewFacet {
    typename Mesh<D>::Facet vertices;
    int ref;
    Index replaced;  // the removed facet whose side it stars from the vertex
    bool inner;      // inside the domain: a face of two new elements
  };
  struct NewLine {
    typename Mesh<D>::Line vertices;
    int ref;
    bool ridge;
  };
  std::span<const NewFacet> new_facets() const { return new_facets_; }
  std::span<const NewLine> new_lines() const { return new_lines_; }

  // Applies the plan. On a P2 mesh `inner_edge_nodes[i]` is the node of new_inner_edges()[i], and
  // `changed_boundary_nodes` replaces the nodes of some boundary edges (edge id, node).
  void commit(Mesh<D>& mesh, std::span<const Point> inner_edge_nodes = {},
              std::span<const std::pair<Index, Point>> changed_boundary_nodes = {});

 private:
  struct BoundaryFace {
    std::array<Index, D> vertices;  // oriented as seen from inside the cavity
    Index outer_element;            // the neighbour outside, or kNoIndex
    int outer_face;
    Index facet;          // the boundary facet on the face, or kNoIndex
    Index inner_element;  // the cavity element it is a face of, and its local face there
    int inner_face;
    bool removed;  // its facet is replaced by the surface star
  };
  // A face containing the vertex, keyed by its other D − 1 vertices: a new element's face or a
  // kept boundary face; matched in pairs.
  struct RidgeFace {
    std::uint64_t key;
    Index new_element;  // index in new_elements_, or kNoIndex for a kept boundary face
    int face;           // local face of the new element, or index in boundary_faces_
  };
  struct Link {
    std::uint64_t key;
    Index new_element;        // kNoIndex: an exposed face, kept boundary face `kept_face` taking new facet
    int face;                 // `face` − boundary_faces_.size() (CavityOptions::exposes_faces)
    Index other_new_element;  // kNoIndex: linked to the kept boundary face `kept_face`, or to new
    int other_face;           // facet kept_face − boundary_faces_.size() when it is past them
    int kept_face;
    int inner_facet;  // between two new elements: the new inner facet on the face (index in new_facets_), or −1
  };
  // A removed facet between two cavity elements, and the refs of its two sides (smaller first).
  struct InnerFacet {
    Index facet;
    std::array<int, 2> refs;
  };

  // An edge of the cavity by key, with its id.
  struct KeyedEdge {
    std::uint64_t key;
    Index id;
  };

  bool in_cavity(Index k) const;
  CavityStatus collect_boundary(const Mesh<D>& mesh);
  // P1 (see plan_edges for P2): whether the boundary faces bound a ball, one sphere (2D: one cycle)
  // by Euler's formula. A cavity whose boundary touches itself at a vertex would be starred into
  // two fans around one new edge, pinching that vertex; only rounding on near-flat elements lets
  // such a star pass the measure test.
  bool boundary_is_a_sphere();
  // Boundary operations: the new facets and lines, starred from the vertex.
  struct SurfaceSide {
    Index from, to;  // 3D: a directed edge of a removed facet; 2D: its vertex as `from` (tail) or `to` (head)
    int ref;
    Index facet;
    bool inner;      // of an inner facet: cancels only with those
    bool cancelled;  // met twice in its ref: inside the surface cavity
  };
  void collect_surface_sides(const Mesh<D>& mesh);
  CavityStatus star_surface(const Mesh<D>& mesh, const CavityOptions& options);
  void star_lines(const Mesh<D>& mesh, std::span<const Index> removed_lines);
  bool is_removed_line(const Mesh<D>& mesh, Index a, Index b) const;
  CavityStatus match_ridges();
  bool pair_ridge_faces();  // fills links_; false when a ridge has not exactly two faces
  // Each new inner facet on the link between the two new elements that share it, their refs those of
  // the facet it replaces; and every other link between new elements of different refs refused.
  bool place_inner_facets();
  // The inner facet a new facet replaces.
  const InnerFacet& replaced_inner_facet(const NewFacet& facet) const;
  // Whether two faces without a new element may pair: a kept face that may be exposed and a new facet.
  bool exposable(const RidgeFace& kept, const RidgeFace& facet) const;
  // Whether every edge of the exposed faces that no removed facet holds (a cap's inner edge) is
  // inside the domain: on the boundary already, it would hold four facets.
  bool exposed_edges_inside(const Mesh<D>& mesh);
  // Commits an exposed face: the element beyond it takes the new facet there.
  void expose(Mesh<D>& mesh, const BoundaryFace& face, const NewFacet& facet) const;
  CavityStatus plan_edges(const Mesh<D>& mesh);
  // P1 (no edge table, whose look-up plan_edges makes): whether a new edge of the star already joins
  // its ends through an element outside the cavity. Exact orientations would forbid it, but
  // near-flat elements let rounding pass a star that folds over the mesh, and a face would then
  // have three elements.
  bool star_folds_over_mesh(const Mesh<D>& mesh);
  // Position of the edge with this key in boundary_edge_keys_, or its size when it is not there.
  std::size_t boundary_edge_slot(std::uint64_t key) const;
  // new_element_edges_ holds edge ids (≥ 0) and, for new inner edge i, whose id only the commit
  // knows, inner_edge_ref(i).
  static Index inner_edge_ref(std::size_t i) { return -2 - static_cast<Index>(i); }
  static std::size_t inner_edge_of(Index ref) { return static_cast<std::size_t>(-2 - ref); }

  std::vector<Index> cavity_;
  Index vertex_ = kNoIndex;
  std::vector<int> new_element_refs_;
  std::vector<InnerFacet> inner_facets_;
  std::vector<BoundaryFace> boundary_faces_;
  std::vector<std::uint8_t> boundary_face_bits_;  // per cavity element: bit f set when its face f is a boundary face
  bool vertex_on_boundary_ = false;               // the vertex is on a boundary face (not inside the cavity)
  bool exposes_faces_ = false;                    // CavityOptions::exposes_faces
  std::vector<Index> starred_faces_;              // boundary face of each new element
  std::vector<Element> new_elements_;
  std::vector<RidgeFace> ridge_faces_;
  std::vector<int> ridge_slots_, ridge_partner_;  // pair_ridge_faces' table, and each face's partner
  std::vector<Link> links_;
  std::vector<Index> vanishing_vertices_;
  std::vector<Index> removed_facets_, removed_lines_;  // sorted
  std::vector<NewFacet> new_facets_;
  std::vector<NewLine> new_lines_;
  std::vector<SurfaceSide> surface_sides_;
  std::vector<std::uint64_t> scratch_keys_;
  std::vector<std::uint64_t> boundary_edge_keys_;
  std::vector<Index> boundary_edge_ids_;
  std::vector<KeyedEdge> removed_edges_;  // by increasing id
  std::vector<KeyedEdge> keyed_edges_;    // scratch
  std::vector<typename Mesh<D>::ElementEdges> new_element_edges_;
  std::vector<std::array<Index, 2>> new_inner_edges_;
  std::vector<Index> recreated_ids_;    // per new inner edge: its old id when it existed (kept), else kNoIndex
  std::vector<Index> inner_edge_ids_;   // per new inner edge: its id once committed
  std::vector<Index> new_element_ids_;  // per new element: its id once committed
  std::vector<Point> start_nodes_;
  std::vector<Index> scratch_;
  std::vector<Index> ball_, kept_neighbors_, new_neighbors_;  // star_folds_over_mesh's (ball_: exposed_edges_inside's too)
  IndexHashMap sphere_vertices_;                              // boundary_is_a_sphere's
};

extern template class CavityOperator<2>;
extern template class CavityOperator<3>;

}  // namespace hocav
