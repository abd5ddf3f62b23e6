// The tests every operator of the loop shares: worst qualities, length windows, neighbours, and
// the names of refusals (adaptation_operations.hpp).
#include <algorithm>
#include <limits>

#include "adapt/adaptation_operations.hpp"
#include "base/small_set.hpp"

namespace hocav {

template <int D>
double worst_quality(const AdaptationMesh<D>& am, std::span<const Index> elements) {
  double worst = std::numeric_limits<double>::infinity();
  for (Index k : elements) worst = std::min(worst, am.quality(k));
  return worst;
}

template <int D>
double worst_planned_quality(const AdaptationMesh<D>& am, const CavityOperator<D>& plan) {
  double worst = std::numeric_limits<double>::infinity();
  for (const auto& element : plan.new_elements()) worst = std::min(worst, am.quality(element));
  return worst;
}

template <int D>
bool edges_from_within(const AdaptationMesh<D>& am, Index center, std::span<const typename Mesh<D>::Element> elements, double longest) {
  for (const auto& element : elements)
    for (Index w : element)
      if (w != center && am.edge_length(center, w) > longest) return false;
  return true;
}

const char* to_string(Refusal refusal) {
  switch (refusal) {
    case Refusal::kNone: return "accepted";
    case Refusal::kClasses: return "classes";
    case Refusal::kTopology: return "topology";
    case Refusal::kQuality: return "quality";
    case Refusal::kLength: return "length";
    case Refusal::kGeometry: return "geometry";
  }
  return "?";
}

template <int D>
void neighbors_in(std::span<const typename Mesh<D>::Element> elements, Index center, std::vector<Index>& out, std::vector<Index>* places) {
  out.clear();
  if (places) places->clear();
  for (const auto& element : elements) {
    if (std::find(element.begin(), element.end(), center) == element.end()) continue;
    for (Index w : element) {
      if (w == center) continue;
      const std::size_t place = small_set_place(out, w);
      if (places) places->push_back(static_cast<Index>(place));
      if (place == out.size()) out.push_back(w);
    }
  }
}

template <int D>
std::pair<double, double> length_range_from(const AdaptationMesh<D>& am, const Vec<D>& x, const SymMat<D>& metric_x,
                                            std::span<const Index> neighbors) {
  std::pair<double, double> range{std::numeric_limits<double>::infinity(), 0.0};
  for (Index w : neighbors) {
    const double length = metric_edge_length<D>(x, am.mesh().vertex(w), metric_x, am.metric(w));
    range = {std::min(range.first, length), std::max(range.second, length)};
  }
  return range;
}

bool lengths_stay_in_window(std::pair<double, double> before, std::pair<double, double> after, const AdaptationLimits& limits) {
  return after.first >= std::min(limits.collapse_length, before.first) && after.second <= std::max(limits.split_length, before.second);
}

template void neighbors_in<2>(std::span<const Mesh<2>::Element>, Index, std::vector<Index>&, std::vector<Index>*);
template void neighbors_in<3>(std::span<const Mesh<3>::Element>, Index, std::vector<Index>&, std::vector<Index>*);
template std::pair<double, double> length_range_from(const AdaptationMesh<2>&, const Vec<2>&, const SymMat<2>&, std::span<const Index>);
template std::pair<double, double> length_range_from(const AdaptationMesh<3>&, const Vec<3>&, const SymMat<3>&, std::span<const Index>);
template double worst_quality(const AdaptationMesh<2>&, std::span<const Index>);
template double worst_quality(const AdaptationMesh<3>&, std::span<const Index>);
template double worst_planned_quality(const AdaptationMesh<2>&, const CavityOperator<2>&);
template double worst_planned_quality(const AdaptationMesh<3>&, const CavityOperator<3>&);
template bool edges_from_within(const AdaptationMesh<2>&, Index, std::span<const Mesh<2>::Element>, double);
template bool edges_from_within(const AdaptationMesh<3>&, Index, std::span<const Mesh<3>::Element>, double);

}  // namespace hocav
