#include "cavity/cavity_operator.hpp"

#include <algorithm>
#include <cmath>

#include "mesh/ball_and_shell.hpp"
#include "mesh/measure.hpp"

namespace hocav {

const char* to_string(CavityStatus status) {
  switch (status) {
    case CavityStatus::kAccepted: return "accepted";
    case CavityStatus::kNotStarShaped: return "not star-shaped";
    case CavityStatus::kCrossesBoundary: return "crosses a boundary facet";
    case CavityStatus::kMixedRefs: return "mixed element refs";
    case CavityStatus::kRemovesVertex: return "would remove a vertex";
    case CavityStatus::kNonPositiveMeasure: return "non-positive straight measure";
    case CavityStatus::kRejectedByCurving: return "no valid curving";
    case CavityStatus::kNoImprovement: return "no quality improvement";
    case CavityStatus::kFlatStraightElement: return "near-flat straight element";
    case CavityStatus::kBoundaryGeometry: return "new boundary off the geometry";
  }
  return "?";
}

namespace {

// Key of the D − 1 vertices of a face other than the starred vertex (sorted; fits 64 bits).
template <int D>
std::uint64_t ridge_key(const Index* vertices, Index skip) {
  Index kept[2] = {kNoIndex, kNoIndex};
  int count = 0;
  for (int i = 0; i < D; ++i)
    if (vertices[i] != skip) kept[count++] = vertices[i];
  if constexpr (D == 2) return static_cast<std::uint64_t>(kept[0]);
  return Mesh<3>::edge_key(kept[0], kept[1]);
}

// The local edge of a D-simplex joining two local vertices.
template <int D>
struct LocalEdges {
  std::array<std::array<int, D + 1>, D + 1> of_vertices{};
  constexpr LocalEdges() {
    for (int e = 0; e < Simplex<D>::kEdges; ++e) {
      const auto [p, q] = edge_vertices<D>(e);
      of_vertices[static_cast<std::size_t>(p)][static_cast<std::size_t>(q)] = e;
      of_vertices[static_cast<std::size_t>(q)][static_cast<std::size_t>(p)] = e;
    }
  }
  int operator()(int p, int q) const { return of_vertices[static_cast<std::size_t>(p)][static_cast<std::size_t>(q)]; }
};
template <int D>
constexpr LocalEdges<D> kLocalEdge{};

// The length of the element's longest edge to the power D, the scale of its measure.
template <int D>
double longest_edge_power(const Mesh<D>& mesh, const typename Mesh<D>::Element& element) {
  double longest2 = 0;
  for (int i = 0; i <= D; ++i)
    for (int j = 0; j < i; ++j) {
      const Vec<D> e = mesh.vertex(element[i]) - mesh.vertex(element[j]);
      longest2 = std::max(longest2, dot(e, e));
    }
  return D == 2 ? longest2 : longest2 * std::sqrt(longest2);  // one root, no pow: the test runs for every planned element
}

}  // namespace

template <int D>
bool CavityOperator<D>::in_cavity(Index k) const {
  // A binary search without branches: on a small cavity a mispredicted branch costs more than the
  // few extra comparisons.
  const Index* first = cavity_.data();
  for (std::size_t count = cavity_.size(); count > 1;) {
    const std::size_t half = count / 2;
    first = first[half] <= k ? first + half : first;
    count -= half;
  }
  return *first == k;
}

template <int D>
CavityStatus CavityOperator<D>::plan(const Mesh<D>& mesh, std::span<const Index> cavity, Index vertex, const CavityOptions& options) {
  cavity_.assign(cavity.begin(), cavity.end());
  std::sort(cavity_.begin(), cavity_.end());
  vertex_ = vertex;
  new_elements_.clear();
  new_inner_edges_.clear();
  recreated_ids_.clear();
  start_nodes_.clear();
  boundary_edge_keys_.clear();
  boundary_edge_ids_.clear();
  removed_edges_.clear();
  if (cavity_.empty()) return CavityStatus::kNotStarShaped;
  // The plan reads every record of the cavity's elements and the neighbour rows of the elements
  // around it: requested together, their cache misses overlap.
  for (Index k : cavity_) mesh.prefetch_element(k);
  for (Index k : cavity_)
    for (int face = 0; face <= D; ++face)
      if (Index outer = mesh.neighbor(k, face); outer != kNoIndex) mesh.prefetch_element(outer);

  removed_facets_.assign(options.removed_facets.begin(), options.removed_facets.end());
  // Without a removed facet no interface can be inside: refs are decided before any face is read.
  if (removed_facets_.empty())
    for (Index k : cavity_)
      if (mesh.element_ref(k) != mesh.element_ref(cavity_.front())) return CavityStatus::kMixedRefs;
  std::sort(removed_facets_.begin(), removed_facets_.end());
  removed_lines_.assign(options.removed_lines.begin(), options.removed_lines.end());
  std::sort(removed_lines_.begin(), removed_lines_.end());
  exposes_faces_ = options.exposes_faces && !removed_facets_.empty();
  if (CavityStatus status = collect_boundary(mesh); status != CavityStatus::kAccepted) return status;
  if (CavityStatus status = star_surface(mesh, options); status != CavityStatus::kAccepted) return status;

  // One new element per boundary face not containing the vertex: (vertex, face) is positive when
  // the vertex sees the face from inside, since faces are oriented outward.
  starred_faces_.clear();
  new_element_refs_.clear();
  for (std::size_t f = 0; f < boundary_faces_.size(); ++f) {
    const auto& face = boundary_faces_[f].vertices;
    if (boundary_faces_[f].removed || std::find(face.begin(), face.end(), vertex) != face.end()) continue;
    Element element;
    element[0] = vertex;
    for (int i = 0; i < D; ++i) element[i + 1] = face[i];
    new_elements_.push_back(element);
    new_element_refs_.push_back(mesh.element_ref(boundary_faces_[f].inner_element));
    starred_faces_.push_back(static_cast<Index>(f));
  }
  if (new_elements_.empty() && !exposes_faces_) return CavityStatus::kNotStarShaped;
  const std::size_t removed_boundary_faces = removed_facets_.size() - inner_facets_.size();
  vertex_on_boundary_ = new_elements_.size() + removed_boundary_faces < boundary_faces_.size();
  if (CavityStatus status = match_ridges(); status != CavityStatus::kAccepted) return status;
  if (exposes_faces_ && !exposed_edges_inside(mesh)) return CavityStatus::kNotStarShaped;

  // Vertices of the cavity on no boundary face disappear. Most lie on a boundary face of their own
  // element (in a ball, all but the vertex); only the others are searched among all the faces.
  scratch_.clear();
  vanishing_vertices_.clear();
  for (std::size_t i = 0; i < cavity_.size(); ++i)
    for (int j = 0; j <= D; ++j) {
      const Index v = mesh.element(cavity_[i])[j];
      if (v == vertex || (boundary_face_bits_[i] & ~(1u << j))) continue;  // on a boundary face of its element
      if (scratch_.empty()) {
        for (const auto& face : boundary_faces_)
          if (!face.removed) scratch_.insert(scratch_.end(), face.vertices.begin(), face.vertices.end());
        std::sort(scratch_.begin(), scratch_.end());
      }
      if (!std::binary_search(scratch_.begin(), scratch_.end(), v) &&
          std::find(vanishing_vertices_.begin(), vanishing_vertices_.end(), v) == vanishing_vertices_.end())
        vanishing_vertices_.push_back(v);
    }
  for (Index v : vanishing_vertices_)
    if (v != options.removable_vertex) return CavityStatus::kRemovesVertex;

  if (options.check_straight_measure)
    for (const Element& element : new_elements_) {
      typename Mesh<D>::Point p[D + 1];
      for (int i = 0; i <= D; ++i) p[i] = mesh.vertex(element[i]);
      double measure;
      if constexpr (D == 2)
        measure = signed_measure(p[0], p[1], p[2]);
      else
        measure = signed_measure(p[0], p[1], p[2], p[3]);
      if (!(measure > options.min_relative_measure * longest_edge_power(mesh, element))) return CavityStatus::kNonPositiveMeasure;
    }

  if (mesh.has_edges() && mesh.edge_count() > 0) return plan_edges(mesh);
  // P1: the measure test is the only geometric one, and rounding defeats it on near-flat elements
  // (P2 certifies its elements above the Jacobian floor, far above rounding).
  return boundary_is_a_sphere() && !star_folds_over_mesh(mesh) ? CavityStatus::kAccepted : CavityStatus::kNotStarShaped;
}

template <int D>
bool CavityOperator<D>::star_folds_over_mesh(const Mesh<D>& mesh) {
  if (mesh.vertex_element(vertex_) == kNoIndex) return false;  // a new vertex: every edge of its star is new
  // The star's edges from the vertex that no boundary face of the cavity holds are new.
  kept_neighbors_.clear();
  for (const BoundaryFace& face : boundary_faces_)
    if (std::find(face.vertices.begin(), face.vertices.end(), vertex_) != face.vertices.end())
      kept_neighbors_.insert(kept_neighbors_.end(), face.vertices.begin(), face.vertices.end());
  new_neighbors_.clear();
  const auto listed = [](const std::vector<Index>& list, Index v) { return std::find(list.begin(), list.end(), v) != list.end(); };
  for (const Element& element : new_elements_)
    for (int i = 1; i <= D; ++i)
      if (!listed(kept_neighbors_, element[i]) && !listed(new_neighbors_, element[i])) new_neighbors_.push_back(element[i]);
  if (new_neighbors_.empty()) return false;
  // Any of them joined to the vertex through an element outside the cavity?
  collect_ball(mesh, vertex_, ball_);
  for (Index k : ball_)
    if (!in_cavity(k))
      for (Index v : mesh.element(k))
        if (listed(new_neighbors_, v)) return true;
  return false;
}

template <int D>
CavityStatus CavityOperator<D>::collect_boundary(const Mesh<D>& mesh) {
  boundary_faces_.clear();
  inner_facets_.clear();
  std::size_t removed_found = 0;
  // Faces between cavity elements of different refs, each counted from both sides; plan() has
  // refused them already when no facet is removed.
  int ref_changes = 0;
  const bool refs_may_change = !removed_facets_.empty();
  boundary_face_bits_.assign(cavity_.size(), 0);
  const auto is_removed = [&](Index facet) { return std::binary_search(removed_facets_.begin(), removed_facets_.end(), facet); };
  for (std::size_t position = 0; position < cavity_.size(); ++position) {
    const Index k = cavity_[position];
    for (int face = 0; face <= D; ++face) {
      Index outer = mesh.neighbor(k, face);
      Index facet = mesh.element_face_facet(k, face);
      if (outer != kNoIndex && in_cavity(outer)) {
        // An inner facet is linked from one of its sides only: it is found once.
        ref_changes += refs_may_change && mesh.element_ref(outer) != mesh.element_ref(k);
        if (facet == kNoIndex) continue;
        if (!is_removed(facet) || mesh.is_p2()) return CavityStatus::kCrossesBoundary;
        const int here = mesh.element_ref(k), there = mesh.element_ref(outer);
        inner_facets_.push_back({facet, {std::min(here, there), std::max(here, there)}});
        ++removed_found;
        continue;
      }
      const bool removed = facet != kNoIndex && is_removed(facet);
      // A facet with an element past it (an interface inside the domain) would leave that element's
      // face unmatched.
      if (removed && outer != kNoIndex) return CavityStatus::kCrossesBoundary;
      BoundaryFace boundary{{}, outer, -1, facet, k, face, removed};
      for (int i = 0; i < D; ++i) boundary.vertices[i] = mesh.element(k)[face_vertices<D>(face)[i]];
      if (outer != kNoIndex)
        for (int back = 0; back <= D; ++back)
          if (mesh.neighbor(outer, back) == k) boundary.outer_face = back;
      boundary_faces_.push_back(boundary);
      removed_found += removed;
      // The bits say which faces stay on the new region's boundary: a removed facet's face does not.
      if (!removed) boundary_face_bits_[position] = static_cast<std::uint8_t>(boundary_face_bits_[position] | (1u << face));
    }
  }
  if (removed_found != removed_facets_.size()) return CavityStatus::kCrossesBoundary;
  // Elements of different refs may meet only on a removed inner facet.
  const auto interfaces = std::count_if(inner_facets_.begin(), inner_facets_.end(),
                                        [](const InnerFacet& f) { return f.refs[0] != f.refs[1]; });
  return ref_changes == 2 * interfaces ? CavityStatus::kAccepted : CavityStatus::kMixedRefs;
}

template <int D>
bool CavityOperator<D>::boundary_is_a_sphere() {
  sphere_vertices_.clear();  // the faces' distinct vertices (a sort of them cost more)
  for (const BoundaryFace& face : boundary_faces_)
    for (Index v : face.vertices) sphere_vertices_.insert(static_cast<std::uint64_t>(v), v);
  const std::size_t vertices = sphere_vertices_.size(), faces = boundary_faces_.size();
  if constexpr (D == 2)
    return vertices == faces;  // a cycle: as many vertices as sides
  else
    return 2 * vertices == faces + 4;  // V − E + F = 2 with E = 3F / 2
}

template <int D>
void CavityOperator<D>::collect_surface_sides(const Mesh<D>& mesh) {
  // The removed facets' own faces (edges in 3D, vertices in 2D), directed by the outward facets
  // (an inner facet by its own orientation, the same along an interface: Mesh::orient_boundary_facets_outward),
  // cancel in pairs inside each facet ref; those left bound the surface cavity.
  surface_sides_.clear();
  const auto add_sides = [&](const typename Mesh<D>::Facet& vertices, Index facet, bool inner) {
    const int ref = mesh.facet_ref(facet);
    if constexpr (D == 2) {
      surface_sides_.push_back({vertices[0], kNoIndex, ref, facet, inner, false});
      surface_sides_.push_back({kNoIndex, vertices[1], ref, facet, inner, false});
    } else {
      for (int i = 0; i < 3; ++i) surface_sides_.push_back({vertices[i], vertices[(i + 1) % 3], ref, facet, inner, false});
    }
  };
  for (const BoundaryFace& face : boundary_faces_)
    if (face.removed) add_sides(face.vertices, face.facet, false);
  for (const InnerFacet& inner : inner_facets_) add_sides(mesh.facet(inner.facet), inner.facet, true);
  const auto cancels = [](const SurfaceSide& x, const SurfaceSide& y) {
    return x.ref == y.ref && x.inner == y.inner &&
           (D == 2 ? (x.from == y.to && x.from != kNoIndex) || (x.to == y.from && x.to != kNoIndex) : x.from == y.to && x.to == y.from);
  };
  for (std::size_t i = 0; i < surface_sides_.size(); ++i)
    for (std::size_t j = i + 1; j < surface_sides_.size() && !surface_sides_[i].cancelled; ++j)
      if (!surface_sides_[j].cancelled && cancels(surface_sides_[i], surface_sides_[j]))
        surface_sides_[i].cancelled = surface_sides_[j].cancelled = true;
}

template <int D>
CavityStatus CavityOperator<D>::star_surface(const Mesh<D>& mesh, const CavityOptions& options) {
  // The sides bounding the surface cavity are starred from the vertex, except those through it and
  // (3D) the removed lines, which the line star replaces.
  new_facets_.clear();
  new_lines_.clear();
  if (removed_facets_.empty()) return CavityStatus::kAccepted;
  collect_surface_sides(mesh);
  for (const SurfaceSide& side : surface_sides_) {
    if (side.cancelled || side.from == vertex_ || side.to == vertex_) continue;
    if constexpr (D == 2) {
      const typename Mesh<D>::Facet facet = side.from != kNoIndex ? typename Mesh<D>::Facet{side.from, vertex_}
                                                                  : typename Mesh<D>::Facet{vertex_, side.to};
      new_facets_.push_back({facet, side.ref, side.facet, side.inner});
    } else {
      if (is_removed_line(mesh, side.from, side.to)) continue;
      new_facets_.push_back({{side.from, side.to, vertex_}, side.ref, side.facet, side.inner});
    }
  }
  // Two patches starring their shared side would stack two facets on one face.
  scratch_keys_.clear();
  for (const NewFacet& facet : new_facets_) scratch_keys_.push_back(ridge_key<D>(facet.vertices.data(), vertex_));
  std::sort(scratch_keys_.begin(), scratch_keys_.end());
  if (std::adjacent_find(scratch_keys_.begin(), scratch_keys_.end()) != scratch_keys_.end()) return CavityStatus::kNotStarShaped;
  if constexpr (D == 3) star_lines(mesh, options.removed_lines);
  return CavityStatus::kAccepted;
}

template <int D>
bool CavityOperator<D>::is_removed_line(const Mesh<D>& mesh, Index a, Index b) const {
  const std::uint64_t key = Mesh<D>::edge_key(a, b);
  for (Index l : removed_lines_)
    if (Mesh<D>::edge_key(mesh.line(l)[0], mesh.line(l)[1]) == key) return true;
  return false;
}

template <int D>
void CavityOperator<D>::star_lines(const Mesh<D>& mesh, std::span<const Index> removed_lines) {
  // Ends met once among the removed lines bound the chain; each is joined to the vertex.
  for (Index l : removed_lines)
    for (int side = 0; side < 2; ++side) {
      const Index end = mesh.line(l)[side];
      int count = 0;
      for (Index other : removed_lines) count += (mesh.line(other)[0] == end) + (mesh.line(other)[1] == end);
      if (count == 1 && end != vertex_) new_lines_.push_back({{vertex_, end}, mesh.line_ref(l), mesh.is_ridge(l)});
    }
}

template <int D>
CavityStatus CavityOperator<D>::match_ridges() {
  // Faces through the vertex pair up: two new elements, or a new element and a kept boundary
  // face; anything else leaves a hole or a fold, so the star is refused.
  ridge_faces_.clear();
  for (std::size_t n = 0; n < new_elements_.size(); ++n)
    for (int face = 1; face <= D; ++face) {
      Index vertices[D];
      for (int i = 0; i < D; ++i) vertices[i] = new_elements_[n][face_vertices<D>(face)[i]];
      ridge_faces_.push_back({ridge_key<D>(vertices, vertex_), static_cast<Index>(n), face});
    }
  for (std::size_t f = 0; f < boundary_faces_.size(); ++f) {
    const auto& face = boundary_faces_[f].vertices;
    if (boundary_faces_[f].removed || std::find(face.begin(), face.end(), vertex_) == face.end()) continue;
    ridge_faces_.push_back({ridge_key<D>(face.data(), vertex_), kNoIndex, static_cast<int>(f)});
  }
  for (std::size_t f = 0; f < new_facets_.size(); ++f)
    if (!new_facets_[f].inner)  // an inner facet lies between two new elements: placed on their link
      ridge_faces_.push_back(
          {ridge_key<D>(new_facets_[f].vertices.data(), vertex_), kNoIndex, static_cast<int>(boundary_faces_.size() + f)});
  links_.clear();
  if (!pair_ridge_faces()) return CavityStatus::kNotStarShaped;
  // New facets are appended in the links' order: by key, so that it does not depend on the table.
  if (!new_facets_.empty()) std::sort(links_.begin(), links_.end(), [](const Link& x, const Link& y) { return x.key < y.key; });
  if (!inner_facets_.empty() && !place_inner_facets()) return CavityStatus::kMixedRefs;
  return CavityStatus::kAccepted;
}

template <int D>
const typename CavityOperator<D>::InnerFacet& CavityOperator<D>::replaced_inner_facet(const NewFacet& facet) const {
  return *std::find_if(inner_facets_.begin(), inner_facets_.end(), [&](const InnerFacet& f) { return f.facet == facet.replaced; });
}

template <int D>
bool CavityOperator<D>::place_inner_facets() {
  const auto refs_of = [&](const Link& link) {
    const int one = new_element_refs_[static_cast<std::size_t>(link.new_element)];
    const int other = new_element_refs_[static_cast<std::size_t>(link.other_new_element)];
    return std::array<int, 2>{std::min(one, other), std::max(one, other)};
  };
  for (std::size_t f = 0; f < new_facets_.size(); ++f) {
    if (!new_facets_[f].inner) continue;
    const std::uint64_t key = ridge_key<D>(new_facets_[f].vertices.data(), vertex_);
    const auto link = std::lower_bound(links_.begin(), links_.end(), key, [](const Link& l, std::uint64_t k) { return l.key < k; });
    if (link == links_.end() || link->key != key || link->new_element == kNoIndex || link->other_new_element == kNoIndex) return false;
    if (refs_of(*link) != replaced_inner_facet(new_facets_[f]).refs) return false;  // the interface moved into a side
    link->inner_facet = static_cast<int>(f);
  }
  return std::none_of(links_.begin(), links_.end(), [&](const Link& link) {
    if (link.new_element == kNoIndex || link.other_new_element == kNoIndex || link.inner_facet >= 0) return false;
    const std::array<int, 2> refs = refs_of(link);
    return refs[0] != refs[1];  // two sides meeting without a facet
  });
}

template <int D>
bool CavityOperator<D>::pair_ridge_faces() {
  // An open-addressing table of the faces by key (a sort cost more than the rest of the plan's
  // bookkeeping): each key must come exactly twice.
  std::size_t size = 16;
  while (size < 2 * ridge_faces_.size()) size *= 2;
  ridge_slots_.assign(size, -1);
  ridge_partner_.assign(ridge_faces_.size(), -1);
  for (std::size_t i = 0; i < ridge_faces_.size(); ++i) {
    std::size_t slot = (ridge_faces_[i].key * 0x9E3779B97F4A7C15ull) >> 40 & (size - 1);
    while (ridge_slots_[slot] >= 0 && ridge_faces_[static_cast<std::size_t>(ridge_slots_[slot])].key != ridge_faces_[i].key)
      slot = (slot + 1) & (size - 1);
    if (ridge_slots_[slot] < 0) {
      ridge_slots_[slot] = static_cast<int>(i);
      continue;
    }
    const auto j = static_cast<std::size_t>(ridge_slots_[slot]);
    if (ridge_partner_[j] >= 0) return false;  // a third face through the same ridge: a fold
    ridge_partner_[j] = static_cast<int>(i);
    RidgeFace first = ridge_faces_[j], second = ridge_faces_[i];
    if (first.new_element == kNoIndex) std::swap(first, second);
    if (first.new_element == kNoIndex) {
      if (first.face > second.face) std::swap(first, second);  // the kept face, then the new facet
      if (!exposable(first, second)) return false;             // two kept faces: a hole
      links_.push_back({first.key, kNoIndex, second.face, kNoIndex, -1, first.face, -1});
      continue;
    }
    if (second.new_element == kNoIndex)
      links_.push_back({first.key, first.new_element, first.face, kNoIndex, -1, second.face, -1});
    else
      links_.push_back({first.key, first.new_element, first.face, second.new_element, second.face, -1, -1});
  }
  return 2 * links_.size() == ridge_faces_.size();  // else a face is unpaired: a hole
}

template <int D>
bool CavityOperator<D>::exposable(const RidgeFace& kept, const RidgeFace& facet) const {
  const auto faces = static_cast<int>(boundary_faces_.size());
  if (!exposes_faces_ || kept.face >= faces || facet.face < faces) return false;
  const BoundaryFace& face = boundary_faces_[static_cast<std::size_t>(kept.face)];
  return face.outer_element != kNoIndex && face.facet == kNoIndex;
}

template <int D>
bool CavityOperator<D>::exposed_edges_inside(const Mesh<D>& mesh) {
  if constexpr (D == 3) {
    const auto removed_side = [&](Index u, Index v) {
      return std::any_of(surface_sides_.begin(), surface_sides_.end(),
                         [&](const SurfaceSide& s) { return (s.from == u && s.to == v) || (s.from == v && s.to == u); });
    };
    for (const Link& link : links_) {
      if (link.new_element != kNoIndex) continue;
      const auto& face = boundary_faces_[static_cast<std::size_t>(link.kept_face)].vertices;
      for (int i = 0; i < 3; ++i) {
        const Index u = face[i], v = face[(i + 1) % 3];
        if (removed_side(u, v)) continue;  // on the boundary already, its removed facet replaced
        collect_shell(mesh, u, v, ball_);
        if (!shell_is_closed<D>(mesh, ball_, u, v)) return false;
      }
    }
  }
  return true;
}

template <int D>
void CavityOperator<D>::expose(Mesh<D>& mesh, const BoundaryFace& face, const NewFacet& facet) const {
  mesh.set_neighbor(face.outer_element, face.outer_face, kNoIndex);
  mesh.add_attached_facet(facet.vertices, facet.ref, face.outer_element, face.outer_face);
  for (Index v : face.vertices) mesh.set_vertex_element(v, face.outer_element);
}

template <int D>
CavityStatus CavityOperator<D>::plan_edges(const Mesh<D>& mesh) {
  // The boundary faces' edges, their ids from the cavity elements the faces belong to (no look-up),
  // kept sorted by key as they come: each is listed by two faces, so the list stays short. A
  // removed facet's face does not stay: an edge only on such faces (a split boundary edge, the
  // edges of a collapsed boundary vertex) goes with the cavity.
  boundary_edge_keys_.clear();
  boundary_edge_ids_.clear();
  for (const auto& face : boundary_faces_) {
    if (face.removed) continue;
    const auto& ids = mesh.element_edges(face.inner_element);
    const auto& local = face_vertices<D>(face.inner_face);
    for (int i = 0; i < D; ++i)
      for (int j = 0; j < i; ++j) {
        const std::uint64_t key = Mesh<D>::edge_key(face.vertices[i], face.vertices[j]);
        const auto at = std::lower_bound(boundary_edge_keys_.begin(), boundary_edge_keys_.end(), key);
        if (at != boundary_edge_keys_.end() && *at == key) continue;
        boundary_edge_ids_.insert(boundary_edge_ids_.begin() + (at - boundary_edge_keys_.begin()), ids[kLocalEdge<D>(local[i], local[j])]);
        boundary_edge_keys_.insert(at, key);
      }
  }

  // The cavity's other edges are removed (keys from the elements' vertices, not the edge table).
  // Searched only when neither a boundary face of their element nor an inner vertex decides.
  keyed_edges_.clear();
  for (std::size_t position = 0; position < cavity_.size(); ++position) {
    const Element& element = mesh.element(cavity_[position]);
    const auto& ids = mesh.element_edges(cavity_[position]);
    for (int e = 0; e < Mesh<D>::kElementEdges; ++e) {
      const auto [p, q] = edge_vertices<D>(e);
      if (boundary_face_bits_[position] & ~(1u << p) & ~(1u << q)) continue;
      const bool through_inner_vertex = !vertex_on_boundary_ && (element[p] == vertex_ || element[q] == vertex_);
      const std::uint64_t key = Mesh<D>::edge_key(element[p], element[q]);
      if (through_inner_vertex || boundary_edge_slot(key) == boundary_edge_keys_.size()) keyed_edges_.push_back({key, ids[e]});
    }
  }
  // Each is listed by several elements: a linear search among the few kept, then a short sort.
  for (const KeyedEdge& edge : keyed_edges_)
    if (std::none_of(removed_edges_.begin(), removed_edges_.end(), [&](const KeyedEdge& e) { return e.id == edge.id; })) {
      removed_edges_.push_back(edge);
      if (mesh.is_p2()) __builtin_prefetch(&mesh.edge_node(edge.id));  // the start of a recreated edge
    }
  std::sort(removed_edges_.begin(), removed_edges_.end(), [](const KeyedEdge& x, const KeyedEdge& y) { return x.id < y.id; });

  // The new elements' edges: the face's from its cavity element, the others through the vertex.
  new_element_edges_.resize(new_elements_.size());
  for (std::size_t n = 0; n < new_elements_.size(); ++n) {
    const BoundaryFace& face = boundary_faces_[starred_faces_[n]];
    auto& edges = new_element_edges_[n];
    const auto& ids = mesh.element_edges(face.inner_element);
    const auto& local = face_vertices<D>(face.inner_face);
    for (int i = 0; i < D; ++i)
      for (int j = 0; j < i; ++j) edges[kLocalEdge<D>(i + 1, j + 1)] = ids[kLocalEdge<D>(local[i], local[j])];
    for (int i = 0; i < D; ++i) {
      const Index v = face.vertices[i];
      Index& edge = edges[kLocalEdge<D>(0, i + 1)];
      const std::uint64_t key = Mesh<D>::edge_key(vertex_, v);
      if (const std::size_t slot = vertex_on_boundary_ ? boundary_edge_slot(key) : boundary_edge_keys_.size();
          slot < boundary_edge_keys_.size()) {
        edge = boundary_edge_ids_[slot];
        continue;
      }
      auto listed = std::find_if(new_inner_edges_.begin(), new_inner_edges_.end(), [&](const auto& e) { return e[1] == v; });
      edge = inner_edge_ref(static_cast<std::size_t>(listed - new_inner_edges_.begin()));
      if (listed != new_inner_edges_.end()) continue;
      new_inner_edges_.push_back({vertex_, v});
      // An inner edge the star recreates (a reinsertion) keeps its id: no edge-table churn. One
      // that exists outside the cavity would be created twice: the star folds over the mesh.
      auto removed = std::find_if(removed_edges_.begin(), removed_edges_.end(), [&](const KeyedEdge& e) { return e.key == key; });
      Index kept = kNoIndex;
      if (removed != removed_edges_.end()) {
        kept = removed->id;
        removed_edges_.erase(removed);
      } else if (mesh.find_edge(vertex_, v) != kNoIndex) {
        return CavityStatus::kNotStarShaped;
      }
      recreated_ids_.push_back(kept);
      start_nodes_.push_back(kept != kNoIndex && mesh.is_p2() ? mesh.edge_node(kept) : 0.5 * (mesh.vertex(vertex_) + mesh.vertex(v)));
    }
  }
  return CavityStatus::kAccepted;
}

template <int D>
std::size_t CavityOperator<D>::boundary_edge_slot(std::uint64_t key) const {
  auto found = std::lower_bound(boundary_edge_keys_.begin(), boundary_edge_keys_.end(), key);
  return found != boundary_edge_keys_.end() && *found == key ? static_cast<std::size_t>(found - boundary_edge_keys_.begin())
                                                             : boundary_edge_keys_.size();
}

template <int D>
Index CavityOperator<D>::boundary_edge(Index a, Index b) const {
  const std::size_t slot = boundary_edge_slot(Mesh<D>::edge_key(a, b));
  return slot < boundary_edge_ids_.size() ? boundary_edge_ids_[slot] : kNoIndex;
}

template <int D>
void CavityOperator<D>::commit(Mesh<D>& mesh, std::span<const Point> inner_edge_nodes,
                               std::span<const std::pair<Index, Point>> changed_boundary_nodes) {
  // Since the plan, other cavities may have pushed these records out of the cache: request them
  // all now so that their misses overlap.
  for (Index k : cavity_) mesh.prefetch_element(k);
  for (const BoundaryFace& face : boundary_faces_)
    if (face.outer_element != kNoIndex) mesh.prefetch_element(face.outer_element);
  const bool with_edges = mesh.has_edges() && mesh.edge_count() > 0;
  // Removed facets first: their links name cavity slots that the new elements take over.
  for (Index f : removed_facets_) mesh.remove_facet(f);
  for (Index l : removed_lines_) mesh.remove_line(l);
  for (const NewLine& line : new_lines_) {
    const Index id = mesh.add_line(line.vertices, line.ref);
    if (line.ridge) mesh.ridges().push_back(id);
  }
  if (with_edges) {
    for (const KeyedEdge& edge : removed_edges_) mesh.remove_edge(edge.id);
    inner_edge_ids_.clear();
    for (std::size_t i = 0; i < new_inner_edges_.size(); ++i) {
      const Point& node = i < inner_edge_nodes.size() ? inner_edge_nodes[i] : start_nodes_[i];
      if (recreated_ids_[i] == kNoIndex) {
        inner_edge_ids_.push_back(mesh.add_edge(new_inner_edges_[i][0], new_inner_edges_[i][1], node));
      } else {
        inner_edge_ids_.push_back(recreated_ids_[i]);
        if (mesh.is_p2()) mesh.edge_node(recreated_ids_[i]) = node;
      }
    }
    for (const auto& [edge, node] : changed_boundary_nodes) mesh.edge_node(edge) = node;
  }

  // New elements take the cavity's slots first, then new slots.
  new_element_ids_.assign(new_elements_.size(), kNoIndex);
  for (std::size_t n = 0; n < new_elements_.size(); ++n) {
    if (n < cavity_.size()) {
      new_element_ids_[n] = cavity_[n];
      mesh.set_element(cavity_[n], new_elements_[n], new_element_refs_[n]);
    } else {
      new_element_ids_[n] = mesh.append_element(new_elements_[n], new_element_refs_[n]);
    }
  }
  const std::vector<Index>& slot = new_element_ids_;
  for (std::size_t n = 0; n < new_elements_.size(); ++n) {
    const BoundaryFace& face = boundary_faces_[starred_faces_[n]];
    mesh.set_neighbor(slot[n], 0, face.outer_element);
    if (face.outer_element != kNoIndex) mesh.set_neighbor(face.outer_element, face.outer_face, slot[n]);
    if (face.facet != kNoIndex) mesh.attach_facet(face.facet, slot[n], 0);
    for (Index v : new_elements_[n]) mesh.set_vertex_element(v, slot[n]);
  }
  for (const Link& link : links_) {
    if (link.new_element == kNoIndex) {
      expose(mesh, boundary_faces_[static_cast<std::size_t>(link.kept_face)],
             new_facets_[static_cast<std::size_t>(link.face) - boundary_faces_.size()]);
      continue;
    }
    Index k = slot[link.new_element];
    if (link.other_new_element != kNoIndex) {
      mesh.set_neighbor(k, link.face, slot[link.other_new_element]);
      mesh.set_neighbor(slot[link.other_new_element], link.other_face, k);
      if (link.inner_facet >= 0) {  // linked from one side, either: a cavity finds it from the side that links it
        const NewFacet& facet = new_facets_[static_cast<std::size_t>(link.inner_facet)];
        mesh.add_attached_facet(facet.vertices, facet.ref, k, link.face);
      }
      continue;
    }
    if (static_cast<std::size_t>(link.kept_face) >= boundary_faces_.size()) {
      const NewFacet& facet = new_facets_[static_cast<std::size_t>(link.kept_face) - boundary_faces_.size()];
      mesh.set_neighbor(k, link.face, kNoIndex);
      mesh.add_attached_facet(facet.vertices, facet.ref, k, link.face);
      continue;
    }
    const BoundaryFace& kept = boundary_faces_[link.kept_face];
    mesh.set_neighbor(k, link.face, kept.outer_element);
    if (kept.outer_element != kNoIndex) mesh.set_neighbor(kept.outer_element, kept.outer_face, k);
    if (kept.facet != kNoIndex) mesh.attach_facet(kept.facet, k, link.face);
  }
  for (Index v : vanishing_vertices_) mesh.remove_vertex(v);
  if (with_edges)
    for (std::size_t n = 0; n < new_elements_.size(); ++n)
      for (int e = 0; e < Mesh<D>::kElementEdges; ++e) {
        const Index edge = new_element_edges_[n][e];
        mesh.set_element_edge(slot[n], e, edge >= 0 ? edge : inner_edge_ids_[inner_edge_of(edge)]);
      }

  // Cavity slots left over: fill each from the end of the array, highest first.
  for (std::size_t i = cavity_.size(); i-- > new_elements_.size();) {
    Index last = mesh.element_count() - 1;
    if (cavity_[i] != last) mesh.move_element(last, cavity_[i]);
    mesh.pop_element();
  }
}

template class CavityOperator<2>;
template class CavityOperator<3>;

}  // namespace hocav
