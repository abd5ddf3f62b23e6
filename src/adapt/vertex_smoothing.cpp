// Vertex smoothing (docs/adaptation.md §Smoothing): an interior vertex moves toward the mean of the
// points that would make each of its edges unit (w + (v − w)/l(v, w) for each neighbour w), by the
// whole step or a half or a quarter of it, when that raises the worst quality of its ball. The ball
// keeps its topology, so the move is checked by the quality itself: it is positive only for
// elements of positive measure.
#include <algorithm>

#include "adapt/adaptation_operations.hpp"
#include "mesh/ball_and_shell.hpp"

namespace hocav {
namespace {

// A move must raise the ball's worst quality by this factor (mmg asks 1.02): no move undoes another.
constexpr double kSmoothingGain = 1.01;

template <int D>
Vec<D> unit_edge_target(const AdaptationMesh<D>& am, Index v, std::span<const Index> ball) {
  const Mesh<D>& mesh = am.mesh();
  Vec<D> sum{};
  int count = 0;
  for (Index k : ball)
    for (Index w : mesh.element(k))
      if (w != v) {
        const double length = am.edge_length(v, w);
        if (!(length > 0)) continue;
        sum = sum + (mesh.vertex(w) + (1 / length) * (mesh.vertex(v) - mesh.vertex(w)));
        ++count;
      }
  return count ? (1.0 / count) * sum : mesh.vertex(v);
}

template <int D>
struct SmoothingScratch {
  std::vector<Index> ball;
  std::vector<typename Mesh<D>::Element> elements;
};

template <int D>
bool smooth_vertex(AdaptationMesh<D>& am, Index v, SmoothingScratch<D>& scratch, const AdaptationLimits& limits) {
  std::vector<Index>& ball = scratch.ball;
  collect_ball(am.mesh(), v, ball);
  if (ball.empty()) return false;
  scratch.elements.clear();
  for (Index k : ball) scratch.elements.push_back(am.mesh().element(k));
  const auto old_lengths = length_range_from<D>(am, v, scratch.elements);
  const Vec<D> start = am.mesh().vertex(v);
  const SymMat<D> start_metric = am.metric(v);
  const double old_worst = worst_quality<D>(am, ball);
  const Vec<D> step = unit_edge_target(am, v, ball) - start;
  for (double fraction : {1.0, 0.5, 0.25}) {
    am.move_vertex(v, start + fraction * step);
    if (worst_quality<D>(am, ball) > kSmoothingGain * old_worst &&
        lengths_stay_in_window<D>(am, v, old_lengths, scratch.elements, limits)) {
      for (const auto& element : scratch.elements)
        for (Index w : element) am.mark_changed(w);
      return true;
    }
  }
  am.restore_vertex(v, start, start_metric);
  return false;
}

}  // namespace

template <int D>
OperationCount smooth_vertices(AdaptationMesh<D>& am, const AdaptationLimits& limits) {
  OperationCount count;
  SmoothingScratch<D> scratch;
  for (Index v = 0; v < am.mesh().vertex_count(); ++v) {
    if (am.mesh().vertex_removed(v) || am.vertex_class(v) != VertexClass::kInterior || !am.changed_recently(v)) continue;
    count.add(smooth_vertex(am, v, scratch, limits) ? Refusal::kNone : Refusal::kQuality);
  }
  return count;
}

template OperationCount smooth_vertices(AdaptationMesh<2>&, const AdaptationLimits&);
template OperationCount smooth_vertices(AdaptationMesh<3>&, const AdaptationLimits&);

}  // namespace hocav
