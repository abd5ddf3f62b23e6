// Where the Lp metric of a scalar field's Hessian comes from (docs/metrics.md): the field at a mesh
// file's nodes (FIELD.sol/.solb, its Hessian recovered), or analytic:NAME (its Hessian exact), with
// the metric's options. Shared by `hocav metric`, `hocav adapt` and their runs from pieces.
#pragma once

#include <optional>
#include <string>

#include "metric/analytic_field.hpp"
#include "metric/hessian_metric.hpp"

namespace hocav {

struct HessianSource {
  std::string field;
  AnalyticFieldSpec shape;  // of analytic:NAME (its name is taken from `field`)
  double complexity = 0;
  std::optional<double> norm;
  std::optional<double> h_min, h_max;  // default: kHessianSizeRange × h_max, the bounding-box diagonal
};

inline constexpr const char* kAnalyticFieldPrefix = "analytic:";
inline bool is_analytic_field(const std::string& field) { return field.starts_with(kAnalyticFieldPrefix); }

// The analytic field of an analytic:NAME source: its shape, named.
AnalyticFieldSpec analytic_field_of(const HessianSource& source);

// The Lp metric's options, the sizes' defaults made of the mesh's bounding-box diagonal.
LpMetricOptions lp_options_of(const HessianSource& source, double diagonal);

}  // namespace hocav
