// Mesh<D> storage, the P2 edge table and the derived topology.
#include "mesh/mesh.hpp"

#include <algorithm>
#include <array>
#include <string>

#include "base/element_list.hpp"
#include "base/error.hpp"
#include "mesh/baffle_orientation.hpp"

namespace hocav {

template <int D>
Index Mesh<D>::add_vertex(const Point& point, int ref) {
  Index id = checked_index(vertices_.size(), "vertices");
  vertices_.push_back(point);
  vertex_refs_.push_back(ref);
  if (vertex_element_.size() + 1 == vertices_.size()) vertex_element_.push_back(kNoIndex);
  if (!removed_vertices_.empty()) removed_vertices_.push_back(0);
  for (std::size_t a = 0; a < attributes_.size(); ++a)
    attributes_[a].resize(attributes_[a].size() + static_cast<std::size_t>(attribute_widths_[a]), 0.0);
  return id;
}

template <int D>
void Mesh<D>::pop_vertex() {
  vertices_.pop_back();
  vertex_refs_.pop_back();
  if (vertex_element_.size() > vertices_.size()) vertex_element_.pop_back();
  if (!removed_vertices_.empty()) removed_vertices_.pop_back();
  for (std::size_t a = 0; a < attributes_.size(); ++a)
    attributes_[a].resize(attributes_[a].size() - static_cast<std::size_t>(attribute_widths_[a]));
}

template <int D>
int Mesh<D>::add_vertex_attribute(int width) {
  attribute_widths_.push_back(width);
  attributes_.emplace_back(vertices_.size() * static_cast<std::size_t>(width), 0.0);
  return static_cast<int>(attributes_.size()) - 1;
}

template <int D>
void Mesh<D>::remove_vertex(Index v) {
  if (removed_vertices_.empty()) removed_vertices_.assign(vertices_.size(), 0);
  if (removed_vertices_[v]) return;
  removed_vertices_[v] = 1;
  ++removed_vertex_count_;
  if (static_cast<std::size_t>(v) < vertex_element_.size()) vertex_element_[v] = kNoIndex;
}

template <int D>
void Mesh<D>::remove_facet(Index f) {
  if (Index at = facet_element_face_[f]; at != kNoIndex && element_face_facets_.find(static_cast<std::uint64_t>(at)) == f)
    unlink_face_facet(at / (D + 1), at % (D + 1));
  facet_element_face_[f] = kNoIndex;
  facets_[f].fill(kNoIndex);
  ++removed_facet_count_;
}

template <int D>
void Mesh<D>::remove_line(Index l) {
  lines_[l].fill(kNoIndex);
  ++removed_line_count_;
}

template <int D>
Index Mesh<D>::add_attached_facet(const Facet& vertices, int ref, Index k, int face) {
  const Index f = add_facet(vertices, ref);
  facet_element_face_.push_back(kNoIndex);
  attach_facet(f, k, face);
  return f;
}

template <int D>
bool Mesh<D>::is_ridge(Index l) const {
  return std::find(ridges_.begin(), ridges_.end(), l) != ridges_.end();
}

template <int D>
Index Mesh<D>::add_element(const Element& vertices, int ref) {
  for (Index v : vertices)
    if (v < 0 || v >= vertex_count())
      throw Error("element " + one_based(elements_.size()) + " has vertex " + one_based(v) + " out of range");
  Index id = checked_index(elements_.size(), "elements");
  elements_.push_back(vertices);
  element_refs_.push_back(ref);
  for (ElementAttribute& attribute : element_attributes_) attribute.values.push_back(attribute.initial);
  return id;
}

template <int D>
int Mesh<D>::add_element_attribute(double initial) {
  element_attributes_.push_back({initial, std::vector<double>(elements_.size(), initial)});
  return static_cast<int>(element_attributes_.size()) - 1;
}

template <int D>
Index Mesh<D>::add_facet(const Facet& vertices, int ref) {
  for (Index v : vertices)
    if (v < 0 || v >= vertex_count())
      throw Error("boundary facet " + one_based(facets_.size()) + " has vertex " + one_based(v) + " out of range");
  Index id = checked_index(facets_.size(), "boundary facets");
  facets_.push_back(vertices);
  facet_refs_.push_back(ref);
  return id;
}

template <int D>
Index Mesh<D>::add_line(const Line& vertices, int ref) {
  for (Index v : vertices)
    if (v < 0 || v >= vertex_count()) throw Error("edge " + one_based(lines_.size()) + " has vertex " + one_based(v) + " out of range");
  Index id = checked_index(lines_.size(), "edges");
  lines_.push_back(vertices);
  line_refs_.push_back(ref);
  return id;
}

template <int D>
Index Mesh<D>::insert_edge(Index a, Index b) {
  Index candidate = static_cast<Index>(edge_vertices_.size());
  Index id = edge_ids_.insert(edge_key(a, b), candidate);
  if (id == candidate) {
    checked_index(edge_vertices_.size() + 1, "edges");
    edge_vertices_.push_back({std::min(a, b), std::max(a, b)});
  }
  return id;
}

namespace {

// Vertex -> incident elements in compressed rows (offsets, then element ids).
template <int D>
void build_vertex_elements(const Mesh<D>& mesh, std::vector<Index>& offsets, std::vector<Index>& incident) {
  offsets.assign(static_cast<std::size_t>(mesh.vertex_count()) + 1, 0);
  for (const auto& element : mesh.elements())
    for (Index v : element) ++offsets[static_cast<std::size_t>(v) + 1];
  for (std::size_t v = 0; v + 1 < offsets.size(); ++v) offsets[v + 1] += offsets[v];
  incident.resize(static_cast<std::size_t>(offsets.back()));
  std::vector<Index> fill(offsets.begin(), offsets.end() - 1);
  for (Index k = 0; k < mesh.element_count(); ++k)
    for (Index v : mesh.element(k)) incident[static_cast<std::size_t>(fill[v]++)] = k;
}

}  // namespace

template <int D>
void Mesh<D>::build_edges() {
  edge_vertices_.clear();
  edge_ids_.clear();
  free_edges_.clear();
  // Euler: a tetrahedral mesh has about 1.2 edges per element, a triangular one about 1.5.
  edge_ids_.reserve(elements_.size() * (D == 3 ? 13 : 16) / 10 + facets_.size() + lines_.size());
  edge_vertices_.reserve(elements_.size() * (D == 3 ? 13 : 16) / 10);
  element_edges_.resize(elements_.size());
  // Edges are numbered by their smaller vertex, then the larger: each vertex collects the edges of
  // its ball that start at it, so every edge is inserted in the table once, not once per element.
  std::vector<Index> offsets, incident;
  build_vertex_elements(*this, offsets, incident);
  std::vector<Index> ends;
  for (Index v = 0; v < vertex_count(); ++v) {
    ends.clear();
    for (Index slot = offsets[v]; slot < offsets[v + 1]; ++slot)
      for (Index w : elements_[incident[slot]])
        if (w > v) ends.push_back(w);
    std::sort(ends.begin(), ends.end());
    ends.erase(std::unique(ends.begin(), ends.end()), ends.end());
    Index first = static_cast<Index>(edge_vertices_.size());
    for (Index w : ends) insert_edge(v, w);
    for (Index slot = offsets[v]; slot < offsets[v + 1]; ++slot) {
      Index k = incident[slot];
      for (int e = 0; e < kElementEdges; ++e) {
        const auto& local = hocav::edge_vertices<D>(e);
        Index a = elements_[k][local[0]], b = elements_[k][local[1]];
        if (std::min(a, b) != v) continue;
        if (a == b) {  // a degenerate element (the checker reports it) still gets an edge
          element_edges_[k][e] = insert_edge(a, b);
          continue;
        }
        auto rank = std::lower_bound(ends.begin(), ends.end(), std::max(a, b)) - ends.begin();
        element_edges_[k][e] = first + static_cast<Index>(rank);
      }
    }
  }
  // Boundary and feature edges are element edges in a conforming mesh; inserting them too keeps
  // the table complete for meshes that carry a facet or line no element touches.
  for (const Facet& f : facets_)
    for (int i = 0; i < D; ++i)
      if (D == 3 || i == 0) insert_edge(f[i], f[(i + 1) % D]);
  for (const Line& l : lines_) insert_edge(l[0], l[1]);
}

template <int D>
void Mesh<D>::make_p2() {
  if (order_ == 2 && edge_nodes_.size() == edge_vertices_.size()) return;
  build_edges();
  edge_nodes_.resize(edge_vertices_.size());
  for (std::size_t e = 0; e < edge_vertices_.size(); ++e)
    edge_nodes_[e] = 0.5 * (vertices_[edge_vertices_[e][0]] + vertices_[edge_vertices_[e][1]]);
  order_ = 2;
}

template <int D>
void Mesh<D>::forget_edges() {
  make_p1();
  edge_vertices_ = {};
  element_edges_ = {};
  edge_ids_.clear();
  free_edges_ = {};
}

template <int D>
void Mesh<D>::make_p1() {
  edge_nodes_.clear();
  edge_nodes_.shrink_to_fit();
  order_ = 1;
}

namespace {

template <int D>
bool element_has_vertices(const typename Mesh<D>::Element& element, const Index* vertices, int count) {
  for (int i = 0; i < count; ++i)
    if (std::find(element.begin(), element.end(), vertices[i]) == element.end()) return false;
  return true;
}

// The local face of `element` made of exactly these D vertices, or -1.
template <int D>
int local_face_of(const typename Mesh<D>::Element& element, const Index* vertices) {
  for (int face = 0; face <= D; ++face)
    if (std::find(vertices, vertices + D, element[face]) == vertices + D && element_has_vertices<D>(element, vertices, D)) return face;
  return -1;
}

// A face of an element seen from its smallest vertex: the D - 1 other vertices, sorted.
template <int D>
struct FaceAtVertex {
  std::array<Index, D - 1> others;
  Index element;
  int face;
};

}  // namespace

template <int D>
void Mesh<D>::build_topology() {
  std::vector<Index> offsets, incident;
  build_vertex_elements(*this, offsets, incident);

  // Each face is matched once, at its smallest vertex v: the faces of v's ball whose smallest
  // vertex is v are sorted by their other vertices, so a shared face is two equal neighbours.
  Element boundary;
  boundary.fill(kNoIndex);
  adjacency_.assign(elements_.size(), boundary);
  std::vector<FaceAtVertex<D>> faces;
  for (Index v = 0; v < vertex_count(); ++v) {
    faces.clear();
    for (Index slot = offsets[v]; slot < offsets[v + 1]; ++slot) {
      Index k = incident[slot];
      for (int face = 0; face <= D; ++face) {
        FaceAtVertex<D> entry{{}, k, face};
        int count = 0;
        bool smallest = true;
        for (int i = 0; i < D; ++i) {
          Index w = elements_[k][hocav::face_vertices<D>(face)[i]];
          if (w == v) continue;
          smallest = smallest && w > v;
          if (count < D - 1) entry.others[count] = w;
          ++count;
        }
        if (count == D - 1 && smallest) {
          std::sort(entry.others.begin(), entry.others.end());
          faces.push_back(entry);
        }
      }
    }
    std::sort(faces.begin(), faces.end(), [](const auto& a, const auto& b) { return a.others < b.others; });
    for (std::size_t i = 0; i < faces.size();) {
      std::size_t j = i + 1;
      while (j < faces.size() && faces[j].others == faces[i].others) ++j;
      if (j - i > 2)
        throw Error("non-manifold mesh: the face of element " + one_based(faces[i].element) + " opposite its vertex " +
                    one_based(faces[i].face) + " is shared by more than two elements");
      Index across = j - i == 2 ? faces[i + 1].element : kNoIndex;
      adjacency_[faces[i].element][faces[i].face] = across;
      if (across != kNoIndex) adjacency_[across][faces[i + 1].face] = faces[i].element;
      i = j;
    }
  }

  vertex_element_.assign(vertices_.size(), kNoIndex);
  for (Index v = 0; v < vertex_count(); ++v)
    if (offsets[v] < offsets[v + 1]) vertex_element_[v] = incident[offsets[v]];

  facet_element_face_.assign(facets_.size(), kNoIndex);
  element_face_facets_.clear();
  element_face_facets_.reserve(facets_.size());
  faces_with_facet_.assign(elements_.size(), 0);
  for (Index f = 0; f < facet_count(); ++f) {
    const Facet& facet = facets_[f];
    Index v = facet[0];
    for (Index slot = offsets[v]; slot < offsets[v + 1] && facet_element_face_[f] == kNoIndex; ++slot) {
      int face = local_face_of<D>(elements_[incident[slot]], facet.data());
      if (face >= 0) facet_element_face_[f] = incident[slot] * (D + 1) + face;
    }
    if (facet_element_face_[f] == kNoIndex) throw Error("boundary facet " + one_based(f) + " is not a face of any element");
    link_face_facet(facet_element_face_[f] / (D + 1), facet_element_face_[f] % (D + 1), f);
  }
}

template <int D>
void Mesh<D>::link_facets() {
  std::vector<Index> ball, stack;
  for (auto f = static_cast<Index>(facet_element_face_.size()); f < facet_count(); ++f) {
    const Index found = facet_face(f, ball, stack);
    // As build_topology links it: from the smaller of the two elements across it.
    Index k = found / (D + 1);
    auto face = static_cast<int>(found % (D + 1));
    if (const Index across = adjacency_[k][face]; across != kNoIndex && across < k) {
      face = static_cast<int>(std::find(adjacency_[across].begin(), adjacency_[across].end(), k) - adjacency_[across].begin());
      k = across;
    }
    facet_element_face_.push_back(k * (D + 1) + face);
    link_face_facet(k, face, f);
  }
}

template <int D>
Index Mesh<D>::facet_face(Index f, std::vector<Index>& ball, std::vector<Index>& stack) const {
  const Facet& facet = facets_[f];
  // A vertex of a non-manifold place has balls the walk does not join: the facet's other vertices,
  // then every element.
  Index found = kNoIndex;
  for (int i = 0; i < D && found == kNoIndex; ++i) found = facet_face_near(facet, facet[i], ball, stack);
  for (Index k = 0; k < element_count() && found == kNoIndex; ++k)
    if (const int face = local_face_of<D>(elements_[k], facet.data()); face >= 0) found = k * (D + 1) + face;
  if (found == kNoIndex) throw Error("boundary facet " + one_based(f) + " is not a face of any element");
  return found;
}

template <int D>
void Mesh<D>::relink_facets_off_their_faces() {
  std::vector<Index> ball, stack;
  for (Index f = 0; f < facet_count(); ++f) {
    if (facet_removed(f)) continue;
    const Index at = facet_element_face_[f];
    const Index k = at == kNoIndex ? kNoIndex : at / (D + 1);
    if (k != kNoIndex && k < element_count() && local_face_of<D>(elements_[k], facets_[f].data()) == static_cast<int>(at % (D + 1)))
      continue;
    facet_element_face_[f] = facet_face(f, ball, stack);
  }
}

template <int D>
Index Mesh<D>::facet_face_near(const Facet& facet, Index center, std::vector<Index>& ball, std::vector<Index>& stack) const {
  ball.clear();
  ElementList seen(ball);  // (a frozen interface vertex's ball may hold thousands)
  stack.assign(1, vertex_element_.at(center));
  while (!stack.empty()) {
    const Index k = stack.back();
    stack.pop_back();
    if (k == kNoIndex || seen.holds(k)) continue;
    seen.push_back(k);
    if (const int face = local_face_of<D>(elements_[k], facet.data()); face >= 0) return k * (D + 1) + face;
    for (int face = 0; face <= D; ++face)
      if (elements_[k][face] != center) stack.push_back(adjacency_[k][face]);
  }
  return kNoIndex;
}

template <int D>
void Mesh<D>::orient_boundary_facets_outward() {
  for (Index f = 0; f < facet_count(); ++f) {
    if (facet_removed(f)) continue;
    const Index k = outward_element(f);
    if (k != kNoIndex) orient_facet_as_face(f, k, local_face_of<D>(elements_[k], facets_[f].data()));
  }
  for (Index f : baffle_facets_to_turn(*this)) turn_facet(f);
}

template <int D>
Index Mesh<D>::outward_element(Index f) const {
  const Index k = facet_element_face_[f] / (D + 1);
  const Index across = neighbor(k, static_cast<int>(facet_element_face_[f] % (D + 1)));
  // An interface: as a face of the side with the smaller ref, so that its facets agree (the cavity
  // operator's surface cavity needs them to).
  if (across == kNoIndex || element_refs_[k] < element_refs_[across]) return k;
  return element_refs_[across] < element_refs_[k] ? across : kNoIndex;
}

template <int D>
void Mesh<D>::orient_facet_as_face(Index f, Index k, int face, bool inward) {
  Facet outward;
  for (int i = 0; i < D; ++i) outward[i] = elements_[k][hocav::face_vertices<D>(face)[i]];
  Facet& facet = facets_[f];
  // The same orientation: 2D the same first vertex, 3D a rotation of the outward face.
  const auto first = static_cast<int>(std::find(facet.begin(), facet.end(), outward[0]) - facet.begin());
  const bool same = D == 2 ? first == 0 : facet[(first + 1) % D] == outward[1];
  if (same == inward) turn_facet(f);
}

template <int D>
Index Mesh<D>::append_element(const Element& vertices, int ref) {
  // Derived arrays that were complete before stay complete.
  bool had_topology = adjacency_.size() == elements_.size();
  bool had_edges = element_edges_.size() == elements_.size() && !edge_vertices_.empty();
  Index k = add_element(vertices, ref);
  if (had_topology) {
    Element none;
    none.fill(kNoIndex);
    adjacency_.push_back(none);
    faces_with_facet_.push_back(0);
  }
  if (had_edges) {
    ElementEdges none;
    none.fill(kNoIndex);
    element_edges_.push_back(none);
  }
  return k;
}

template <int D>
void Mesh<D>::move_element(Index from, Index to) {
  elements_[to] = elements_[from];
  element_refs_[to] = element_refs_[from];
  for (ElementAttribute& attribute : element_attributes_) attribute.values[to] = attribute.values[from];
  if (!element_edges_.empty()) element_edges_[to] = element_edges_[from];
  adjacency_[to] = adjacency_[from];
  for (int face = 0; face <= D; ++face) {
    Index n = adjacency_[to][face];
    if (n != kNoIndex)
      for (int back = 0; back <= D; ++back)
        if (adjacency_[n][back] == from) adjacency_[n][back] = to;
    Index f = element_face_facet(from, face);
    if (f != kNoIndex) {
      unlink_face_facet(from, face);
      attach_facet(f, to, face);
    }
  }
  for (Index v : elements_[to])
    if (vertex_element_[v] == from) vertex_element_[v] = to;
}

template <int D>
void Mesh<D>::pop_element() {
  elements_.pop_back();
  element_refs_.pop_back();
  for (ElementAttribute& attribute : element_attributes_) attribute.values.pop_back();
  adjacency_.pop_back();
  faces_with_facet_.pop_back();
  if (!element_edges_.empty()) element_edges_.pop_back();
}

template <int D>
void Mesh<D>::attach_facet(Index f, Index k, int face) {
  Index old = facet_element_face_[f];
  if (old != kNoIndex && element_face_facets_.find(static_cast<std::uint64_t>(old)) == f) unlink_face_facet(old / (D + 1), old % (D + 1));
  facet_element_face_[f] = k * (D + 1) + face;
  link_face_facet(k, face, f);
}

template <int D>
void Mesh<D>::link_face_facet(Index k, int face, Index f) {
  element_face_facets_.assign(face_key(k, face), f);
  faces_with_facet_[k] = static_cast<std::uint8_t>(faces_with_facet_[k] | (1u << face));
}

template <int D>
void Mesh<D>::unlink_face_facet(Index k, int face) {
  element_face_facets_.erase(face_key(k, face));
  faces_with_facet_[k] = static_cast<std::uint8_t>(faces_with_facet_[k] & ~(1u << face));
}

template <int D>
Index Mesh<D>::add_edge(Index a, Index b, const Point& node) {
  Index id;
  if (!free_edges_.empty()) {
    id = free_edges_.back();
    free_edges_.pop_back();
    edge_vertices_[id] = {std::min(a, b), std::max(a, b)};
  } else {
    id = checked_index(edge_vertices_.size(), "edges");
    edge_vertices_.push_back({std::min(a, b), std::max(a, b)});
    if (order_ == 2) edge_nodes_.emplace_back();
  }
  if (order_ == 2) edge_nodes_[id] = node;
  edge_ids_.assign(edge_key(a, b), id);
  return id;
}

template <int D>
void Mesh<D>::remove_edge(Index e) {
  edge_ids_.erase(edge_key(edge_vertices_[e][0], edge_vertices_[e][1]));
  edge_vertices_[e] = {kNoIndex, kNoIndex};
  free_edges_.push_back(e);
}

template <int D>
void Mesh<D>::compact_edges() {
  if (free_edges_.empty()) return;
  std::vector<Index> new_id(edge_vertices_.size(), kNoIndex);
  Index next = 0;
  for (std::size_t e = 0; e < edge_vertices_.size(); ++e) {
    if (edge_vertices_[e][0] == kNoIndex) continue;
    new_id[e] = next;
    edge_vertices_[next] = edge_vertices_[e];
    if (order_ == 2) edge_nodes_[next] = edge_nodes_[e];
    ++next;
  }
  edge_vertices_.resize(static_cast<std::size_t>(next));
  if (order_ == 2) edge_nodes_.resize(static_cast<std::size_t>(next));
  for (auto& row : element_edges_)
    for (Index& e : row) e = new_id[e];
  edge_ids_.clear();
  for (Index e = 0; e < next; ++e) edge_ids_.assign(edge_key(edge_vertices_[e][0], edge_vertices_[e][1]), e);
  free_edges_.clear();
}

namespace {

// Keeps the entries whose `keep` is true, in order; returns each old position's new one.
template <typename Row, typename Keep>
std::vector<Index> compact_rows(std::vector<Row>& rows, Keep keep) {
  std::vector<Index> new_id(rows.size(), kNoIndex);
  Index next = 0;
  for (std::size_t i = 0; i < rows.size(); ++i)
    if (keep(i)) {
      new_id[i] = next;
      rows[static_cast<std::size_t>(next++)] = rows[i];
    }
  rows.resize(static_cast<std::size_t>(next));
  return new_id;
}

// Applies a renumbering to a list of ids, dropping the removed ones.
void renumber_list(std::vector<Index>& ids, const std::vector<Index>& new_id) {
  std::vector<Index> kept;
  for (Index id : ids)
    if (new_id[id] != kNoIndex) kept.push_back(new_id[id]);
  ids = std::move(kept);
}

}  // namespace

template <int D>
std::vector<Index> Mesh<D>::compact() {
  compact_edges();
  const auto live_vertex = [&](std::size_t v) { return !vertex_removed(static_cast<Index>(v)); };
  std::vector<Index> vertex_id = compact_rows(vertices_, live_vertex);
  const auto keep_vertex = [&](std::size_t v) { return vertex_id[v] != kNoIndex; };
  compact_rows(vertex_refs_, keep_vertex);
  if (vertex_element_.size() == vertex_id.size()) compact_rows(vertex_element_, keep_vertex);
  for (std::size_t a = 0; a < attributes_.size(); ++a) {
    const auto w = static_cast<std::size_t>(attribute_widths_[a]);
    std::vector<double>& rows = attributes_[a];
    for (std::size_t v = 0; v < vertex_id.size(); ++v)
      if (vertex_id[v] != kNoIndex)
        std::copy_n(rows.begin() + static_cast<std::ptrdiff_t>(v * w), w,
                    rows.begin() + static_cast<std::ptrdiff_t>(static_cast<std::size_t>(vertex_id[v]) * w));
    rows.resize(vertices_.size() * w);
  }
  removed_vertices_.clear();
  removed_vertex_count_ = 0;
  for (Element& e : elements_)
    for (Index& v : e) v = vertex_id[v];
  for (auto& edge : edge_vertices_)
    for (Index& v : edge) v = vertex_id[v];
  renumber_list(corners_, vertex_id);
  renumber_list(required_vertices_, vertex_id);

  const auto live_facet = [&](std::size_t f) { return facets_[f][0] != kNoIndex; };
  std::vector<Index> facet_id(facets_.size());
  for (std::size_t f = 0; f < facets_.size(); ++f) facet_id[f] = live_facet(f) ? 0 : kNoIndex;
  compact_rows(facet_refs_, [&](std::size_t f) { return facet_id[f] != kNoIndex; });
  if (facet_element_face_.size() == facet_id.size())
    compact_rows(facet_element_face_, [&](std::size_t f) { return facet_id[f] != kNoIndex; });
  facet_id = compact_rows(facets_, live_facet);
  for (Facet& f : facets_)
    for (Index& v : f) v = vertex_id[v];
  removed_facet_count_ = 0;

  const auto live_line = [&](std::size_t l) { return lines_[l][0] != kNoIndex; };
  std::vector<Index> line_id(lines_.size());
  for (std::size_t l = 0; l < lines_.size(); ++l) line_id[l] = live_line(l) ? 0 : kNoIndex;
  compact_rows(line_refs_, [&](std::size_t l) { return line_id[l] != kNoIndex; });
  line_id = compact_rows(lines_, live_line);
  for (Line& l : lines_)
    for (Index& v : l) v = vertex_id[v];
  removed_line_count_ = 0;
  renumber_list(ridges_, D == 2 ? facet_id : line_id);
  renumber_list(required_edges_, D == 2 ? facet_id : line_id);
  renumber_list(required_triangles_, facet_id);

  if (has_topology() && facet_element_face_.size() == facets_.size()) relink_facets_off_their_faces();
  rekey_after_renumbering();
  return vertex_id;
}

namespace {

// Moves rows[i] to rows[new_id[i]] (a permutation).
template <typename Row>
void permute_rows(std::vector<Row>& rows, std::span<const Index> new_id) {
  std::vector<Row> moved(rows.size());
  for (std::size_t i = 0; i < rows.size(); ++i) moved[static_cast<std::size_t>(new_id[i])] = rows[i];
  rows = std::move(moved);
}

// The same for rows of `width` values each.
void permute_wide_rows(std::vector<double>& rows, std::size_t width, std::span<const Index> new_id) {
  std::vector<double> moved(rows.size());
  for (std::size_t i = 0; i < new_id.size(); ++i)
    std::copy_n(rows.begin() + static_cast<std::ptrdiff_t>(i * width), width,
                moved.begin() + static_cast<std::ptrdiff_t>(static_cast<std::size_t>(new_id[i]) * width));
  rows = std::move(moved);
}

// Renames every id of these records (kNoIndex stays).
template <typename Records>
void rename_ids(Records& records, std::span<const Index> new_id) {
  for (auto& record : records)
    for (Index& id : record)
      if (id != kNoIndex) id = new_id[static_cast<std::size_t>(id)];
}

}  // namespace

template <int D>
void Mesh<D>::renumber(std::span<const Index> new_vertex_id, std::span<const Index> new_element_id) {
  if (has_topology() && facet_element_face_.size() == facets_.size()) relink_facets_off_their_faces();  // (their links are renamed below)
  permute_rows(vertices_, new_vertex_id);
  permute_rows(vertex_refs_, new_vertex_id);
  for (std::size_t a = 0; a < attributes_.size(); ++a)
    permute_wide_rows(attributes_[a], static_cast<std::size_t>(attribute_widths_[a]), new_vertex_id);
  rename_ids(elements_, new_vertex_id);
  rename_ids(facets_, new_vertex_id);
  rename_ids(lines_, new_vertex_id);
  rename_ids(edge_vertices_, new_vertex_id);
  for (Line& ends : edge_vertices_)  // an edge record lists its smaller vertex first
    if (ends[0] > ends[1]) std::swap(ends[0], ends[1]);
  for (std::vector<Index>* tags : {&corners_, &required_vertices_})
    for (Index& v : *tags) v = new_vertex_id[static_cast<std::size_t>(v)];

  permute_rows(elements_, new_element_id);
  permute_rows(element_refs_, new_element_id);
  for (ElementAttribute& attribute : element_attributes_) permute_rows(attribute.values, new_element_id);
  if (!element_edges_.empty()) permute_rows(element_edges_, new_element_id);
  if (has_topology()) {
    permute_rows(adjacency_, new_element_id);
    rename_ids(adjacency_, new_element_id);
    permute_rows(faces_with_facet_, new_element_id);
    permute_rows(vertex_element_, new_vertex_id);
    for (Index& k : vertex_element_)
      if (k != kNoIndex) k = new_element_id[static_cast<std::size_t>(k)];
    for (Index& face : facet_element_face_)
      if (face != kNoIndex) face = new_element_id[static_cast<std::size_t>(face / (D + 1))] * (D + 1) + face % (D + 1);
  }
  rekey_after_renumbering();
}

template <int D>
void Mesh<D>::rekey_after_renumbering() {
  if (!edge_vertices_.empty()) {
    edge_ids_.clear();
    for (Index e = 0; e < edge_count(); ++e) edge_ids_.assign(edge_key(edge_vertices_[e][0], edge_vertices_[e][1]), e);
  }
  if (facet_element_face_.size() == facets_.size() && has_topology()) {
    element_face_facets_.clear();
    std::fill(faces_with_facet_.begin(), faces_with_facet_.end(), std::uint8_t{0});
    for (Index f = 0; f < facet_count(); ++f)
      if (facet_element_face_[f] != kNoIndex) link_face_facet(facet_element_face_[f] / (D + 1), facet_element_face_[f] % (D + 1), f);
  }
}

template <int D>
std::size_t Mesh<D>::memory_bytes() const {
  auto bytes = [](const auto& v) { return v.capacity() * sizeof(v[0]); };
  return bytes(vertices_) + bytes(vertex_refs_) + bytes(elements_) + bytes(element_refs_) + bytes(facets_) + bytes(facet_refs_) +
         bytes(lines_) + bytes(line_refs_) + bytes(corners_) + bytes(ridges_) + bytes(required_vertices_) + bytes(required_edges_) +
         bytes(required_triangles_) + bytes(removed_vertices_) + bytes(edge_vertices_) + bytes(edge_nodes_) + bytes(element_edges_) +
         edge_ids_.memory_bytes() + bytes(adjacency_) + bytes(vertex_element_) + bytes(facet_element_face_) +
         element_face_facets_.memory_bytes() + bytes(faces_with_facet_) + [&] {
           std::size_t total = 0;
           for (const auto& rows : attributes_) total += bytes(rows);
           for (const auto& attribute : element_attributes_) total += bytes(attribute.values);
           return total;
         }();
}

template class Mesh<2>;
template class Mesh<3>;

}  // namespace hocav
