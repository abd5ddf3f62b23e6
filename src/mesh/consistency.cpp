#include "mesh/consistency.hpp"

#include <algorithm>
#include <cstdint>
#include <string>
#include <unordered_set>

#include "mesh/ball_and_shell.hpp"
#include "mesh/measure.hpp"

namespace hocav {
namespace {

template <int D>
std::array<Index, D> sorted_face(const typename Mesh<D>::Element& element, int face) {
  std::array<Index, D> out;
  for (int i = 0; i < D; ++i) out[i] = element[face_vertices<D>(face)[i]];
  std::sort(out.begin(), out.end());
  return out;
}

template <int D>
class Checker {
 public:
  Checker(const Mesh<D>& mesh, const ConsistencyOptions& options) : mesh_(mesh), options_(options) {}

  std::vector<std::string> run() {
    if (!check_elements()) return problems_;
    check_adjacency();
    check_vertex_elements();
    check_facets();
    if constexpr (D == 3) check_lines();
    if (mesh_.is_p2() || mesh_.edge_count() > 0) check_edges();
    return problems_;
  }

 private:
  bool full() const { return problems_.size() >= options_.max_problems; }
  void report(std::string problem) {
    if (!full()) problems_.push_back(std::move(problem));
  }

  bool check_elements() {
    for (Index k = 0; k < mesh_.element_count() && !full(); ++k) {
      auto e = mesh_.element(k);
      std::sort(e.begin(), e.end());
      if (std::adjacent_find(e.begin(), e.end()) != e.end())
        report("element " + one_based(k) + " repeats a vertex");
      else if (options_.require_positive_orientation && !(element_measure(mesh_, k) > 0))
        report("element " + one_based(k) + " has non-positive P1 measure " + std::to_string(element_measure(mesh_, k)));
    }
    if (!mesh_.has_topology() && mesh_.element_count() > 0) report("topology was not built");
    return problems_.empty() || mesh_.has_topology();
  }

  void check_adjacency() {
    for (Index k = 0; k < mesh_.element_count() && !full(); ++k)
      for (int face = 0; face <= D; ++face) {
        Index n = mesh_.neighbor(k, face);
        if (n == kNoIndex) {
          if (options_.require_boundary_facets && mesh_.element_face_facet(k, face) == kNoIndex)
            report("boundary face " + one_based(face) + " of element " + one_based(k) + " has no boundary facet");
          continue;
        }
        if (n < 0 || n >= mesh_.element_count()) {
          report("element " + one_based(k) + " has neighbor " + one_based(n) + " out of range");
          continue;
        }
        int back = -1;
        for (int g = 0; g <= D; ++g)
          if (mesh_.neighbor(n, g) == k) back = g;
        if (back < 0)
          report("adjacency is not symmetric between elements " + one_based(k) + " and " + one_based(n));
        else if (sorted_face<D>(mesh_.element(k), face) != sorted_face<D>(mesh_.element(n), back))
          report("elements " + one_based(k) + " and " + one_based(n) + " are neighbors but do not share the face");
        else if (!opposite_orientation(ordered_face(k, face), ordered_face(n, back)))
          report("elements " + one_based(k) + " and " + one_based(n) + " are not consistently oriented across their face");
      }
  }

  std::array<Index, D> ordered_face(Index k, int face) const {
    std::array<Index, D> out;
    for (int i = 0; i < D; ++i) out[i] = mesh_.element(k)[face_vertices<D>(face)[i]];
    return out;
  }

  // Two elements oriented alike see their common face in opposite cyclic orders.
  static bool opposite_orientation(const std::array<Index, D>& a, const std::array<Index, D>& b) {
    if constexpr (D == 2) return a[0] == b[1] && a[1] == b[0];  // an edge has a direction, not a cycle
    for (int shift = 0; shift < D; ++shift) {
      bool reversed = true;
      for (int i = 0; i < D; ++i) reversed = reversed && a[i] == b[(shift + D - i) % D];
      if (reversed) return true;
    }
    return false;
  }

  void check_vertex_elements() {
    std::vector<bool> used(static_cast<std::size_t>(mesh_.vertex_count()), false);
    for (const auto& e : mesh_.elements())
      for (Index v : e) used[v] = true;
    for (Index v = 0; v < mesh_.vertex_count() && !full(); ++v) {
      Index k = mesh_.vertex_element(v);
      if (mesh_.vertex_removed(v)) {
        if (used[v] || k != kNoIndex) report("removed vertex " + one_based(v) + " is still used");
      } else if (k == kNoIndex) {
        if (used[v]) report("vertex " + one_based(v) + " is used but has no incident element");
      } else if (k < 0 || k >= mesh_.element_count() || local_vertex(mesh_, k, v) < 0) {
        report("vertex " + one_based(v) + " points to element " + one_based(k) + " which does not contain it");
      }
    }
  }

  void check_facets() {
    for (Index f = 0; f < mesh_.facet_count() && !full(); ++f) {
      if (mesh_.facet_removed(f)) continue;
      Index slot = mesh_.facet_element_face(f);
      if (slot == kNoIndex) {
        report("boundary facet " + one_based(f) + " lies on no element face");
        continue;
      }
      Index k = slot / (D + 1);
      int face = static_cast<int>(slot % (D + 1));
      auto facet = mesh_.facet(f);
      std::sort(facet.begin(), facet.end());
      if (k >= mesh_.element_count() || sorted_face<D>(mesh_.element(k), face) != facet)
        report("boundary facet " + one_based(f) + " does not match face " + one_based(face) + " of element " + one_based(k));
      else if (mesh_.element_face_facet(k, face) != f)
        report("face " + one_based(face) + " of element " + one_based(k) + " does not lead back to boundary facet " + one_based(f));
    }
  }

  // A feature line is an edge of an element: of one around its first vertex, or else (the walk
  // from a vertex pinching two parts of the mesh sees one part: a distributed part may have such
  // vertices on its interface) of any element.
  void check_lines() {
    std::vector<Index> ball;
    std::unordered_set<std::uint64_t> element_edges;  // filled when a ball first misses a line
    for (Index l = 0; l < mesh_.line_count() && !full(); ++l) {
      if (mesh_.line_removed(l)) continue;
      const Index a = mesh_.line(l)[0], b = mesh_.line(l)[1];  // not a structured binding: the lambda below takes b
      if (a < 0 || a >= mesh_.vertex_count() || b < 0 || b >= mesh_.vertex_count() || mesh_.vertex_removed(a) || mesh_.vertex_removed(b)) {
        report("edge (line) " + one_based(l) + " has a vertex out of range or removed");
        continue;
      }
      if (mesh_.vertex_element(a) == kNoIndex) continue;  // a line on a vertex no element uses is the file's business
      collect_ball(mesh_, a, ball);
      if (std::any_of(ball.begin(), ball.end(), [&](Index k) { return local_vertex(mesh_, k, b) >= 0; })) continue;
      if (element_edges.empty())
        for (Index k = 0; k < mesh_.element_count(); ++k)
          for (int e = 0; e < Simplex<D>::kEdges; ++e)
            element_edges.insert(Mesh<D>::edge_key(mesh_.element(k)[edge_vertices<D>(e)[0]], mesh_.element(k)[edge_vertices<D>(e)[1]]));
      if (!element_edges.contains(Mesh<D>::edge_key(a, b)))
        report("edge (line) " + one_based(l) + " (" + one_based(a) + ", " + one_based(b) + ") is no element edge");
    }
  }

  void check_edges() {
    for (Index k = 0; k < mesh_.element_count() && !full(); ++k)
      for (int e = 0; e < Mesh<D>::kElementEdges; ++e) {
        Index a = mesh_.element(k)[edge_vertices<D>(e)[0]], b = mesh_.element(k)[edge_vertices<D>(e)[1]];
        Index edge = mesh_.element_edge(k, e);
        if (edge < 0 || edge >= mesh_.edge_count()) {
          report("element " + one_based(k) + " has edge id " + one_based(edge) + " out of range");
          continue;
        }
        // Every element of an edge refers to the one edge record, hence to the one P2 node.
        const auto& ends = mesh_.edge_vertices(edge);
        if (ends[0] != std::min(a, b) || ends[1] != std::max(a, b))
          report("local edge " + one_based(e) + " of element " + one_based(k) + " refers to edge " + one_based(edge) +
                 " of other vertices");
        else if (mesh_.find_edge(a, b) != edge)
          report("edge (" + one_based(a) + ", " + one_based(b) + ") of element " + one_based(k) + " is not the one the edge table finds");
      }
    std::vector<bool> used(static_cast<std::size_t>(mesh_.edge_count()), false);
    for (Index k = 0; k < mesh_.element_count(); ++k)
      for (Index edge : mesh_.element_edges(k))
        if (edge >= 0 && edge < mesh_.edge_count()) used[edge] = true;
    for (Index edge = 0; edge < mesh_.edge_count() && !full(); ++edge) {
      auto [a, b] = mesh_.edge_vertices(edge);
      if (a == kNoIndex) continue;  // a removed edge's id, waiting for reuse
      if (!used[edge])
        report("edge " + one_based(edge) + " (" + one_based(a) + ", " + one_based(b) + ") belongs to no element");
      else if (mesh_.find_edge(a, b) != edge)
        report("edge " + one_based(edge) + " is not where the edge table finds it");
      else if (mesh_.is_p2() && !is_finite(mesh_.edge_node(edge)))
        report("the P2 node of edge " + one_based(edge) + " is not finite");
    }
  }

  const Mesh<D>& mesh_;
  const ConsistencyOptions& options_;
  std::vector<std::string> problems_;
};

}  // namespace

template <int D>
std::vector<std::string> check_consistency(const Mesh<D>& mesh, const ConsistencyOptions& options) {
  return Checker<D>(mesh, options).run();
}

template std::vector<std::string> check_consistency(const Mesh<2>&, const ConsistencyOptions&);
template std::vector<std::string> check_consistency(const Mesh<3>&, const ConsistencyOptions&);

}  // namespace hocav
