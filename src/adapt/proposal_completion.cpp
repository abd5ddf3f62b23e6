#include "adapt/proposal_completion.hpp"

#include <chrono>

#include "bezier/jacobian_bounds.hpp"
#include "bezier/p2_element.hpp"
#include "mesh/ball_and_shell.hpp"

namespace hocav {
namespace {

enum class Placement { kFull, kPart, kNone };

// Moves the node of `edge` from where it is toward `target`, as far as the elements of `shell` allow.
template <int D>
class EdgeNodeMove {
 public:
  EdgeNodeMove(Mesh<D>& mesh, const std::vector<Index>& shell, Index edge, const Vec<D>& target, const ProposalCompletionOptions& options,
               ProposalCompletion& result)
      : mesh_(mesh), shell_(shell), edge_(edge), start_(mesh.edge_node(edge)), target_(target), options_(options), result_(result) {}

  Placement run() {
    if (certified_at(1)) return Placement::kFull;
    // Bisection between the start (certified: the mesh was valid) and the proposal.
    double good = 0, bad = 1;
    for (int step = 0; step < options_.correction_steps; ++step) {
      const double middle = 0.5 * (good + bad);
      (certified_at(middle) ? good : bad) = middle;
    }
    set(good);
    return good > 0 ? Placement::kPart : Placement::kNone;
  }

 private:
  void set(double fraction) { mesh_.edge_node(edge_) = start_ + fraction * (target_ - start_); }

  bool certified_at(double fraction) {
    set(fraction);
    for (Index k : shell_) {
      ++result_.elements_certified;
      if (!certify_min_normalized_jacobian_above(gather_p2_element(mesh_, k), options_.jacobian_floor)) return false;
    }
    return true;
  }

  Mesh<D>& mesh_;
  const std::vector<Index>& shell_;
  Index edge_;
  Vec<D> start_, target_;
  const ProposalCompletionOptions& options_;
  ProposalCompletion& result_;
};

// One sweep over the proposals left; returns how many were consumed.
template <int D>
Index sweep(Mesh<D>& mesh, BoundaryProposals<D>& proposals, const ProposalCompletionOptions& options, ProposalCompletion& result) {
  std::vector<Index> shell;
  Index consumed = 0;
  result.pulled_back = result.blocked = result.absent = 0;
  result.largest_gap = 0;
  for (const auto& left : proposals.left()) {
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
    switch (EdgeNodeMove<D>(mesh, shell, edge, left.node, options, result).run()) {
      case Placement::kFull:
        proposals.take(left.a, left.b);
        ++result.placed;
        ++consumed;
        continue;
      case Placement::kPart: ++result.pulled_back; break;
      case Placement::kNone: ++result.blocked; break;
    }
    result.largest_gap = std::max(result.largest_gap, norm(mesh.edge_node(edge) - left.node));
  }
  return consumed;
}

}  // namespace

template <int D>
ProposalCompletion complete_boundary_proposals(Mesh<D>& mesh, BoundaryProposals<D>& proposals, const ProposalCompletionOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  ProposalCompletion result;
  while (result.sweeps < options.max_sweeps && proposals.size() > 0) {
    ++result.sweeps;
    if (sweep(mesh, proposals, options, result) == 0) break;
  }
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

template ProposalCompletion complete_boundary_proposals(Mesh<2>&, BoundaryProposals<2>&, const ProposalCompletionOptions&);
template ProposalCompletion complete_boundary_proposals(Mesh<3>&, BoundaryProposals<3>&, const ProposalCompletionOptions&);

}  // namespace hocav
