#include "parallel/gradual_metric.hpp"

#include <algorithm>
#include <cmath>

#include "geom/sym_functions.hpp"
#include "metric/gradation.hpp"

namespace hocav {

template <int D>
int gradual_steps(const Mesh<D>& input, const MetricField<D>& input_metric, const AdaptationMetric<D>& metric, int max_steps) {
  double ratio = 1;
  Index hint = kNoIndex;
  for (Index v = 0; v < input.vertex_count(); ++v) {
    const SymMat<D> own = exp_sym(input_metric.vertex_log_metric(v));
    ratio = std::max(ratio, std::sqrt(largest_relative_eigenvalue(metric.metric_at(input.vertex(v), hint), own)));
  }
  const int steps = static_cast<int>(std::ceil(std::log(ratio) / std::log(kGradualRefinement) - 1e-9));
  return std::clamp(steps, 1, max_steps);
}

template int gradual_steps(const Mesh<2>&, const MetricField<2>&, const AdaptationMetric<2>&, int);
template int gradual_steps(const Mesh<3>&, const MetricField<3>&, const AdaptationMetric<3>&, int);

}  // namespace hocav
