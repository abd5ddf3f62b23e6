// The gradual metric of a distributed run (docs/distributed.md §A gradual metric): its whole-mesh
// iterations step from the input's own metric to the target, so that each starts at most a few
// times coarser than it asks and its frozen interfaces stay near their metric.
#pragma once

#include "adapt/adaptation_metric.hpp"

namespace hocav {

// A whole-mesh iteration asks for sizes at most this many times finer than the mesh it starts from
// (where the metric is finest against the input), if the steps allow.
constexpr double kGradualRefinement = 5;

// The steps from the input's own metric to the target: enough for the largest ratio of the input's
// sizes to the target's, at the vertices of `input` (the whole input, or a piece of it: the
// pieces' largest is the whole's), to take steps of at most kGradualRefinement, and 1 to `max_steps`.
template <int D>
int gradual_steps(const Mesh<D>& input, const MetricField<D>& input_metric, const AdaptationMetric<D>& metric, int max_steps);

// The share of the way from the input's own metric to the target that iteration `iteration` (from
// 1) adapts to: the steps are even, and the iterations after them and the last runs adapt to the target.
inline double gradual_fraction(int iteration, int steps) { return std::min(1.0, static_cast<double>(iteration) / steps); }

}  // namespace hocav
