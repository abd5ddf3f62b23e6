// A distributed run's metric on a share of the back mesh (back_mesh_share.hpp, docs/distributed.md
// §The back mesh in shares): the same metric as rank 0's, made from the share's fields.
#pragma once

#include <optional>
#include <vector>

#include "adapt/adaptation_metric.hpp"
#include "parallel/back_mesh_share.hpp"

namespace hocav {

// What a run's metric is made of besides its fields, the same on every process: analytic or a field
// on the back mesh, its size bounds, and for an analytic one whether a Hausdorff bound field goes with it.
struct MetricRecipe {
  std::optional<AnalyticMetricSpec> analytic;
  SizeBounds bounds;
  bool hausdorff = false;
};

template <int D>
MetricRecipe recipe_of(const AdaptationMetric<D>& metric);

// On rank 0, per field of a share, the log-metric at each back vertex: first the input's own metric
// (where the gradual metric starts), then the field of `metric` (a field's, or an analytic metric's
// Hausdorff bound) if it has one. `input_metric` and that field have the same back mesh.
template <int D>
std::vector<std::vector<SymMat<D>>> share_log_metrics(const AdaptationMetric<D>& metric, const MetricField<D>& input_metric);

template <int D>
class ShareMetric {
 public:
  // `share` holds the fields share_log_metrics lists, for `recipe`; its mesh and log-metrics become
  // the fields' (the mesh with its topology built), not copied.
  ShareMetric(BackMeshShare<D> share, MetricRecipe recipe);
  ShareMetric(const ShareMetric&) = delete;  // the metrics it makes point at its fields
  ShareMetric& operator=(const ShareMetric&) = delete;

  // The run's metric a fraction of the way from the input's own (AdaptationMetric::partway_from);
  // it refers to this object.
  AdaptationMetric<D> partway(double fraction) const;

 private:
  MetricRecipe recipe_;
  MetricField<D> start_;
  std::optional<MetricField<D>> field_;  // the target's, or the analytic metric's Hausdorff bound
};

extern template class ShareMetric<2>;
extern template class ShareMetric<3>;

}  // namespace hocav
