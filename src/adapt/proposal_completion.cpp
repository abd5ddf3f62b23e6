#include "adapt/proposal_completion.hpp"

#include <chrono>

#include "adapt/element_guard.hpp"
#include "adapt/layer_bending.hpp"
#include "base/bisection.hpp"
#include "mesh/ball_and_shell.hpp"

namespace hocav {
namespace {

// Moves the node of `edge` from where it is toward `target`, as far as the elements around it allow.
template <int D>
class EdgeNodeMove {
 public:
  EdgeNodeMove(Mesh<D>& mesh, std::vector<Index> shell, Index edge, const Vec<D>& target, const ProposalCompletionOptions<D>& options,
               ProposalCompletion& result)
      : mesh_(mesh),
        guard_(mesh, std::move(shell), options.jacobian_floor, options.field),
        edge_(edge),
        start_(mesh.edge_node(edge)),
        target_(target),
        steps_(options.correction_steps),
        result_(result) {}

  // Whether the node fits at the target; when not, it stays where it was.
  bool fits_in_full() {
    if (certified_at(1)) return true;
    set(0);
    return false;
  }

  // Bisection between the start (certified: the mesh was valid) and the target.
  void move_part_way() {
    set(largest_fraction_holding(steps_, [&](double fraction) { return certified_at(fraction); }));
  }

 private:
  void set(double fraction) { mesh_.edge_node(edge_) = start_ + fraction * (target_ - start_); }

  bool certified_at(double fraction) {
    set(fraction);
    return guard_.holds(result_.elements_certified);
  }

  Mesh<D>& mesh_;
  ElementGuard<D> guard_;
  Index edge_;
  Vec<D> start_, target_;
  int steps_;
  ProposalCompletion& result_;
};

// Bends the layers around the edge of `left` (its node held back); returns the fraction of the
// moves made, 1 when its proposal and those of the wall edges moved with it are placed.
template <int D>
double bend(Mesh<D>& mesh, BoundaryProposals<D>& proposals, const typename BoundaryProposals<D>::Left& left,
            const ProposalCompletionOptions<D>& options, ProposalCompletion& result) {
  const LayerBend made = bend_layers(
      mesh, proposals, left.a, left.b,
      {.jacobian_floor = options.jacobian_floor, .field = options.field, .correction_steps = options.correction_steps});
  result.elements_certified += made.elements_certified;
  if (made.fraction < 1) return made.fraction;
  for (const auto& [a, b] : made.wall_edges) proposals.take(a, b);
  result.placed += static_cast<Index>(made.wall_edges.size());
  ++result.bends;
  result.volume_nodes_bent += made.volume_nodes;
  return 1;
}

// One sweep over the proposals left; returns how many were consumed.
template <int D>
Index sweep(Mesh<D>& mesh, BoundaryProposals<D>& proposals, const ProposalCompletionOptions<D>& options, ProposalCompletion& result) {
  std::vector<Index> shell;
  Index consumed = 0;
  result.pulled_back = result.blocked = result.absent = 0;
  result.largest_gap = 0;
  for (const auto& left : proposals.left()) {
    if (!proposals.find(left.a, left.b)) continue;  // placed by a bend of this sweep
    const Index edge = mesh.find_edge(left.a, left.b);
    if (edge == kNoIndex) {
      ++result.absent;
      continue;
    }
    if (mesh.edge_node(edge) == left.node) {
      proposals.take(left.a, left.b);
      ++result.already_placed;
      ++consumed;
      continue;
    }
    collect_shell(mesh, left.a, left.b, shell);
    const Vec<D> start = mesh.edge_node(edge);
    EdgeNodeMove<D> move(mesh, shell, edge, left.node, options, result);
    if (move.fits_in_full()) {
      proposals.take(left.a, left.b);
      ++result.placed;
      ++consumed;
      continue;
    }
    // The layers bent with the wall, else the node alone part of the way.
    if (const double fraction = bend(mesh, proposals, left, options, result); fraction == 1) {
      ++consumed;
      continue;
    } else if (fraction == 0) {
      move.move_part_way();
    }
    ++(norm(mesh.edge_node(edge) - start) > 0 ? result.pulled_back : result.blocked);
    result.largest_gap = std::max(result.largest_gap, norm(mesh.edge_node(edge) - left.node));
  }
  return consumed;
}

}  // namespace

template <int D>
ProposalCompletion complete_boundary_proposals(Mesh<D>& mesh, BoundaryProposals<D>& proposals,
                                               const ProposalCompletionOptions<D>& options) {
  const auto start = std::chrono::steady_clock::now();
  ProposalCompletion result;
  while (result.sweeps < options.max_sweeps && proposals.size() > 0) {
    ++result.sweeps;
    if (sweep(mesh, proposals, options, result) == 0) break;
  }
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

template ProposalCompletion complete_boundary_proposals(Mesh<2>&, BoundaryProposals<2>&, const ProposalCompletionOptions<2>&);
template ProposalCompletion complete_boundary_proposals(Mesh<3>&, BoundaryProposals<3>&, const ProposalCompletionOptions<3>&);

}  // namespace hocav
