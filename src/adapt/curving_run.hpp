// One curving of a mesh in its metric, as `hocav curve`, `hocav demo` and `hocav bench` run it:
// boundary proposals from a geometry (none: boundary nodes stay), every volume vertex reinserted
// by the P2 cavity operator, the proposals no cavity consumed placed by a last pass
// (proposal_completion.hpp; its time counts in the curving time), the output measured.
#pragma once

#include "adapt/reinsertion_curving.hpp"
#include "report/curving_report.hpp"
#include "surface/boundary_geometry.hpp"

namespace hocav {

struct CurvingRun {
  CurvingReport report;
  double proposal_seconds = 0;  // wall time building the boundary proposals
  double cpu_seconds = 0;       // processor time of the reinsertion, all threads
};

template <int D>
CurvingRun curve_with_boundary(Mesh<D>& mesh, const MetricField<D>& field, const BoundaryGeometry<D>* geometry,
                               const ReinsertionOptions& options);

}  // namespace hocav
