// The quality of a curved (P2) element in a metric (docs/curving.md §Curved quality): the metric
// mean ratio of the element's Jacobian, averaged over a quadrature rule on the reference simplex,
// with the metric interpolated log-Euclidean from the vertices' metrics. On a straight element in
// a constant metric it is the P1 metric mean ratio (metric/metric_quality.hpp) exactly; it is
// negative where the Jacobian is. Its gradient with respect to the P2 nodes drives node moves.
#pragma once

#include <array>

#include "bezier/p2_element.hpp"
#include "geom/sym_mat.hpp"

namespace hocav {

template <int D>
struct CurvedQuality {
  double value = 0;
  std::array<Vec<D>, kP2NodeCount<D>> gradient{};  // ∂value/∂node, in P2Element's node order
};

// `vertex_log_metrics[i]` is log M at vertex i.
template <int D>
CurvedQuality<D> curved_mean_ratio(const P2Element<D>& element, const std::array<SymMat<D>, D + 1>& vertex_log_metrics);

}  // namespace hocav
