// Analytic scalar fields with their exact Hessians, for `hocav metric --hessian analytic:NAME` and
// for testing the Hessian recovery and the Lp metric (docs/method.md §10):
//   quadratic   u = x² + xy − 4y² (+ 9z² in 3D): a constant, indefinite Hessian
//               [[2, 1], [1, −8]] (3D: and 18 on the z diagonal);
//   tanh-shock  u = tanh((r − radius) / width), r = |x − origin|: a smooth step across the circle
//               (2D) or sphere (3D) of radius `radius`, about 2·width thick. With f(r) the profile,
//               H = f''(r) e_r e_rᵀ + f'(r)/r (I − e_r e_rᵀ); at r = 0, H = f''(0) I.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "geom/sym_mat.hpp"

namespace hocav {

struct AnalyticFieldSpec {
  std::string name = "tanh-shock";
  double radius = 0.75;                   // tanh-shock
  double width = 0.05;                    // tanh-shock
  std::array<double, 3> origin{0, 0, 0};  // tanh-shock
};

// The names accepted, for help texts and errors.
const std::vector<std::string>& analytic_field_names();

// u(x) and its Hessian; throw Error for an unknown name or a non-positive width.
template <int D>
double analytic_field(const AnalyticFieldSpec& spec, const Vec<D>& x);
template <int D>
SymMat<D> analytic_field_hessian(const AnalyticFieldSpec& spec, const Vec<D>& x);

}  // namespace hocav
