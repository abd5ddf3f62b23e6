#include "parallel/part_curving.hpp"

#include <algorithm>

namespace hocav {
namespace {

void add_completion(ProposalCompletion& sum, const ProposalCompletion& part) {
  sum.placed += part.placed;
  sum.already_placed += part.already_placed;
  sum.pulled_back += part.pulled_back;
  sum.blocked += part.blocked;
  sum.absent += part.absent;
  sum.bends += part.bends;
  sum.volume_nodes_bent += part.volume_nodes_bent;
  sum.largest_gap = std::max(sum.largest_gap, part.largest_gap);
  sum.elements_certified += part.elements_certified;
  sum.sweeps = std::max(sum.sweeps, part.sweeps);
  sum.seconds = std::max(sum.seconds, part.seconds);
}

}  // namespace

template <int D>
PartCurving curve_part(MeshPart<D>& part, const MetricField<D>& field, const std::vector<char>& region, std::span<const Index> geometry_ids,
                       const BoundaryGeometry<D>* geometry, const CurvingOptions& options) {
  if (part.mesh.element_count() == 0) return {};
  if (!part.mesh.has_topology()) part.mesh.build_topology();
  ReinsertionOptions reinsertion = reinsertion_options(options);
  reinsertion.region = region;
  const ProposalScope scope{kInterfaceRef, region, geometry_ids};
  const CurvingWork work = curve_unmeasured(part.mesh, field, geometry, reinsertion, scope);
  return {work.result.counters, work.completion, work.result.seconds, work.proposals_left};
}

void add_part(PartCurving& round, const PartCurving& part) {
  round.counters += part.counters;
  add_completion(round.completion, part.completion);
  round.seconds = std::max(round.seconds, part.seconds);
  round.proposals_left += part.proposals_left;
}

void add_round(PartCurving& total, const PartCurving& round) {
  const double seconds = total.seconds + round.seconds, completion_seconds = total.completion.seconds + round.completion.seconds;
  add_part(total, round);
  total.seconds = seconds;
  total.completion.seconds = completion_seconds;
}

template PartCurving curve_part(MeshPart<2>&, const MetricField<2>&, const std::vector<char>&, std::span<const Index>,
                                const BoundaryGeometry<2>*, const CurvingOptions&);
template PartCurving curve_part(MeshPart<3>&, const MetricField<3>&, const std::vector<char>&, std::span<const Index>,
                                const BoundaryGeometry<3>*, const CurvingOptions&);

}  // namespace hocav
