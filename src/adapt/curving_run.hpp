// One curving of a mesh in its metric, as `hocav curve`, `hocav demo`, `hocav bench` and the Python
// module run it: boundary proposals from a geometry (none: boundary nodes stay), every volume vertex
// reinserted by the P2 cavity operator, the proposals no cavity consumed placed by a last pass
// (proposal_completion.hpp; its time counts in the curving time), the output measured (docs/curving.md).
#pragma once

#include <functional>

#include "adapt/proposal_completion.hpp"
#include "adapt/reinsertion_curving.hpp"
#include "curve/quadrature.hpp"
#include "report/curving_report.hpp"
#include "surface/boundary_geometry.hpp"
#include "surface/boundary_proposals.hpp"

namespace hocav {

struct CurvingRun {
  CurvingReport report;
  double proposal_seconds = 0;  // wall time building the boundary proposals
  double cpu_seconds = 0;       // processor time of the reinsertion, all threads
};

// A curving's work without the measures of its output.
struct CurvingWork {
  ReinsertionResult result;       // its seconds include the last pass's
  ProposalCompletion completion;  // the last pass over the proposals no cavity consumed
  Index proposals_left = 0;       // proposals no cavity consumed
  double proposal_seconds = 0;    // wall time building the boundary proposals
  double cpu_seconds = 0;         // processor time of the reinsertion, all threads
};

// `scope`: which boundary edges get a proposal (boundary_proposals.hpp; by default every one).
// Without measuring the output: for a caller that measures what it merges (a distributed part).
template <int D>
CurvingWork curve_unmeasured(Mesh<D>& mesh, const MetricField<D>& field, const BoundaryGeometry<D>* geometry,
                             const ReinsertionOptions& options, const ProposalScope& scope = {});

// curve_unmeasured, then the output measured.
template <int D>
CurvingRun curve_with_boundary(Mesh<D>& mesh, const MetricField<D>& field, const BoundaryGeometry<D>* geometry,
                               const ReinsertionOptions& options, const ProposalScope& scope = {});

// The options of `hocav curve` (docs/usage.md).
struct CurvingOptions {
  QuadratureRule quadrature = default_optimizer_rule();  // of the length the edge optimizer minimizes
  double jacobian_floor = 0.01;                          // every element the operator creates keeps its min normalized Jacobian above
  int passes = 1;                                        // reinsertion passes over the volume vertices
  int threads = 1;                                       // the output does not depend on it
  // Called now and then with the fraction of the work done.
  std::function<void(double)> progress;
};

// The P2 cavity operator's options of a curving (its floor and quadrature).
P2CavityOptions cavity_options(const CurvingOptions& options);
// The reinsertion's options of a curving (its cavity options, passes, threads, progress).
ReinsertionOptions reinsertion_options(const CurvingOptions& options);

// Error ("internal error: ...") unless the curved `mesh` is consistent (a valid curved element may be
// an inverted P1 one).
template <int D>
void check_curved_consistency(const Mesh<D>& mesh);

// The paper's algorithm on `mesh` (P1 or P2; the field's back mesh is its P1 copy, or any mesh
// covering it): boundary nodes proposed from `geometry` (may be null), every volume vertex
// reinserted, the result checked consistent (Error otherwise) and measured.
template <int D>
CurvingReport curve_in_metric(Mesh<D>& mesh, const MetricField<D>& field, const BoundaryGeometry<D>* geometry,
                              const CurvingOptions& options);

}  // namespace hocav
