#include "curve/edge_length_integral.hpp"

#include <cmath>

#include "geom/sym_functions.hpp"

namespace hocav {
namespace {

// The P2 curve t ↦ γ(t) through a, node, b and its tangent (docs/method.md §4).
template <int D>
struct P2Curve {
  Vec<D> a, node, b;
  Vec<D> point(double t) const { return (1 - t) * (1 - 2 * t) * a + 4 * t * (1 - t) * node + t * (2 * t - 1) * b; }
  Vec<D> tangent(double t) const { return (4 * t - 3) * a + 4 * (1 - 2 * t) * node + (4 * t - 1) * b; }
};

// sqrt(uᵀ exp(T) u), in the eigenbasis of T (relatively accurate at any anisotropy).
template <int D>
double metric_length(const SymMat<D>& log_metric, const Vec<D>& u) {
  return std::sqrt(ExpFrechet<D>(log_metric).squared_length(u));
}

// The localized integrand; successive points reuse the last element as hint and the locator's scratch
// (one object per thread).
template <int D>
class LocalizedIntegrand {
 public:
  LocalizedIntegrand(const MetricField<D>& field, const P2Curve<D>& curve) : field_(field), curve_(curve) {}
  double operator()(double t) {
    auto sample = field_.sample(curve_.point(t), hint_, scratch_);
    hint_ = sample.where.element;
    return metric_length(sample.log_metric, curve_.tangent(t));
  }

 private:
  const MetricField<D>& field_;
  P2Curve<D> curve_;
  Index hint_ = kNoIndex;
  LocatorScratch scratch_;
};

}  // namespace

template <int D>
double true_edge_length(const MetricField<D>& field, const Vec<D>& a, const Vec<D>& b, const Vec<D>& node, const QuadratureRule& rule) {
  LocalizedIntegrand<D> integrand(field, {a, node, b});
  double length = 0;
  for (std::size_t q = 0; q < rule.nodes.size(); ++q) length += rule.weights[q] * integrand(rule.nodes[q]);
  return length;
}

template <int D>
AdaptiveIntegral adaptive_true_edge_length(const MetricField<D>& field, const Vec<D>& a, const Vec<D>& b, const Vec<D>& node,
                                           double tolerance) {
  LocalizedIntegrand<D> integrand(field, {a, node, b});
  // Kinked: 16 initial pieces, so that chance agreements of K15 and G7 on long pieces across several
  // back-mesh faces do not end it early (with 1 or 4, an error 4× the tolerance was seen at 1e-5).
  return adaptive_integral([&](double t) { return integrand(t); }, tolerance, 16);
}

template <int D>
AdaptiveIntegral adaptive_edge_length(const MetricField<D>& field, const Vec<D>& a, const Vec<D>& b, const SymMat<D>& log_a,
                                      const SymMat<D>& log_b, const Vec<D>& node, double tolerance, Index hint) {
  const P2Curve<D> curve{a, node, b};
  const SymMat<D> log_node = field.log_metric_at(node, hint);
  return adaptive_integral(
      [&](double t) {
        const SymMat<D> log_metric = (1 - t) * (1 - 2 * t) * log_a + 4 * t * (1 - t) * log_node + t * (2 * t - 1) * log_b;
        return metric_length(log_metric, curve.tangent(t));
      },
      tolerance);
}

#define HOCAV_INSTANTIATE(D)                                                                                                              \
  template double true_edge_length(const MetricField<D>&, const Vec<D>&, const Vec<D>&, const Vec<D>&, const QuadratureRule&);            \
  template AdaptiveIntegral adaptive_true_edge_length(const MetricField<D>&, const Vec<D>&, const Vec<D>&, const Vec<D>&, double);        \
  template AdaptiveIntegral adaptive_edge_length(const MetricField<D>&, const Vec<D>&, const Vec<D>&, const SymMat<D>&, const SymMat<D>&, \
                                                 const Vec<D>&, double, Index);
HOCAV_INSTANTIATE(2)
HOCAV_INSTANTIATE(3)
#undef HOCAV_INSTANTIATE

}  // namespace hocav
