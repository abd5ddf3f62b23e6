#include "cavity/p2_cavity_operator.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <utility>

#include "base/bisection.hpp"
#include "base/stopwatch.hpp"
#include "bezier/jacobian_bounds.hpp"
#include "curve/curved_quality.hpp"
#include "mesh/ball_and_shell.hpp"
#include "metric/metric_quality.hpp"

namespace hocav {
namespace {

using Clock = std::chrono::steady_clock;

// Sorts the vertices of an element; true when that takes an odd permutation (so two elements with
// the same sorted vertices and parity are one element, with one orientation).
template <std::size_t N>
bool sort_with_parity(std::array<Index, N>& vertices) {
  bool odd = false;
  for (std::size_t i = 1; i < N; ++i)
    for (std::size_t j = i; j > 0 && vertices[j - 1] > vertices[j]; --j) {
      std::swap(vertices[j - 1], vertices[j]);
      odd = !odd;
    }
  return odd;
}

}  // namespace

P2CavityCounters& P2CavityCounters::operator+=(const P2CavityCounters& other) {
  cavities += other.cavities;
  accepted += other.accepted;
  rejected_topology += other.rejected_topology;
  rejected_curving += other.rejected_curving;
  rejected_quality += other.rejected_quality;
  rejected_straight_quality += other.rejected_straight_quality;
  rejected_boundary += other.rejected_boundary;
  edges_optimized += other.edges_optimized;
  optimizer_iterations += other.optimizer_iterations;
  edges_kept_optimal += other.edges_kept_optimal;
  boundary_nodes_applied += other.boundary_nodes_applied;
  corrections += other.corrections;
  elements_certified += other.elements_certified;
  certificates_kept += other.certificates_kept;
  seconds_plan += other.seconds_plan;
  seconds_optimize += other.seconds_optimize;
  seconds_certify += other.seconds_certify;
  seconds_commit += other.seconds_commit;
  return *this;
}

template <int D>
P2CavityOperator<D>::P2CavityOperator(const MetricField<D>& field, std::vector<SymMat<D>>& vertex_log_metrics,
                                      std::vector<Index>& vertex_hints, OptimizedEdgeMarks* optimized_edges,
                                      BoundaryNodeSource<D>* boundary, const P2CavityOptions& options)
    : field_(field),
      vertex_log_metrics_(vertex_log_metrics),
      vertex_hints_(vertex_hints),
      optimized_edges_(optimized_edges),
      boundary_(boundary),
      options_(options) {}

template <int D>
CavityStatus P2CavityOperator<D>::prepare(const Mesh<D>& mesh, std::span<const Index> cavity, Index vertex,
                                          const P2CavityRequest<D>& request) {
  ++counters_.cavities;
  auto start = Clock::now();
  CavityOptions plan_options;
  plan_options.check_straight_measure = options_.positive_straight_elements;
  plan_options.removable_vertex = request.removable_vertex;
  plan_options.removed_facets = request.removed_facets;
  plan_options.removed_lines = request.removed_lines;
  plan_options.exposes_faces = request.exposes_faces;
  CavityStatus status = p1_.plan(mesh, cavity, vertex, plan_options);
  counters_.seconds_plan += seconds_since(start);
  if (status != CavityStatus::kAccepted) {
    ++counters_.rejected_topology;
    return status;
  }
  if (request.boundary_check && !request.boundary_check(p1_)) {
    ++counters_.rejected_boundary;
    return CavityStatus::kBoundaryGeometry;
  }
  if (request.straight_quality_to_keep >= 0 && !new_straight_elements_above(mesh, request.straight_quality_to_keep)) {
    ++counters_.rejected_straight_quality;
    return CavityStatus::kFlatStraightElement;
  }

  start = Clock::now();
  curved_.clear();
  curve_inner_edges(mesh, request);
  take_boundary_proposals(mesh, request);
  counters_.seconds_optimize += seconds_since(start);

  start = Clock::now();
  collect_candidates(mesh);
  // Certify every candidate; pull back the edges of the first that fails, and start over (a
  // pulled-back edge changes its other elements too). Each round lowers some scale, so it ends.
  // A candidate whose nodes did not move since it was certified is not certified again, nor one
  // identical to a cavity element, which was above the floor.
  bool valid = true;
  certified_already_.assign(candidates_.size(), false);
  // Given start nodes differ from the cavity's old nodes (or its vertex moved): nothing is recreated.
  if (options_.every_element_above_floor && request.start_nodes.empty()) {
    collect_cavity_vertex_sets(mesh);
    for (std::size_t i = 0; i < candidates_.size(); ++i)
      if (candidates_[i].mesh_element == kNoIndex && recreates_cavity_element(candidates_[i])) {
        certified_already_[i] = true;
        ++counters_.certificates_kept;
      }
  }
  for (std::size_t round = 0; valid; ++round) {
    std::size_t failing = 0;
    while (failing < candidates_.size() && (certified_already_[failing] || certified(candidates_[failing])))
      certified_already_[failing++] = true;
    if (failing == candidates_.size()) break;
    ++counters_.corrections;
    valid = round < 8 * candidates_.size() && correct(candidates_[failing]);
    forget_certificates_of_corrected_edges();
  }
  counters_.seconds_certify += seconds_since(start);
  if (!valid) {
    ++counters_.rejected_curving;
    return CavityStatus::kRejectedByCurving;
  }
  if (std::any_of(curved_.begin(), curved_.end(), [](const CurvedEdge& edge) { return edge.placed && edge.scale < 1; })) {
    ++counters_.rejected_boundary;  // a boundary node pulled off the geometry
    return CavityStatus::kBoundaryGeometry;
  }
  if ((request.quality_to_beat >= 0 && !new_elements_above(request.quality_to_beat)) ||
      (request.unit_edges_to_keep >= 0 && unit_new_inner_edges(mesh) < request.unit_edges_to_keep) ||
      !placed_edges_within(mesh, request.longest_placed_edge)) {
    ++counters_.rejected_quality;
    return CavityStatus::kNoImprovement;
  }
  return CavityStatus::kAccepted;
}

template <int D>
double P2CavityOperator<D>::curved_length(const Mesh<D>& mesh, const CurvedEdge& edge) const {
  const auto a = static_cast<std::size_t>(edge.a), b = static_cast<std::size_t>(edge.b);
  return high_precision_edge_length(field_, mesh.vertex(edge.a), mesh.vertex(edge.b), vertex_log_metrics_[a], vertex_log_metrics_[b],
                                    edge.node(), vertex_hints_[a]);
}

template <int D>
int P2CavityOperator<D>::unit_new_inner_edges(const Mesh<D>& mesh) const {
  int unit = 0;
  for (const CurvedEdge& edge : curved_)
    if (edge.inner) unit += unit_length(curved_length(mesh, edge));
  return unit;
}

template <int D>
bool P2CavityOperator<D>::placed_edges_within(const Mesh<D>& mesh, double longest) const {
  if (longest == INFINITY) return true;
  return std::all_of(curved_.begin(), curved_.end(),
                     [&](const CurvedEdge& edge) { return !edge.placed || curved_length(mesh, edge) <= longest; });
}

template <int D>
bool P2CavityOperator<D>::new_straight_elements_above(const Mesh<D>& mesh, double floor) const {
  SimplexPoints<D> points;
  for (const auto& element : p1_.new_elements()) {
    for (int i = 0; i <= D; ++i) points[static_cast<std::size_t>(i)] = mesh.vertex(element[i]);
    if (!(centroid_metric_mean_ratio<D>(points, log_metrics_of(element)) >= floor)) return false;
  }
  return true;
}

template <int D>
std::array<SymMat<D>, D + 1> P2CavityOperator<D>::log_metrics_of(const typename Mesh<D>::Element& vertices) const {
  std::array<SymMat<D>, D + 1> log_metrics;
  for (int i = 0; i <= D; ++i) log_metrics[static_cast<std::size_t>(i)] = vertex_log_metrics_[static_cast<std::size_t>(vertices[i])];
  return log_metrics;
}

template <int D>
bool P2CavityOperator<D>::new_elements_above(double bar) const {
  for (const Candidate& candidate : candidates_) {
    const bool changed_by_placement = std::any_of(candidate.curved.begin(), candidate.curved.end(),
                                                  [&](int i) { return i >= 0 && curved_[static_cast<std::size_t>(i)].placed; });
    if (candidate.mesh_element != kNoIndex && !changed_by_placement) continue;
    if (!(curved_mean_ratio(element_of(candidate), log_metrics_of(candidate.vertices)).value > bar)) return false;
  }
  return true;
}

template <int D>
void P2CavityOperator<D>::commit(Mesh<D>& mesh) {
  auto start = Clock::now();
  inner_nodes_.assign(p1_.new_inner_edges().size(), Vec<D>{});
  boundary_nodes_.clear();
  for (const CurvedEdge& edge : curved_) {
    if (edge.inner) {
      inner_nodes_[edge.id] = edge.node();
    } else {
      boundary_nodes_.emplace_back(edge.id, edge.node());
      if (edge.scale == 1 && !edge.placed) {
        boundary_->consume(edge.a, edge.b);
        ++counters_.boundary_nodes_applied;
      }
    }
  }
  p1_.commit(mesh, inner_nodes_, boundary_nodes_);
  if (optimized_edges_) mark_optimized_edges();
  counters_.seconds_commit += seconds_since(start);
  ++counters_.accepted;
}

template <int D>
void P2CavityOperator<D>::curve_inner_edges(const Mesh<D>& mesh, const P2CavityRequest<D>& request) {
  const auto edges = p1_.new_inner_edges();
  const auto default_starts = p1_.new_inner_edge_start_nodes();
  const auto recreated_ids = p1_.new_inner_edge_recreated_ids();
  EdgeEndpoint<D> end_a;  // the new edges share their first vertex (the cavity's): its metric once
  Index end_a_vertex = kNoIndex;
  for (std::size_t i = 0; i < edges.size(); ++i) {
    const auto [a, b] = edges[i];
    const std::uint64_t key = Mesh<D>::edge_key(a, b);  // a plain variable: clang's lambdas take no structured binding
    const auto same_edge = [key](const EdgeStart<D>& s) { return Mesh<D>::edge_key(s.a, s.b) == key; };
    const auto given = std::find_if(request.start_nodes.begin(), request.start_nodes.end(), same_edge);
    const Vec<D> start = given != request.start_nodes.end() ? given->node : default_starts[i];
    const auto on_geometry = std::find_if(request.boundary_nodes.begin(), request.boundary_nodes.end(), same_edge);
    if (on_geometry != request.boundary_nodes.end()) {  // a new boundary edge: its node is the geometry's
      curved_.push_back({a, b, start, on_geometry->node, 1, true, static_cast<Index>(i), false, kNoIndex, true});
      continue;
    }
    if (given == request.start_nodes.end() && optimized_edges_ && recreated_ids[i] != kNoIndex &&
        optimized_edges_->marked(recreated_ids[i])) {
      ++counters_.edges_kept_optimal;
      curved_.push_back({a, b, start, start, 1, true, static_cast<Index>(i), true});
      continue;
    }
    if (a != end_a_vertex) {
      end_a = edge_endpoint(mesh.vertex(a), vertex_log_metrics_[a]);
      end_a_vertex = a;
    }
    const Index start_hint = vertex_hints_[a];
    auto result = optimize_edge_length(field_, end_a, edge_endpoint(mesh.vertex(b), vertex_log_metrics_[b]), start, start_hint,
                                       options_.optimizer, locator_scratch_);
    ++counters_.edges_optimized;
    counters_.optimizer_iterations += result.iterations;
    vertex_hints_[a] = result.back_element;  // near a: the next walk from a starts close
    // The optimizer's unconverged exits leave no optimum to keep: the iteration limit, and a
    // non-finite Newton model (it returns before measuring a length).
    const bool converged = result.iterations < options_.optimizer.max_iterations && result.length > 0;
    curved_.push_back({a, b, start, result.node, 1, true, static_cast<Index>(i), converged, start_hint});
  }
}

template <int D>
void P2CavityOperator<D>::take_boundary_proposals(const Mesh<D>& mesh, const P2CavityRequest<D>& request) {
  for (Index edge : p1_.boundary_edges()) {
    const auto [a, b] = mesh.edge_vertices(edge);
    const std::uint64_t key = Mesh<D>::edge_key(a, b);
    const auto placed = std::find_if(request.boundary_nodes.begin(), request.boundary_nodes.end(),
                                     [key](const EdgeStart<D>& s) { return Mesh<D>::edge_key(s.a, s.b) == key; });
    if (placed != request.boundary_nodes.end()) {
      curved_.push_back({a, b, mesh.edge_node(edge), placed->node, 1, false, edge, false, kNoIndex, true});
      continue;
    }
    if (!boundary_) continue;
    auto proposal = boundary_->proposal(a, b);
    if (!proposal || *proposal == mesh.edge_node(edge)) continue;
    // Pulling back moves the node from where it is now toward the proposal.
    curved_.push_back({a, b, mesh.edge_node(edge), *proposal, 1, false, edge, false});
  }
}

template <int D>
void P2CavityOperator<D>::collect_candidates(const Mesh<D>& mesh) {
  curved_by_key_.clear();
  for (std::size_t i = 0; i < curved_.size(); ++i)
    curved_by_key_.emplace_back(Mesh<D>::edge_key(curved_[i].a, curved_[i].b), static_cast<int>(i));
  std::sort(curved_by_key_.begin(), curved_by_key_.end());
  candidates_.clear();
  for (const auto& element : p1_.new_elements()) add_candidate(mesh, element, kNoIndex);
  // Elements outside the cavity around a boundary edge whose node changes change too.
  const auto cavity = p1_.cavity();
  for (const CurvedEdge& edge : curved_) {
    if (edge.inner) continue;
    collect_shell(mesh, edge.a, edge.b, shell_);
    for (Index k : shell_) {
      if (std::binary_search(cavity.begin(), cavity.end(), k)) continue;
      bool listed = std::any_of(candidates_.begin(), candidates_.end(),
                                [&](const Candidate& candidate) { return candidate.mesh_element == k; });
      if (!listed) add_candidate(mesh, mesh.element(k), k);
    }
  }
}

template <int D>
void P2CavityOperator<D>::add_candidate(const Mesh<D>& mesh, const typename Mesh<D>::Element& vertices, Index mesh_element) {
  Candidate& candidate = candidates_.emplace_back();
  candidate.vertices = vertices;
  candidate.mesh_element = mesh_element;
  for (int i = 0; i <= D; ++i) candidate.fixed_nodes.nodes[i] = mesh.vertex(vertices[i]);
  for (int e = 0; e < Simplex<D>::kEdges; ++e) {
    const Index a = vertices[edge_vertices<D>(e)[0]], b = vertices[edge_vertices<D>(e)[1]];
    const std::pair<std::uint64_t, int> key{Mesh<D>::edge_key(a, b), -1};
    auto found = std::upper_bound(curved_by_key_.begin(), curved_by_key_.end(), key);
    candidate.curved[e] = found != curved_by_key_.end() && found->first == key.first ? found->second : -1;
    if (candidate.curved[e] >= 0) continue;
    // An unchanged edge: the element's own (outside the cavity) or one on the cavity's boundary.
    Index id = mesh_element != kNoIndex ? mesh.element_edge(mesh_element, e) : p1_.boundary_edge(a, b);
    if (id == kNoIndex) id = mesh.find_edge(a, b);
    candidate.fixed_nodes.nodes[D + 1 + e] = mesh.edge_node(id);
  }
}

template <int D>
void P2CavityOperator<D>::collect_cavity_vertex_sets(const Mesh<D>& mesh) {
  cavity_vertex_sets_.clear();
  for (Index k : p1_.cavity()) {
    typename Mesh<D>::Element vertices = mesh.element(k);
    const bool odd = sort_with_parity(vertices);
    cavity_vertex_sets_.emplace_back(vertices, odd);
  }
  std::sort(cavity_vertex_sets_.begin(), cavity_vertex_sets_.end());
}

template <int D>
bool P2CavityOperator<D>::recreates_cavity_element(const Candidate& candidate) const {
  // Its edges are then the cavity element's (recreated or on the cavity's boundary): the nodes
  // are the same when none of its curved edges moves.
  for (int index : candidate.curved)
    if (index >= 0) {
      const CurvedEdge& edge = curved_[static_cast<std::size_t>(index)];
      if (edge.target != edge.fallback) return false;
    }
  typename Mesh<D>::Element vertices = candidate.vertices;
  const bool odd = sort_with_parity(vertices);
  return std::binary_search(cavity_vertex_sets_.begin(), cavity_vertex_sets_.end(), std::pair{vertices, odd});
}

template <int D>
void P2CavityOperator<D>::mark_optimized_edges() {
  const auto inner_ids = p1_.committed_inner_edge_ids();
  for (const CurvedEdge& edge : curved_)
    optimized_edges_->set(edge.inner ? inner_ids[static_cast<std::size_t>(edge.id)] : edge.id, edge.optimal && edge.scale == 1);
}

template <int D>
void P2CavityOperator<D>::forget_certificates_of_corrected_edges() {
  for (std::size_t i = 0; i < candidates_.size(); ++i)
    for (int index : candidates_[i].curved)
      if (index >= 0 &&
          std::find(corrected_edges_.begin(), corrected_edges_.end(), &curved_[static_cast<std::size_t>(index)]) != corrected_edges_.end())
        certified_already_[i] = false;
}

template <int D>
P2Element<D> P2CavityOperator<D>::element_of(const Candidate& candidate) const {
  P2Element<D> element = candidate.fixed_nodes;
  for (int e = 0; e < Simplex<D>::kEdges; ++e)
    if (candidate.curved[e] >= 0) element.nodes[D + 1 + e] = curved_[static_cast<std::size_t>(candidate.curved[e])].node();
  return element;
}

template <int D>
bool P2CavityOperator<D>::certified(const Candidate& candidate) {
  ++counters_.elements_certified;
  return certify_min_normalized_jacobian_above(element_of(candidate), options_.jacobian_floor);
}

template <int D>
bool P2CavityOperator<D>::correct(const Candidate& candidate) {
  // The changed edges of this element: inner ones first, then boundary ones as well.
  for (bool with_boundary : {false, true}) {
    corrected_edges_.clear();
    for (int index : candidate.curved) {
      if (index < 0) continue;
      CurvedEdge& edge = curved_[static_cast<std::size_t>(index)];
      // An edge whose node does not move (kept at its optimum, or optimized back to its start) cannot help.
      if (edge.scale > 0 && edge.target != edge.fallback && (edge.inner || with_boundary)) corrected_edges_.push_back(&edge);
    }
    if (corrected_edges_.empty()) continue;
    corrected_scales_.clear();
    for (CurvedEdge* edge : corrected_edges_) corrected_scales_.push_back(edge->scale);
    auto set_factor = [&](double factor) {
      for (std::size_t i = 0; i < corrected_edges_.size(); ++i) corrected_edges_[i]->scale = corrected_scales_[i] * factor;
    };
    // The largest factor in [0, 1) that certifies the element, by bisection.
    set_factor(0);
    if (!certified(candidate)) {
      set_factor(1);
      continue;
    }
    set_factor(largest_fraction_holding(options_.correction_steps, [&](double factor) {
      set_factor(factor);
      return certified(candidate);
    }));
    return true;
  }
  return false;
}

template class P2CavityOperator<2>;
template class P2CavityOperator<3>;

}  // namespace hocav
