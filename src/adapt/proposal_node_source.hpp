// The boundary proposals of src/surface/ as the cavity operator's source of boundary nodes: the
// driver layer joins the two so that neither module depends on the other.
#pragma once

#include "cavity/boundary_node_source.hpp"
#include "surface/boundary_proposals.hpp"

namespace hocav {

template <int D>
class ProposalNodeSource final : public BoundaryNodeSource<D> {
 public:
  explicit ProposalNodeSource(BoundaryProposals<D>& proposals) : proposals_(proposals) {}
  std::optional<Vec<D>> proposal(Index a, Index b) const override { return proposals_.find(a, b); }
  void consume(Index a, Index b) override { proposals_.take(a, b); }

 private:
  BoundaryProposals<D>& proposals_;
};

}  // namespace hocav
