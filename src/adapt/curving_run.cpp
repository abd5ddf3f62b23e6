#include "adapt/curving_run.hpp"

#include <sys/resource.h>

#include <chrono>
#include <optional>

#include "adapt/proposal_node_source.hpp"
#include "base/error.hpp"
#include "mesh/consistency.hpp"

namespace hocav {
namespace {

double processor_seconds() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  auto seconds = [](const timeval& t) { return static_cast<double>(t.tv_sec) + 1e-6 * static_cast<double>(t.tv_usec); };
  return seconds(usage.ru_utime) + seconds(usage.ru_stime);
}

}  // namespace

template <int D>
CurvingWork curve_unmeasured(Mesh<D>& mesh, const MetricField<D>& field, const BoundaryGeometry<D>* geometry,
                             const ReinsertionOptions& options, const ProposalScope& scope) {
  CurvingWork work;
  const auto proposal_start = std::chrono::steady_clock::now();
  std::optional<BoundaryProposals<D>> proposals;
  std::optional<ProposalNodeSource<D>> boundary_nodes;
  if (geometry) {
    proposals.emplace(mesh, *geometry, scope);
    boundary_nodes.emplace(*proposals);
  }
  work.proposal_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - proposal_start).count();
  const double processor_start = processor_seconds();
  work.result = curve_by_reinsertion<D>(mesh, field, boundary_nodes ? &*boundary_nodes : nullptr, options);
  if (proposals) {
    work.completion = complete_boundary_proposals<D>(
        mesh, *proposals,
        {.jacobian_floor = options.cavity.jacobian_floor, .field = &field, .correction_steps = options.cavity.correction_steps});
    work.result.seconds += work.completion.seconds;
    work.proposals_left = static_cast<Index>(proposals->size());
  }
  work.cpu_seconds = processor_seconds() - processor_start;
  return work;
}

template <int D>
CurvingRun curve_with_boundary(Mesh<D>& mesh, const MetricField<D>& field, const BoundaryGeometry<D>* geometry,
                               const ReinsertionOptions& options, const ProposalScope& scope) {
  const Index points_before = mesh.vertex_count();
  const CurvingWork work = curve_unmeasured(mesh, field, geometry, options, scope);
  CurvingRun run;
  run.proposal_seconds = work.proposal_seconds;
  run.cpu_seconds = work.cpu_seconds;
  run.report = make_curving_report(mesh, field, points_before, work.result, work.proposals_left, options.threads);
  run.report.boundary_completion = work.completion;
  run.report.threads = options.threads;
  return run;
}

P2CavityOptions cavity_options(const CurvingOptions& options) {
  P2CavityOptions cavity;
  cavity.jacobian_floor = options.jacobian_floor;
  cavity.optimizer.rule = options.quadrature;
  return cavity;
}

ReinsertionOptions reinsertion_options(const CurvingOptions& options) {
  ReinsertionOptions reinsertion;
  reinsertion.cavity = cavity_options(options);
  reinsertion.passes = options.passes;
  reinsertion.threads = options.threads;
  reinsertion.progress = options.progress;
  return reinsertion;
}

template <int D>
void check_curved_consistency(const Mesh<D>& mesh) {
  ConsistencyOptions consistency;
  consistency.require_positive_orientation = false;
  if (auto problems = check_consistency(mesh, consistency); !problems.empty())
    throw Error("internal error: the curved mesh is inconsistent: " + problems.front());
}

template <int D>
CurvingReport curve_in_metric(Mesh<D>& mesh, const MetricField<D>& field, const BoundaryGeometry<D>* geometry,
                              const CurvingOptions& options) {
  CurvingReport report = curve_with_boundary<D>(mesh, field, geometry, reinsertion_options(options)).report;
  check_curved_consistency(mesh);
  return report;
}

template CurvingWork curve_unmeasured(Mesh<2>&, const MetricField<2>&, const BoundaryGeometry<2>*, const ReinsertionOptions&,
                                      const ProposalScope&);
template CurvingWork curve_unmeasured(Mesh<3>&, const MetricField<3>&, const BoundaryGeometry<3>*, const ReinsertionOptions&,
                                      const ProposalScope&);
template CurvingRun curve_with_boundary(Mesh<2>&, const MetricField<2>&, const BoundaryGeometry<2>*, const ReinsertionOptions&,
                                        const ProposalScope&);
template CurvingRun curve_with_boundary(Mesh<3>&, const MetricField<3>&, const BoundaryGeometry<3>*, const ReinsertionOptions&,
                                        const ProposalScope&);
template void check_curved_consistency(const Mesh<2>&);
template void check_curved_consistency(const Mesh<3>&);
template CurvingReport curve_in_metric(Mesh<2>&, const MetricField<2>&, const BoundaryGeometry<2>*, const CurvingOptions&);
template CurvingReport curve_in_metric(Mesh<3>&, const MetricField<3>&, const BoundaryGeometry<3>*, const CurvingOptions&);

}  // namespace hocav
