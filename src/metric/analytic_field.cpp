#include "metric/analytic_field.hpp"

#include <cmath>

#include "base/error.hpp"

namespace hocav {
namespace {

[[noreturn]] void unknown_field(const std::string& name) {
  std::string known;
  for (const auto& field : analytic_field_names()) known += " " + field;
  throw Error("unknown analytic field '" + name + "' (known:" + known + ")");
}

// x − origin and its length, for the radial field.
template <int D>
Vec<D> from_origin(const AnalyticFieldSpec& spec, const Vec<D>& x) {
  if (!(spec.width > 0) || !std::isfinite(spec.width)) throw Error("analytic field: width must be positive");
  Vec<D> radial;
  for (int i = 0; i < D; ++i) radial[i] = x[i] - spec.origin[static_cast<std::size_t>(i)];
  return radial;
}

// The quadratic's Hessian, in 2D the leading block.
template <int D>
SymMat<D> quadratic_hessian() {
  SymMat<D> h;
  h(0, 0) = 2;
  h(1, 0) = 1;
  h(1, 1) = -8;
  if constexpr (D == 3) h(2, 2) = 18;
  return h;
}

}  // namespace

const std::vector<std::string>& analytic_field_names() {
  static const std::vector<std::string> names{"quadratic", "tanh-shock"};
  return names;
}

template <int D>
double analytic_field(const AnalyticFieldSpec& spec, const Vec<D>& x) {
  if (spec.name == "quadratic") return 0.5 * quadratic_form(quadratic_hessian<D>(), x);
  if (spec.name == "tanh-shock") return std::tanh((norm(from_origin(spec, x)) - spec.radius) / spec.width);
  unknown_field(spec.name);
}

template <int D>
SymMat<D> analytic_field_hessian(const AnalyticFieldSpec& spec, const Vec<D>& x) {
  if (spec.name == "quadratic") return quadratic_hessian<D>();
  if (spec.name != "tanh-shock") unknown_field(spec.name);
  Vec<D> radial = from_origin(spec, x);
  double r = norm(radial);
  double t = std::tanh((r - spec.radius) / spec.width);
  double first = (1 - t * t) / spec.width;                           // f'(r)
  double second = -2 * t * (1 - t * t) / (spec.width * spec.width);  // f''(r)
  if (r == 0) return second * SymMat<D>::identity();
  return (first / r) * SymMat<D>::identity() + (second - first / r) * outer((1 / r) * radial);
}

template double analytic_field(const AnalyticFieldSpec&, const Vec<2>&);
template double analytic_field(const AnalyticFieldSpec&, const Vec<3>&);
template SymMat<2> analytic_field_hessian(const AnalyticFieldSpec&, const Vec<2>&);
template SymMat<3> analytic_field_hessian(const AnalyticFieldSpec&, const Vec<3>&);

}  // namespace hocav
