// Analytic metric fields for tests, benchmarks and `hocav metric --analytic` (docs/method.md §10).
//   uniform       M = h⁻² I
//   linear        size h_axis(s) = h_min + 2 (h_max − h_min) |s − center| along one axis (s = that
//                 coordinate; the UGAWG "linear" field with the defaults), h_max across it
//   shear-circle  (2D) M = h_r⁻² e_r e_rᵀ + h_t⁻² e_t e_tᵀ around `origin`, with
//   shear-sphere  (3D) M = h_r⁻² e_r e_rᵀ + h_t⁻² (I − e_r e_rᵀ)
//                 h_r(r) = h_max + (h_min − h_max) exp(−((r − radius)/width)²), h_t = h_max:
//                 small sizes across a circular (spherical) layer of radius `radius` — a field with
//                 intrinsic curvature (the paper's Fig. 1). At r = 0, M = h_max⁻² I.
#pragma once

#include <string>
#include <vector>

#include "geom/sym_mat.hpp"
#include "mesh/mesh.hpp"

namespace hocav {

struct AnalyticMetricSpec {
  std::string name = "uniform";
  double h = 0.1;                         // uniform
  double h_min = 0.001;                   // linear, shear
  double h_max = 0.1;                     // linear, shear
  int axis = -1;                          // linear: 0 x, 1 y, 2 z; −1 = the last axis
  double center = 0.5;                    // linear
  double radius = 0.75;                   // shear
  double width = 0.05;                    // shear
  std::array<double, 3> origin{0, 0, 0};  // shear
};

// The names accepted, for help texts and errors.
const std::vector<std::string>& analytic_metric_names();

// M at x; throws Error for an unknown name, a name of the other dimension, or non-positive sizes.
template <int D>
SymMat<D> analytic_metric(const AnalyticMetricSpec& spec, const Vec<D>& x);

// M at every vertex of the mesh.
template <int D>
std::vector<SymMat<D>> analytic_metric_at_vertices(const AnalyticMetricSpec& spec, const Mesh<D>& mesh);

}  // namespace hocav
