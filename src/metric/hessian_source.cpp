#include "metric/hessian_source.hpp"

namespace hocav {

AnalyticFieldSpec analytic_field_of(const HessianSource& source) {
  AnalyticFieldSpec shape = source.shape;
  shape.name = source.field.substr(std::string(kAnalyticFieldPrefix).size());
  return shape;
}

LpMetricOptions lp_options_of(const HessianSource& source, double diagonal) {
  LpMetricOptions lp;
  lp.complexity = source.complexity;
  lp.norm = source.norm.value_or(lp.norm);
  lp.h_max = source.h_max.value_or(diagonal);
  lp.h_min = source.h_min.value_or(kHessianSizeRange * lp.h_max);
  return lp;
}

}  // namespace hocav
