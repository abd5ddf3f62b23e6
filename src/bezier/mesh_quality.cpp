// Curved-element quality over a whole mesh (docs/method.md §8, §11).
#include "bezier/mesh_quality.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "base/thread_pool.hpp"
#include "bezier/p2_element.hpp"

namespace hocav {

template <int D>
std::vector<JacobianQuality> mesh_jacobian_quality(const Mesh<D>& mesh, const RefinementOptions& options, int threads) {
  std::vector<JacobianQuality> qualities(mesh.element_count());
  ThreadPool pool(std::max(1, threads));
  run_chunked(pool, qualities.size(), kMeasuredChunk, [&](std::size_t begin, std::size_t end) {
    for (auto k = static_cast<Index>(begin); k < static_cast<Index>(end); ++k)
      qualities[k] = jacobian_quality(gather_p2_element(mesh, k), options);
  });
  return qualities;
}

ValueSummary summarize_values(std::span<const double> values, int bin_count, double histogram_lower, double histogram_upper) {
  ValueSummary summary;
  summary.histogram_lower = histogram_lower;
  summary.histogram_upper = histogram_upper;
  summary.histogram.assign(std::max(bin_count, 1), 0);
  if (values.empty()) return summary;
  summary.count = checked_index(values.size(), "values");
  summary.min = summary.max = values[0];
  double sum = 0.0;
  const double bin_width = (histogram_upper - histogram_lower) / double(summary.histogram.size());
  for (double value : values) {
    summary.min = std::min(summary.min, value);
    summary.max = std::max(summary.max, value);
    sum += value;
    if (!(value > 0.0)) ++summary.invalid_count;  // NaN included
    if (value < histogram_lower) {
      ++summary.below;
    } else if (value > histogram_upper) {
      ++summary.above;
    } else if (!std::isnan(value)) {
      const auto bin = static_cast<std::size_t>((value - histogram_lower) / bin_width);
      ++summary.histogram[std::min(bin, summary.histogram.size() - 1)];
    }
  }
  summary.average = sum / double(values.size());
  return summary;
}

ValueSummary merge_summaries(const ValueSummary& a, const ValueSummary& b) {
  if (b.count == 0) return a;
  if (a.count == 0) return b;
  if (a.histogram.size() != b.histogram.size() || a.histogram_lower != b.histogram_lower || a.histogram_upper != b.histogram_upper)
    throw std::logic_error("merge_summaries: summaries with other bins");
  ValueSummary sum = a;
  sum.count = a.count + b.count;
  sum.min = std::min(a.min, b.min);
  sum.max = std::max(a.max, b.max);
  sum.average = (a.average * double(a.count) + b.average * double(b.count)) / double(sum.count);
  sum.invalid_count += b.invalid_count;
  for (std::size_t i = 0; i < sum.histogram.size(); ++i) sum.histogram[i] += b.histogram[i];
  sum.below += b.below;
  sum.above += b.above;
  return sum;
}

MeshJacobianSummary summarize_jacobian_quality(std::span<const JacobianQuality> qualities, int bin_count) {
  std::vector<double> min_normalized(qualities.size()), scaled(qualities.size());
  for (std::size_t k = 0; k < qualities.size(); ++k) {
    min_normalized[k] = qualities[k].min_normalized_jacobian;
    scaled[k] = qualities[k].scaled_jacobian;
  }
  return {summarize_values(min_normalized, bin_count, 0.0, 1.0), summarize_values(scaled, bin_count, 0.0, 1.0)};
}

template std::vector<JacobianQuality> mesh_jacobian_quality(const Mesh<2>&, const RefinementOptions&, int);
template std::vector<JacobianQuality> mesh_jacobian_quality(const Mesh<3>&, const RefinementOptions&, int);

}  // namespace hocav
