#include "adapt/adaptation_metric.hpp"

#include <algorithm>
#include <cmath>

#include "adapt/hausdorff_metric.hpp"
#include "base/error.hpp"
#include "base/thread_pool.hpp"
#include "geom/sym_eigen.hpp"
#include "geom/sym_functions.hpp"
#include "mesh/measure.hpp"

namespace hocav {

template <int D>
SymMat<D> AdaptationMetric<D>::metric_at(const Vec<D>& x, Index& hint) const {
  const SymMat<D> target = target_at(x, hint);
  if (!start_) return target;
  const auto sample = start_->sample_within(x, hint);
  hint = sample.where.element;
  return exp_sym((1 - fraction_) * sample.log_metric + fraction_ * log_spd(target));
}

template <int D>
AdaptationMetric<D> AdaptationMetric<D>::partway_from(const MetricField<D>& start, double fraction) const {
  for (const MetricField<D>* field : {field_, hausdorff_})
    if (field && field->back_mesh().element_count() != start.back_mesh().element_count())
      throw Error("a gradual metric's start is not on the metric's back mesh");
  AdaptationMetric partway = *this;
  if (fraction >= 1) return partway;  // the target itself, to the last bit
  partway.start_ = &start;
  partway.fraction_ = fraction;
  return partway;
}

template <int D>
SymMat<D> AdaptationMetric<D>::target_at(const Vec<D>& x, Index& hint) const {
  if (analytic_) {
    const SymMat<D> metric = analytic_metric<D>(*analytic_, x);
    if (!hausdorff_) return clamped(metric);
    const auto sample = hausdorff_->sample_within(x, hint);
    hint = sample.where.element;
    return clamped(within_bound(metric, exp_sym(sample.log_metric)));
  }
  const auto sample = field_->sample_within(x, hint);
  hint = sample.where.element;
  return clamped(exp_sym(sample.log_metric));
}

template <int D>
SymMat<D> AdaptationMetric<D>::clamped(const SymMat<D>& metric) const {
  if (bounds_.h_min <= 0 && bounds_.h_max >= 1e300) return metric;
  SymEigen<D> eigen = spd_eigen(metric);
  const double largest = bounds_.h_min > 0 ? 1 / (bounds_.h_min * bounds_.h_min) : 1e300;
  const double smallest = 1 / (bounds_.h_max * bounds_.h_max);
  for (int k = 0; k < D; ++k) eigen.values[k] = std::clamp(eigen.values[k], smallest, largest);
  return SymMat<D>::from_eigen(eigen.vectors, eigen.values);
}

template <int D>
std::vector<double> expected_element_counts(const Mesh<D>& input, const AdaptationMetric<D>& metric) {
  const double unit_volume = D == 3 ? std::sqrt(2.0) / 12 : std::sqrt(3.0) / 4;
  std::vector<double> counts(static_cast<std::size_t>(input.element_count()));
  Index hint = kNoIndex;
  for (Index k = 0; k < input.element_count(); ++k) {
    Vec<D> centroid{};
    for (Index v : input.element(k)) centroid = centroid + (1.0 / (D + 1)) * input.vertex(v);
    counts[k] = std::sqrt(determinant(metric.metric_at(centroid, hint))) * std::abs(element_measure(input, k)) / unit_volume;
  }
  return counts;
}

template <int D>
double expected_element_count(const Mesh<D>& input, const AdaptationMetric<D>& metric) {
  double total = 0;
  for (double count : expected_element_counts(input, metric)) total += count;
  return total;
}

template std::vector<double> expected_element_counts(const Mesh<2>&, const AdaptationMetric<2>&);
template std::vector<double> expected_element_counts(const Mesh<3>&, const AdaptationMetric<3>&);
template double expected_element_count(const Mesh<2>&, const AdaptationMetric<2>&);
template double expected_element_count(const Mesh<3>&, const AdaptationMetric<3>&);
// On the pool's threads, in chunks that each start their back-mesh walk afresh: the same metrics for
// any thread count.
template <int D>
std::vector<SymMat<D>> metrics_at_vertices(const Mesh<D>& mesh, const AdaptationMetric<D>& metric, int threads) {
  const auto count = static_cast<std::size_t>(mesh.vertex_count());
  std::vector<SymMat<D>> metrics(count);
  ThreadPool pool(std::max(1, threads));
  run_chunked(pool, count, 1024, [&](std::size_t begin, std::size_t end) {
    Index hint = kNoIndex;
    for (std::size_t v = begin; v < end; ++v) metrics[v] = metric.metric_at(mesh.vertex(static_cast<Index>(v)), hint);
  });
  return metrics;
}

template std::vector<SymMat<2>> metrics_at_vertices(const Mesh<2>&, const AdaptationMetric<2>&, int);
template std::vector<SymMat<3>> metrics_at_vertices(const Mesh<3>&, const AdaptationMetric<3>&, int);

template class AdaptationMetric<2>;
template class AdaptationMetric<3>;

}  // namespace hocav
