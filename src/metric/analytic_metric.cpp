#include "metric/analytic_metric.hpp"

#include <cmath>

#include "base/error.hpp"

namespace hocav {
namespace {

void check_size(double h, const char* name) {
  if (!(h > 0) || !std::isfinite(h)) throw Error(std::string("analytic metric: ") + name + " must be positive");
}

// The sizes of a graded metric: both positive, the smallest first (else sizes past h-max, or
// infinite ones where the linear size crosses zero).
void check_size_range(const AnalyticMetricSpec& spec) {
  check_size(spec.h_min, "h-min");
  check_size(spec.h_max, "h-max");
  if (spec.h_min > spec.h_max) throw Error("analytic metric: h-min must not exceed h-max");
}

template <int D>
SymMat<D> shear_metric(const AnalyticMetricSpec& spec, const Vec<D>& x) {
  check_size_range(spec);
  check_size(spec.width, "width");
  Vec<D> radial;
  for (int i = 0; i < D; ++i) radial[i] = x[i] - spec.origin[static_cast<std::size_t>(i)];
  double r = norm(radial);
  double tangential = 1 / (spec.h_max * spec.h_max);
  if (r == 0) return tangential * SymMat<D>::identity();
  radial *= 1 / r;
  double s = (r - spec.radius) / spec.width;
  double h_r = spec.h_max + (spec.h_min - spec.h_max) * std::exp(-s * s);
  double across = 1 / (h_r * h_r);
  // h_t⁻² I + (h_r⁻² − h_t⁻²) e_r e_rᵀ equals both forms of the header (e_t e_tᵀ = I − e_r e_rᵀ in 2D).
  SymMat<D> m = tangential * SymMat<D>::identity();
  for (int i = 0; i < D; ++i)
    for (int j = 0; j <= i; ++j) m(i, j) += (across - tangential) * radial[i] * radial[j];
  return m;
}

}  // namespace

const std::vector<std::string>& analytic_metric_names() {
  static const std::vector<std::string> names{"uniform", "linear", "shear-circle", "shear-sphere"};
  return names;
}

template <int D>
SymMat<D> analytic_metric(const AnalyticMetricSpec& spec, const Vec<D>& x) {
  if (spec.name == "uniform") {
    check_size(spec.h, "h");
    return (1 / (spec.h * spec.h)) * SymMat<D>::identity();
  }
  if (spec.name == "linear") {
    check_size_range(spec);
    int axis = spec.axis < 0 ? D - 1 : spec.axis;
    if (axis >= D) throw Error("analytic metric linear: axis " + std::to_string(axis) + " in " + std::to_string(D) + "D");
    double h_axis = spec.h_min + 2 * (spec.h_max - spec.h_min) * std::abs(x[axis] - spec.center);
    SymMat<D> m = (1 / (spec.h_max * spec.h_max)) * SymMat<D>::identity();
    m(axis, axis) = 1 / (h_axis * h_axis);
    return m;
  }
  if (spec.name == "shear-circle" || spec.name == "shear-sphere") {
    if ((spec.name == "shear-circle") != (D == 2))
      throw Error("analytic metric " + spec.name + " is for " + (D == 2 ? "3D" : "2D") + " meshes");
    return shear_metric<D>(spec, x);
  }
  std::string known;
  for (const auto& name : analytic_metric_names()) known += " " + name;
  throw Error("unknown analytic metric '" + spec.name + "' (known:" + known + ")");
}

template <int D>
std::vector<SymMat<D>> analytic_metric_at_vertices(const AnalyticMetricSpec& spec, const Mesh<D>& mesh) {
  std::vector<SymMat<D>> metrics;
  metrics.reserve(static_cast<std::size_t>(mesh.vertex_count()));
  for (const auto& x : mesh.vertices()) metrics.push_back(analytic_metric<D>(spec, x));
  return metrics;
}

template SymMat<2> analytic_metric(const AnalyticMetricSpec&, const Vec<2>&);
template SymMat<3> analytic_metric(const AnalyticMetricSpec&, const Vec<3>&);
template std::vector<SymMat<2>> analytic_metric_at_vertices(const AnalyticMetricSpec&, const Mesh<2>&);
template std::vector<SymMat<3>> analytic_metric_at_vertices(const AnalyticMetricSpec&, const Mesh<3>&);

}  // namespace hocav
