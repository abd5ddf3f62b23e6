#include "cavity/p2_cavity_operator.hpp"

#include <algorithm>
#include <chrono>

#include "bezier/jacobian_bounds.hpp"
#include "mesh/ball_and_shell.hpp"

namespace hocav {
namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

}  // namespace

P2CavityCounters& P2CavityCounters::operator+=(const P2CavityCounters& other) {
  cavities += other.cavities;
  accepted += other.accepted;
  rejected_topology += other.rejected_topology;
  rejected_curving += other.rejected_curving;
  edges_optimized += other.edges_optimized;
  optimizer_iterations += other.optimizer_iterations;
  boundary_nodes_applied += other.boundary_nodes_applied;
  corrections += other.corrections;
  elements_certified += other.elements_certified;
  seconds_plan += other.seconds_plan;
  seconds_optimize += other.seconds_optimize;
  seconds_certify += other.seconds_certify;
  seconds_commit += other.seconds_commit;
  return *this;
}

template <int D>
P2CavityOperator<D>::P2CavityOperator(const MetricField<D>& field, std::vector<SymMat<D>>& vertex_log_metrics,
                                      std::vector<Index>& vertex_hints, BoundaryNodeSource<D>* boundary,
                                      const P2CavityOptions& options)
    : field_(field),
      vertex_log_metrics_(vertex_log_metrics),
      vertex_hints_(vertex_hints),
      boundary_(boundary),
      options_(options) {}

template <int D>
CavityStatus P2CavityOperator<D>::prepare(const Mesh<D>& mesh, std::span<const Index> cavity, Index vertex) {
  ++counters_.cavities;
  auto start = Clock::now();
  CavityOptions topology_only;
  topology_only.check_straight_measure = false;
  CavityStatus status = p1_.plan(mesh, cavity, vertex, topology_only);
  counters_.seconds_plan += seconds_since(start);
  if (status != CavityStatus::kAccepted) {
    ++counters_.rejected_topology;
    return status;
  }

  start = Clock::now();
  curved_.clear();
  curve_inner_edges(mesh);
  take_boundary_proposals(mesh);
  counters_.seconds_optimize += seconds_since(start);

  start = Clock::now();
  collect_candidates(mesh);
  // Certify every candidate; pull back the edges of the first that fails, and start over (a
  // pulled-back edge changes its other elements too). Each round lowers some scale, so it ends.
  bool valid = true;
  for (std::size_t round = 0; valid; ++round) {
    auto failing = std::find_if(candidates_.begin(), candidates_.end(),
                                [&](const Candidate& candidate) { return !certified(mesh, candidate); });
    if (failing == candidates_.end()) break;
    ++counters_.corrections;
    valid = round < 8 * candidates_.size() && correct(mesh, *failing);
  }
  counters_.seconds_certify += seconds_since(start);
  if (!valid) {
    ++counters_.rejected_curving;
    return CavityStatus::kRejectedByCurving;
  }
  return CavityStatus::kAccepted;
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
      if (edge.scale == 1) {
        boundary_->consume(edge.a, edge.b);
        ++counters_.boundary_nodes_applied;
      }
    }
  }
  p1_.commit(mesh, inner_nodes_, boundary_nodes_);
  counters_.seconds_commit += seconds_since(start);
  ++counters_.accepted;
}

template <int D>
void P2CavityOperator<D>::curve_inner_edges(const Mesh<D>& mesh) {
  const auto edges = p1_.new_inner_edges();
  const auto starts = p1_.new_inner_edge_start_nodes();
  for (std::size_t i = 0; i < edges.size(); ++i) {
    const auto [a, b] = edges[i];
    auto result = optimize_edge_length(field_, mesh.vertex(a), mesh.vertex(b), vertex_log_metrics_[a],
                                       vertex_log_metrics_[b], starts[i], vertex_hints_[a], options_.optimizer);
    ++counters_.edges_optimized;
    counters_.optimizer_iterations += result.iterations;
    vertex_hints_[a] = result.back_element;  // near a: the next walk from a starts close
    curved_.push_back({a, b, starts[i], result.node, 1, true, static_cast<Index>(i)});
  }
}

template <int D>
void P2CavityOperator<D>::take_boundary_proposals(const Mesh<D>& mesh) {
  if (!boundary_) return;
  for (Index edge : p1_.boundary_edges()) {
    const auto [a, b] = mesh.edge_vertices(edge);
    auto proposal = boundary_->proposal(a, b);
    if (!proposal || *proposal == mesh.edge_node(edge)) continue;
    // Pulling back moves the node from where it is now toward the proposal.
    curved_.push_back({a, b, mesh.edge_node(edge), *proposal, 1, false, edge});
  }
}

template <int D>
void P2CavityOperator<D>::collect_candidates(const Mesh<D>& mesh) {
  candidates_.clear();
  for (const auto& element : p1_.new_elements()) candidates_.push_back({element, kNoIndex});
  // Elements outside the cavity around a boundary edge whose node changes change too.
  const auto cavity = p1_.cavity();
  for (const CurvedEdge& edge : curved_) {
    if (edge.inner) continue;
    collect_shell(mesh, edge.a, edge.b, shell_);
    for (Index k : shell_) {
      if (std::binary_search(cavity.begin(), cavity.end(), k)) continue;
      bool listed = std::any_of(candidates_.begin(), candidates_.end(),
                                [&](const Candidate& candidate) { return candidate.mesh_element == k; });
      if (!listed) candidates_.push_back({mesh.element(k), k});
    }
  }
}

template <int D>
P2Element<D> P2CavityOperator<D>::element_of(const Mesh<D>& mesh, const Candidate& candidate) const {
  P2Element<D> element;
  for (int i = 0; i <= D; ++i) element.nodes[i] = mesh.vertex(candidate.vertices[i]);
  for (int e = 0; e < Simplex<D>::kEdges; ++e) {
    Index a = candidate.vertices[edge_vertices<D>(e)[0]], b = candidate.vertices[edge_vertices<D>(e)[1]];
    auto curved = std::find_if(curved_.begin(), curved_.end(), [&](const CurvedEdge& edge) {
      return (edge.a == a && edge.b == b) || (edge.a == b && edge.b == a);
    });
    element.nodes[D + 1 + e] = curved != curved_.end() ? curved->node() : mesh.edge_node(mesh.find_edge(a, b));
  }
  return element;
}

template <int D>
bool P2CavityOperator<D>::certified(const Mesh<D>& mesh, const Candidate& candidate) {
  ++counters_.elements_certified;
  return certify_min_normalized_jacobian_above(element_of(mesh, candidate), options_.jacobian_floor);
}

template <int D>
bool P2CavityOperator<D>::correct(const Mesh<D>& mesh, const Candidate& candidate) {
  // The changed edges of this element: inner ones first, then boundary ones as well.
  for (bool with_boundary : {false, true}) {
    std::vector<CurvedEdge*> edges;
    for (int e = 0; e < Simplex<D>::kEdges; ++e) {
      Index a = candidate.vertices[edge_vertices<D>(e)[0]], b = candidate.vertices[edge_vertices<D>(e)[1]];
      for (CurvedEdge& edge : curved_)
        if (((edge.a == a && edge.b == b) || (edge.a == b && edge.b == a)) && edge.scale > 0 &&
            (edge.inner || with_boundary))
          edges.push_back(&edge);
    }
    if (edges.empty()) continue;
    std::vector<double> original;
    for (CurvedEdge* edge : edges) original.push_back(edge->scale);
    auto set_factor = [&](double factor) {
      for (std::size_t i = 0; i < edges.size(); ++i) edges[i]->scale = original[i] * factor;
    };
    // The largest factor in [0, 1) that certifies the element, by bisection.
    set_factor(0);
    if (!certified(mesh, candidate)) {
      set_factor(1);
      continue;
    }
    double good = 0, bad = 1;
    for (int step = 0; step < options_.correction_steps; ++step) {
      double middle = 0.5 * (good + bad);
      set_factor(middle);
      (certified(mesh, candidate) ? good : bad) = middle;
    }
    set_factor(good);
    return true;
  }
  return false;
}

template class P2CavityOperator<2>;
template class P2CavityOperator<3>;

}  // namespace hocav
