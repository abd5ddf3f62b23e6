#include "adapt/adaptation_metric.hpp"

#include <algorithm>

#include "geom/sym_eigen.hpp"
#include "geom/sym_functions.hpp"

namespace hocav {

template <int D>
SymMat<D> AdaptationMetric<D>::metric_at(const Vec<D>& x, Index& hint) const {
  if (analytic_) return clamped(analytic_metric<D>(*analytic_, x));
  const auto sample = field_->sample(x, hint);
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

template class AdaptationMetric<2>;
template class AdaptationMetric<3>;

}  // namespace hocav
