#include "adapt/element_guard.hpp"

#include <algorithm>
#include <array>

#include "bezier/jacobian_bounds.hpp"
#include "bezier/p2_element.hpp"
#include "curve/curved_quality.hpp"

namespace hocav {

template <int D>
ElementGuard<D>::ElementGuard(const Mesh<D>& mesh, std::vector<Index> elements, double jacobian_floor, const MetricField<D>* field)
    : mesh_(mesh), elements_(std::move(elements)), jacobian_floor_(jacobian_floor), field_(field) {
  if (!field_) return;
  bars_.reserve(elements_.size());
  for (Index k : elements_) {
    const double before = quality(k);
    // Less round-off: a node moved by 1e-16 must not be refused for a quality 1e-17 lower.
    bars_.push_back(std::max(0.7 * before, std::min(before, 0.1)) - 1e-12);
  }
}

template <int D>
bool ElementGuard<D>::holds(long long& elements_certified) const {
  for (std::size_t i = 0; i < elements_.size(); ++i) {
    ++elements_certified;
    if (!certify_min_normalized_jacobian_above(gather_p2_element(mesh_, elements_[i]), jacobian_floor_)) return false;
    if (field_ && !(quality(elements_[i]) >= bars_[i])) return false;
  }
  return true;
}

template <int D>
double ElementGuard<D>::quality(Index k) const {
  std::array<SymMat<D>, D + 1> log_metrics;
  const auto& vertices = mesh_.element(k);
  const bool on_back_mesh = &field_->back_mesh() == &mesh_;  // `hocav curve`'s field: the vertices' own metrics
  for (int i = 0; i <= D; ++i)
    log_metrics[i] = on_back_mesh ? field_->vertex_log_metric(vertices[i]) : field_->log_metric_at(mesh_.vertex(vertices[i]));
  return curved_mean_ratio(gather_p2_element(mesh_, k), log_metrics).value;
}

template class ElementGuard<2>;
template class ElementGuard<3>;

}  // namespace hocav
