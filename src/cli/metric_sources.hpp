// Metric sources that `hocav metric` and `hocav adapt` share (docs/usage.md): each gives the metric at
// the vertices of a mesh read from a file.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "geom/sym_mat.hpp"
#include "io/mesh_file.hpp"
#include "mesh/mesh.hpp"
#include "metric/analytic_field.hpp"

namespace hocav {

// The Lp metric of a scalar field's Hessian (docs/metrics.md): the field at the file's nodes
// (FIELD.sol/.solb, its Hessian recovered), or analytic:NAME (its Hessian exact).
struct HessianSource {
  std::string field;
  AnalyticFieldSpec shape;  // of analytic:NAME (its name is taken from `field`)
  double complexity = 0;
  std::optional<double> norm;
  std::optional<double> h_min, h_max;  // default: kHessianSizeRange × h_max, the bounding-box diagonal
};

inline constexpr const char* kAnalyticFieldPrefix = "analytic:";
inline bool is_analytic_field(const std::string& field) { return field.starts_with(kAnalyticFieldPrefix); }

template <int D>
std::vector<SymMat<D>> hessian_source_metrics(const Mesh<D>& mesh, const MeshFileContent& file, const HessianSource& source);

// The surface metric (docs/metrics.md): size `normal` across the boundary and `tangential` along it;
// inside, h_max (default the bounding-box diagonal) until a gradation carries the boundary's sizes in.
template <int D>
std::vector<SymMat<D>> surface_source_metrics(const Mesh<D>& mesh, double normal, double tangential, std::optional<double> h_max);

}  // namespace hocav
