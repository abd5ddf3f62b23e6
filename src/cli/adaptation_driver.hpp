// The paper's pipeline as `hocav adapt` and `hocav demo` run it: the P1 adaptation loop, the metric
// measured on its output, then (optionally) the curving of `hocav curve` in that metric.
#pragma once

#include <memory>
#include <optional>

#include "adapt/adaptation_loop.hpp"
#include "cli/command_support.hpp"
#include "report/adaptation_report.hpp"

namespace hocav {

template <int D>
struct AdaptedMesh {
  AdaptationReport report;
  // The metric on the adapted mesh (its vertices carry the clamped metric the loop used): the
  // curving's field and the .vtu's.
  std::unique_ptr<MetricField<D>> field;
};

// Adapts `mesh` (P1, compact) to `metric`, new boundary points on `geometry`; then, with `curving`,
// curves it. Fills the report's figures from the input's and output's counts.
template <int D>
AdaptedMesh<D> adapt_and_curve(Mesh<D>& mesh, const AdaptationMetric<D>& metric, const BoundaryGeometry<D>* geometry,
                               const AdaptationSettings& settings, const std::optional<CurvingSettings>& curving);

}  // namespace hocav
