#include "cavity/p2_operations.hpp"

#include <algorithm>

#include "base/small_set.hpp"
#include "bezier/p2_element.hpp"
#include "curve/curved_quality.hpp"
#include "mesh/ball_and_shell.hpp"
#include "metric/metric_quality.hpp"

namespace hocav {
namespace {

// Without the caller's guarantee on the whole mesh: every element an operation makes is certified
// (a moved vertex or a given start node changes elements whose vertex ids stay the same).
P2CavityOptions certifying_everything(P2CavityOptions options) {
  options.every_element_above_floor = false;
  return options;
}

// The point of the quadratic edge (a, node, b) at parameter t (node at t = 1/2).
template <int D>
Vec<D> point_on_edge(const Vec<D>& a, const Vec<D>& node, const Vec<D>& b, double t) {
  return (1 - t) * (1 - 2 * t) * a + 4 * t * (1 - t) * node + t * (2 * t - 1) * b;
}

// The measures' kinds in a memo's digests.
enum MeasureKind : std::uint64_t { kCurvedLength = 1, kStraightLength, kCurvedQuality };

// A segment's or curved edge's inputs: its ends, their log-metrics, the back element the field's
// search starts from, and the point where the field is sampled.
template <int D>
Digest edge_digest(MeasureKind kind, const Vec<D>& a, const Vec<D>& b, const SymMat<D>& log_a, const SymMat<D>& log_b, Index hint,
                   const Vec<D>& node) {
  Digest digest(kind);
  for (const Vec<D>* point : {&a, &b, &node}) digest.add_all(point->c);
  digest.add_all(log_a.entries);
  digest.add_all(log_b.entries);
  digest.add_word(static_cast<std::uint64_t>(hint));
  return digest;
}

}  // namespace

template <int D>
P2Operations<D>::P2Operations(Mesh<D>& mesh, const MetricField<D>& field, BoundaryNodeSource<D>* boundary, P2CavityOptions options,
                              DigestMemo* memo)
    : mesh_(mesh),
      field_(field),
      memo_(memo),
      straight_quality_floor_(options.straight_quality_floor),
      log_metrics_(static_cast<std::size_t>(mesh.vertex_count())),
      hints_(static_cast<std::size_t>(mesh.vertex_count()), kNoIndex),
      operator_(field, log_metrics_, hints_, nullptr, boundary, certifying_everything(options)) {
  LocatorScratch scratch;
  Index hint = kNoIndex;
  for (Index v = 0; v < mesh.vertex_count(); ++v) {
    const auto sample = field.sample(mesh.vertex(v), hint, scratch);
    log_metrics_[static_cast<std::size_t>(v)] = sample.log_metric;
    hints_[static_cast<std::size_t>(v)] = hint = sample.where.element;
  }
}

template <int D>
bool P2Operations<D>::on_boundary(std::span<const Index> elements, std::span<const Index> vertices) const {
  for (Index k : elements)
    for (int face = 0; face <= D; ++face) {
      std::size_t held = 0;
      for (int i = 0; i < D; ++i) held += small_set_holds(vertices, mesh_.element(k)[face_vertices<D>(face)[i]]);
      if (held == vertices.size() && (mesh_.neighbor(k, face) == kNoIndex || mesh_.element_face_facet(k, face) != kNoIndex)) return true;
    }
  return false;
}

template <int D>
Index P2Operations<D>::add_vertex(const Vec<D>& x, Index near) {
  const Index v = mesh_.add_vertex(x);
  const auto sample = field_.sample(x, hints_[static_cast<std::size_t>(near)]);
  log_metrics_.push_back(sample.log_metric);
  hints_.push_back(sample.where.element);
  return v;
}

template <int D>
void P2Operations<D>::remove_last_vertex() {
  mesh_.pop_vertex();
  log_metrics_.pop_back();
  hints_.pop_back();
}

template <int D>
double P2Operations<D>::straight_quality_to_keep(std::span<const Index> elements) const {
  if (straight_quality_floor_ <= 0) return -1;
  double floor = straight_quality_floor_;
  for (Index k : elements) floor = std::min(floor, straight_quality(k));
  return floor;
}

template <int D>
CavityStatus P2Operations<D>::split_edge(Index a, Index b, Index* inserted, Bar bar, const BoundaryPlacement<D>* boundary) {
  const Index edge = mesh_.find_edge(a, b);
  if (edge == kNoIndex) return CavityStatus::kNotStarShaped;
  collect_shell(mesh_, a, b, cavity_);
  const Index ends[2] = {a, b};
  if (!boundary && on_boundary(cavity_, ends)) return CavityStatus::kCrossesBoundary;
  // The new vertex is the edge's P2 node, the point of the curved edge at parameter 1/2 (on the
  // boundary, that point's closest point of the surface). The new edges start at the exact
  // subdivision of the shell: the halves of the split edge and, toward each other vertex c, the
  // point of face (a, b, c)'s P2 map halfway between the node and c. So the fallback configuration
  // is the old shell's geometry exactly (docs/curving.md).
  const Vec<D> A = mesh_.vertex(a), B = mesh_.vertex(b), X = mesh_.edge_node(edge);
  const Index m = add_vertex(boundary ? boundary->place(X, kNoIndex) : X, a);
  starts_.assign({{m, a, point_on_edge(A, X, B, 0.25)}, {m, b, point_on_edge(A, X, B, 0.75)}});
  neighbors_.clear();
  for (Index k : cavity_)
    for (Index c : mesh_.element(k))
      if (c != a && c != b && !small_set_holds(neighbors_, c)) {
        neighbors_.push_back(c);
        const Vec<D> to_c = 0.5 * (mesh_.edge_node(mesh_.find_edge(b, c)) + mesh_.edge_node(mesh_.find_edge(c, a)));
        starts_.push_back({m, c, -0.125 * (A + B) + 0.25 * X + to_c});
      }
  P2CavityRequest<D> request;
  request.start_nodes = starts_;
  request.quality_to_beat = bar.quality_to_beat;
  request.unit_edges_to_keep = bar.unit_edges_to_keep;
  request.straight_quality_to_keep = straight_quality_to_keep(cavity_);
  if (boundary) place_on_boundary(*boundary, m, request);
  const CavityStatus status = operator_.apply(mesh_, cavity_, m, request);
  if (status != CavityStatus::kAccepted)
    remove_last_vertex();
  else if (inserted)
    *inserted = m;
  return status;
}

template <int D>
void P2Operations<D>::shifted_starts(Index from_vertex, const Vec<D>& from, Index center) {
  const Vec<D> half_move = 0.5 * (mesh_.vertex(center) - from);
  starts_.clear();
  neighbors_.clear();
  for (Index k : cavity_)
    for (Index w : mesh_.element(k))
      if (w != from_vertex && w != center && !small_set_holds(neighbors_, w)) {
        neighbors_.push_back(w);
        starts_.push_back({center, w, mesh_.edge_node(mesh_.find_edge(from_vertex, w)) + half_move});
      }
}

template <int D>
CavityStatus P2Operations<D>::collapse_edge(Index removed, Index kept, Bar bar, const BoundaryPlacement<D>* boundary) {
  if (mesh_.find_edge(removed, kept) == kNoIndex) return CavityStatus::kNotStarShaped;
  collect_ball(mesh_, removed, cavity_);
  const Index vertex[1] = {removed};
  if (!boundary && on_boundary(cavity_, vertex)) return CavityStatus::kCrossesBoundary;
  // The removed vertex's edges move onto the kept one: each new edge starts from its old node
  // shifted by half the move (the edges (kept, w) that exist already are kept as they are).
  shifted_starts(removed, mesh_.vertex(removed), kept);
  P2CavityRequest<D> request;
  request.removable_vertex = removed;
  request.start_nodes = starts_;
  request.quality_to_beat = bar.quality_to_beat;
  request.unit_edges_to_keep = bar.unit_edges_to_keep;
  request.straight_quality_to_keep = straight_quality_to_keep(cavity_);
  if (boundary) place_on_boundary(*boundary, kept, request);
  return operator_.apply(mesh_, cavity_, kept, request);
}

template <int D>
void P2Operations<D>::place_on_boundary(const BoundaryPlacement<D>& boundary, Index center, P2CavityRequest<D>& request) {
  request.removed_facets = boundary.facets;
  request.removed_lines = boundary.lines;
  request.boundary_check = boundary.check;
  request.longest_placed_edge = boundary.longest_edge;
  boundary_nodes_.clear();
  for (const EdgeStart<D>& start : starts_) {
    const Index w = start.a == center ? start.b : start.a;
    // The edges of `center` that exist already stay as they are (a collapse's kept vertex with the
    // far vertices of the collapsed edge's facets), but for a cap's inner edge, which the removal
    // makes a boundary edge (no removed facet holds it).
    if (mesh_.find_edge(center, w) != kNoIndex && !(request.exposes_faces && !on_a_facet(boundary.facets, center, w))) continue;
    if (std::any_of(boundary.facets.begin(), boundary.facets.end(), [&](Index f) { return small_set_holds(mesh_.facet(f), w); }))
      boundary_nodes_.push_back({start.a, start.b, boundary.place(start.node, w)});
  }
  request.boundary_nodes = boundary_nodes_;
}

template <int D>
CavityStatus P2Operations<D>::swap_edge(Index a, Index b, std::span<const Index> apexes, Bar bar, const BoundaryPlacement<D>* boundary) {
  if (mesh_.find_edge(a, b) == kNoIndex) return CavityStatus::kNotStarShaped;
  collect_shell(mesh_, a, b, cavity_);
  const Index ends[2] = {a, b};
  if (!boundary && on_boundary(cavity_, ends)) return CavityStatus::kCrossesBoundary;
  // The new edges from the apex start straight (their fallback).
  P2CavityRequest<D> request;
  request.quality_to_beat = bar.quality_to_beat;
  request.unit_edges_to_keep = bar.unit_edges_to_keep;
  request.straight_quality_to_keep = straight_quality_to_keep(cavity_);
  // A cap (one element with both facets of a boundary edge) goes with its facets: its inner faces
  // become the boundary (docs/curving.md, "Caps").
  request.exposes_faces = boundary && cavity_.size() == 1;
  // (A shell that holds a boundary facet is refused whatever the apex.)
  CavityStatus status = CavityStatus::kNotStarShaped;
  for (std::size_t i = 0; i < apexes.size() && status != CavityStatus::kAccepted && status != CavityStatus::kCrossesBoundary; ++i) {
    const Index apex = apexes[i];
    const bool apex_in_shell = std::any_of(cavity_.begin(), cavity_.end(),
                                           [&](Index k) { return small_set_holds(mesh_.element(k), apex); });
    if (apex == a || apex == b || !apex_in_shell) {
      status = CavityStatus::kNotStarShaped;
      continue;
    }
    if (boundary) {  // a surface flip: the new boundary edge from the apex starts straight too
      starts_.clear();
      for (Index f : boundary->facets)
        for (Index w : mesh_.facet(f))
          if (w != apex) starts_.push_back({apex, w, 0.5 * (mesh_.vertex(apex) + mesh_.vertex(w))});
      place_on_boundary(*boundary, apex, request);
    }
    status = operator_.apply(mesh_, cavity_, apex, request);
  }
  return status;
}

template <int D>
bool P2Operations<D>::on_a_facet(std::span<const Index> facets, Index v, Index w) const {
  return std::any_of(facets.begin(), facets.end(),
                     [&](Index f) { return small_set_holds(mesh_.facet(f), v) && small_set_holds(mesh_.facet(f), w); });
}

template <int D>
CavityStatus P2Operations<D>::move_vertex(Index v, const Vec<D>& x, Bar bar) {
  collect_ball(mesh_, v, cavity_);
  const Index vertex[1] = {v};
  if (on_boundary(cavity_, vertex)) return CavityStatus::kCrossesBoundary;
  P2CavityRequest<D> request;
  request.straight_quality_to_keep = straight_quality_to_keep(cavity_);  // before the move
  const auto slot = static_cast<std::size_t>(v);
  const Vec<D> from = mesh_.vertex(v);
  const SymMat<D> from_log_metric = log_metrics_[slot];
  const Index from_hint = hints_[slot];
  const auto sample = field_.sample(x, from_hint);
  mesh_.vertex(v) = x;
  log_metrics_[slot] = sample.log_metric;
  hints_[slot] = sample.where.element;
  shifted_starts(v, from, v);
  request.start_nodes = starts_;
  request.quality_to_beat = bar.quality_to_beat;
  request.unit_edges_to_keep = bar.unit_edges_to_keep;
  const CavityStatus status = operator_.apply(mesh_, cavity_, v, request);
  if (status != CavityStatus::kAccepted) {
    mesh_.vertex(v) = from;
    log_metrics_[slot] = from_log_metric;
    hints_[slot] = from_hint;
  }
  return status;
}

template <int D>
double P2Operations<D>::edge_length(Index a, Index b) const {
  const auto sa = static_cast<std::size_t>(a), sb = static_cast<std::size_t>(b);
  const Vec<D> A = mesh_.vertex(a), B = mesh_.vertex(b), node = mesh_.edge_node(mesh_.find_edge(a, b));
  return remembered([&] { return edge_digest(kCurvedLength, A, B, log_metrics_[sa], log_metrics_[sb], hints_[sa], node); },
                    [&] { return high_precision_edge_length(field_, A, B, log_metrics_[sa], log_metrics_[sb], node, hints_[sa]); });
}

template <int D>
double P2Operations<D>::straight_length(Index a, Index b) const {
  const auto sa = static_cast<std::size_t>(a), sb = static_cast<std::size_t>(b);
  const Vec<D> A = mesh_.vertex(a), B = mesh_.vertex(b), middle = 0.5 * (A + B);
  return remembered([&] { return edge_digest(kStraightLength, A, B, log_metrics_[sa], log_metrics_[sb], hints_[sa], middle); },
                    [&] { return high_precision_edge_length(field_, A, B, log_metrics_[sa], log_metrics_[sb], middle, hints_[sa]); });
}

template <int D>
std::array<SymMat<D>, D + 1> P2Operations<D>::element_log_metrics(Index k) const {
  std::array<SymMat<D>, D + 1> vertex_log_metrics;
  for (int i = 0; i <= D; ++i)
    vertex_log_metrics[static_cast<std::size_t>(i)] = log_metrics_[static_cast<std::size_t>(mesh_.element(k)[i])];
  return vertex_log_metrics;
}

template <int D>
double P2Operations<D>::quality(Index k) const {
  const P2Element<D> element = gather_p2_element(mesh_, k);
  const std::array<SymMat<D>, D + 1> log_metrics = element_log_metrics(k);
  const auto key = [&] {
    Digest digest(kCurvedQuality);
    for (const Vec<D>& node : element.nodes) digest.add_all(node.c);
    for (const SymMat<D>& log_metric : log_metrics) digest.add_all(log_metric.entries);
    return digest;
  };
  return remembered(key, [&] { return curved_mean_ratio(element, log_metrics).value; });
}

template <int D>
double P2Operations<D>::straight_quality(Index k) const {
  SimplexPoints<D> points;
  for (int i = 0; i <= D; ++i) points[static_cast<std::size_t>(i)] = mesh_.vertex(mesh_.element(k)[i]);
  return centroid_metric_mean_ratio<D>(points, element_log_metrics(k));
}

template class P2Operations<2>;
template class P2Operations<3>;

}  // namespace hocav
