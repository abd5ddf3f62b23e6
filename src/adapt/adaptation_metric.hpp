// The metric an adaptation run adapts to (docs/adaptation.md §Metric): either a field on a back mesh
// (the input mesh with a metric at its vertices, log-Euclidean interpolation) or an analytic field
// evaluated exactly at every new vertex, then intersected with the Hausdorff bound where that is
// finer (hausdorff_metric.hpp; a field on a back mesh has the bound in its vertex metrics already);
// sizes clamped to [h_min, h_max] in both cases.
#pragma once

#include <optional>
#include <vector>

#include "geom/sym_mat.hpp"
#include "metric/analytic_metric.hpp"
#include "metric/metric_field.hpp"

namespace hocav {

struct SizeBounds {
  double h_min = 0;      // 0: no lower bound on the sizes
  double h_max = 1e300;  // no upper bound
};

template <int D>
class AdaptationMetric {
 public:
  // The field must outlive this object.
  AdaptationMetric(const MetricField<D>& field, SizeBounds bounds) : field_(&field), bounds_(bounds) {}
  // `hausdorff`, when given, must outlive this object.
  AdaptationMetric(AnalyticMetricSpec spec, SizeBounds bounds, const MetricField<D>* hausdorff = nullptr)
      : hausdorff_(hausdorff), analytic_(std::move(spec)), bounds_(bounds) {}

  // The metric at x, clamped. `hint`: a back element near x (kNoIndex: none), updated to where x
  // fell; unused by an analytic field without a Hausdorff bound.
  SymMat<D> metric_at(const Vec<D>& x, Index& hint) const;

  // Clamps a metric's sizes to the bounds (eigenvalues to [1/h_max², 1/h_min²]).
  SymMat<D> clamped(const SymMat<D>& metric) const;

  // This metric a fraction t ∈ [0, 1] of the way from `start`'s, log-Euclidean: log M_t =
  // (1 − t) log M_start + t log M (a distributed run's early iterations, docs/distributed.md §A
  // gradual metric). `start` must be on this metric's back mesh (they share hints) and outlive the
  // result. A fraction of 1 gives this metric itself.
  AdaptationMetric partway_from(const MetricField<D>& start, double fraction) const;

  // What it is made of (a distributed run remakes it on a share of the back mesh): the analytic
  // field, if it is one; its field on the back mesh, a field's or an analytic metric's Hausdorff
  // bound (null: none); its size bounds.
  const std::optional<AnalyticMetricSpec>& analytic() const { return analytic_; }
  const MetricField<D>* field() const { return field_ ? field_ : hausdorff_; }
  SizeBounds bounds() const { return bounds_; }

 private:
  SymMat<D> target_at(const Vec<D>& x, Index& hint) const;

  const MetricField<D>* field_ = nullptr;
  const MetricField<D>* hausdorff_ = nullptr;  // with an analytic field: the bound on its back mesh
  std::optional<AnalyticMetricSpec> analytic_;
  SizeBounds bounds_;
  const MetricField<D>* start_ = nullptr;  // with partway_from: where the metric starts
  double fraction_ = 1;
};

// The output's element count `metric` asks for inside each element of `input`: ∫ √det M over the
// element (the metric at its centroid) divided by the metric volume of a regular unit simplex (√2/12
// in 3D, √3/4 in 2D). The load of a part in a distributed run (docs/distributed.md).
template <int D>
std::vector<double> expected_element_counts(const Mesh<D>& input, const AdaptationMetric<D>& metric);

// Their sum: the output's element count on the domain of `input` (its complexity over the unit
// simplex's metric volume). For the memory check before a run.
template <int D>
double expected_element_count(const Mesh<D>& input, const AdaptationMetric<D>& metric);

// `metric` at every vertex of `mesh`, on `threads` threads: the same for any count.
template <int D>
std::vector<SymMat<D>> metrics_at_vertices(const Mesh<D>& mesh, const AdaptationMetric<D>& metric, int threads);

extern template class AdaptationMetric<2>;
extern template class AdaptationMetric<3>;

}  // namespace hocav
