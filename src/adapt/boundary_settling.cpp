#include "adapt/boundary_settling.hpp"

#include <algorithm>
#include <chrono>
#include <optional>

#include "adapt/adaptation_loop.hpp"
#include "adapt/boundary_pieces.hpp"
#include "adapt/metric_measures.hpp"
#include "adapt/vertex_classes.hpp"
#include "mesh/ball_and_shell.hpp"
#include "mesh/harmonic_extension.hpp"
#include "mesh/measure.hpp"

namespace hocav {
namespace {

// Vertices closer than this share of the bounding box's diagonal to their geometric point stay.
constexpr double kOnGeometry = 1e-9;
// The volume moves within this many times a boundary vertex's move (harmonic_extension).
constexpr double kReachFactor = 20;
// An element keeps at least this share of its quality (and stays above kPoorQuality if it was).
constexpr double kKeptQualityShare = 0.7;
// A vertex whose move is halved this many times and still fails stops moving.
constexpr int kSettlingHalvings = 6;

// The distinct refs of the boundary facets around v.
template <int D>
std::vector<int> facet_refs_around(const Mesh<D>& mesh, Index v, std::vector<Index>& ball, std::vector<Index>& facets) {
  collect_ball(mesh, v, ball);
  const Index center[1] = {v};
  facets_through<D>(mesh, ball, center, facets);
  std::vector<int> refs;
  for (Index f : facets) refs.push_back(mesh.facet_ref(f));
  std::sort(refs.begin(), refs.end());
  refs.erase(std::unique(refs.begin(), refs.end()), refs.end());
  return refs;
}

// Where boundary vertex v belongs on the geometry: on its surface (3D) or curve (2D), a ridge vertex on
// its feature curve; none for corners and for vertices whose facets name more surfaces than that.
template <int D>
std::optional<Vec<D>> geometric_point(const Mesh<D>& mesh, Index v, VertexClass vertex_class, const BoundaryGeometry<D>& geometry,
                                      std::vector<Index>& ball, std::vector<Index>& facets) {
  if (vertex_class != VertexClass::kSurface && vertex_class != VertexClass::kRidge) return std::nullopt;
  const std::vector<int> refs = facet_refs_around(mesh, v, ball, facets);
  if (refs.empty()) return std::nullopt;  // a feature line inside the volume
  if (vertex_class == VertexClass::kSurface) return geometry.project(mesh.vertex(v), {refs.front()}).point;
  if (refs.size() > 2) return std::nullopt;
  return geometry.project_on_ridge(mesh.vertex(v), refs.front(), refs.back());
}

// The moves that put the boundary vertices on the geometry (zero for those on it, and for those
// `candidates` leaves out when it is not empty), every boundary vertex flagged fixed; counts those off it.
template <int D>
std::vector<Vec<D>> boundary_moves(Mesh<D>& mesh, const BoundaryGeometry<D>& geometry, std::span<const VertexClass> classes,
                                   std::span<const char> candidates, std::vector<char>& fixed, BoundarySettling& out) {
  const double tolerance = kOnGeometry * bounding_box_diagonal(mesh);
  std::vector<Vec<D>> moves(static_cast<std::size_t>(mesh.vertex_count()), Vec<D>{});
  fixed.assign(moves.size(), 0);
  std::vector<Index> ball, facets;
  for (Index v = 0; v < mesh.vertex_count(); ++v) {
    if (classes[v] == VertexClass::kInterior) continue;
    fixed[v] = 1;
    if (!candidates.empty() && !candidates[v]) continue;
    const std::optional<Vec<D>> point = geometric_point(mesh, v, classes[v], geometry, ball, facets);
    if (!point || !(norm(*point - mesh.vertex(v)) > tolerance)) continue;
    moves[v] = *point - mesh.vertex(v);
    ++out.off_geometry;
    out.largest_distance = std::max(out.largest_distance, norm(moves[v]));
  }
  return moves;
}

// The moves scaled back, per vertex, until every element that holds a moving vertex keeps its floor:
// the loop's quality with each vertex's own metric (the metric moves with the mesh, so a layer
// translated with its wall keeps its qualities).
template <int D>
class ScaledMoves {
 public:
  ScaledMoves(const Mesh<D>& mesh, std::span<const SymMat<D>> metrics, std::vector<Vec<D>> moves)
      : mesh_(mesh),
        metrics_(metrics),
        moves_(std::move(moves)),
        scale_(moves_.size(), 0),
        halvings_(moves_.size(), 0),
        halved_in_round_(moves_.size(), -1) {
    const auto moving = [&](Index v) { return norm(moves_[v]) > 0; };
    for (Index k = 0; k < mesh.element_count(); ++k)  // (every scale 0 yet: the qualities before)
      if (std::any_of(mesh.element(k).begin(), mesh.element(k).end(), moving)) {
        affected_.push_back(k);
        const double before = quality(k);
        floors_.push_back(std::max(kKeptQualityShare * before, std::min(before, kPoorQuality)));
      }
    for (Index v = 0; v < mesh.vertex_count(); ++v) scale_[v] = moving(v) ? 1 : 0;
  }

  // Halves the moves of the vertices of every element below its floor; false when none had a move
  // left to halve (an element whose vertices are all back has its quality before: it passes).
  bool scale_back_failing(int round) {
    bool halved = false;
    for (std::size_t i = 0; i < affected_.size(); ++i) {
      if (quality(affected_[i]) >= floors_[i]) continue;
      for (Index v : mesh_.element(affected_[i]))
        if (scale_[v] > 0 && halved_in_round_[v] != round) {
          halved_in_round_[v] = round;
          scale_[v] = ++halvings_[v] > kSettlingHalvings ? 0 : 0.5 * scale_[v];
          halved = true;
        }
    }
    return halved;
  }

  double scale(Index v) const { return scale_[v]; }
  const Vec<D>& move(Index v) const { return moves_[v]; }
  Vec<D> point(Index v) const { return mesh_.vertex(v) + scale_[v] * moves_[v]; }

 private:
  double quality(Index k) const {
    SimplexPoints<D> points;
    std::array<SymMat<D>, D + 1> metrics;
    for (int i = 0; i <= D; ++i) {
      points[i] = point(mesh_.element(k)[i]);
      metrics[i] = metrics_[mesh_.element(k)[i]];
    }
    return mean_metric_ratio<D>(points, metrics);
  }

  const Mesh<D>& mesh_;
  std::span<const SymMat<D>> metrics_;
  std::vector<Vec<D>> moves_;
  std::vector<double> scale_;
  std::vector<int> halvings_, halved_in_round_;
  std::vector<Index> affected_;
  std::vector<double> floors_;
};

template <int D>
void count_moves(const ScaledMoves<D>& moves, const std::vector<char>& fixed, BoundarySettling& out) {
  for (Index v = 0; v < static_cast<Index>(fixed.size()); ++v) {
    if (norm(moves.move(v)) == 0) continue;
    if (!fixed[v]) {
      out.inner_vertices_moved += moves.scale(v) > 0;
      continue;
    }
    out.settled += moves.scale(v) == 1;
    out.partly += moves.scale(v) > 0 && moves.scale(v) < 1;
    out.blocked += moves.scale(v) == 0;
    out.largest_distance_left = std::max(out.largest_distance_left, (1 - moves.scale(v)) * norm(moves.move(v)));
  }
}

// settle_boundary with the vertices' classes given, moving only the boundary vertices flagged in
// `candidates` (all when it is empty); the vertices it moved, boundary and inner, go to `moved`.
template <int D>
BoundarySettling settle_classified_boundary(Mesh<D>& mesh, std::span<const SymMat<D>> metrics, const BoundaryGeometry<D>& geometry,
                                            std::span<const VertexClass> classes, std::span<const char> candidates,
                                            std::vector<Index>& moved) {
  const auto start = std::chrono::steady_clock::now();
  BoundarySettling out;
  std::vector<char> fixed;
  const std::vector<Vec<D>> on_boundary = boundary_moves(mesh, geometry, classes, candidates, fixed, out);
  if (out.off_geometry > 0) {
    const HarmonicExtension<D> extension = harmonic_extension<D>(mesh, fixed, on_boundary, kReachFactor);
    out.solver_iterations = extension.iterations;
    ScaledMoves<D> moves(mesh, metrics, extension.moves);
    while (moves.scale_back_failing(out.rounds)) ++out.rounds;
    count_moves(moves, fixed, out);
    for (Index v = 0; v < mesh.vertex_count(); ++v)
      if (moves.scale(v) > 0 && norm(moves.move(v)) > 0) {
        mesh.vertex(v) = moves.point(v);
        moved.push_back(v);
      }
  }
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

}  // namespace

template <int D>
BoundarySettling settle_boundary(Mesh<D>& mesh, std::span<const SymMat<D>> metrics, const BoundaryGeometry<D>& geometry,
                                 double feature_angle_degrees) {
  const std::vector<VertexClass> classes = classify_vertices(mesh, feature_angle_degrees);
  std::vector<Index> moved;
  return settle_classified_boundary<D>(mesh, metrics, geometry, classes, {}, moved);
}

template <int D>
BoundarySettling settle_boundary_between_passes(AdaptationMesh<D>& am) {
  Mesh<D>& mesh = am.mesh();
  const auto count = static_cast<std::size_t>(mesh.vertex_count());
  std::vector<SymMat<D>> metrics(count);
  std::vector<VertexClass> classes(count);
  std::vector<char> changed(count);
  for (Index v = 0; v < mesh.vertex_count(); ++v) {
    metrics[v] = am.metric(v);
    classes[v] = am.vertex_class(v);
    changed[v] = am.changed_recently(v);
  }
  std::vector<Index> moved;
  const BoundarySettling out = settle_classified_boundary<D>(mesh, metrics, *am.geometry(), classes, changed, moved);
  am.vertices_moved(moved);
  return out;
}

template BoundarySettling settle_boundary(Mesh<2>&, std::span<const SymMat<2>>, const BoundaryGeometry<2>&, double);
template BoundarySettling settle_boundary(Mesh<3>&, std::span<const SymMat<3>>, const BoundaryGeometry<3>&, double);
template BoundarySettling settle_boundary_between_passes(AdaptationMesh<2>&);
template BoundarySettling settle_boundary_between_passes(AdaptationMesh<3>&);

}  // namespace hocav
