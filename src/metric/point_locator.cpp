#include "metric/point_locator.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <deque>
#include <limits>

#include "geom/closest_point.hpp"
#include "mesh/ball_and_shell.hpp"

namespace hocav {
namespace {

// Barycentrics this far below zero still count as inside: points on faces must not bounce.
constexpr double kInsideTolerance = 1e-12;
// A walk longer than this is taken as cycling (possible on non-Delaunay meshes).
constexpr int kMaxWalkSteps = 20000;

template <int D>
int most_negative(const Barycentrics<D>& lambda) {
  return static_cast<int>(std::min_element(lambda.begin(), lambda.end()) - lambda.begin());
}

// The squared distance from x to the point of a boundary face closest to it, as the closest-element rule
// ranks faces (the same arithmetic for every caller: ties are decided on these exact values).
template <int D>
double squared_distance_to_face(const std::array<Vec<D>, D>& corners, const Vec<D>& x) {
  Vec<D> closest{};
  if constexpr (D == 2) {
    auto w = closest_on_segment<2>(corners[0], corners[1], x);
    closest = w[0] * corners[0] + w[1] * corners[1];
  } else {
    auto w = closest_on_triangle(corners[0], corners[1], corners[2], x);
    closest = w[0] * corners[0] + w[1] * corners[1] + w[2] * corners[2];
  }
  return dot(closest - x, closest - x);
}

// The squared distance from x to the bounding box of the corners: a lower bound of the distance to the face.
template <int D>
double squared_distance_to_box(const std::array<Vec<D>, D>& corners, const Vec<D>& x) {
  double distance2 = 0;
  for (int i = 0; i < D; ++i) {
    double low = corners[0][i], high = corners[0][i];
    for (int j = 1; j < D; ++j) {
      low = std::min(low, corners[j][i]);
      high = std::max(high, corners[j][i]);
    }
    double gap = std::max({low - x[i], x[i] - high, 0.0});
    distance2 += gap * gap;
  }
  return distance2;
}

// Ids of locators, unique over the process's life (unlike addresses).
std::atomic<std::uint64_t> last_locator_id{0};

}  // namespace

template <int D>
PointLocator<D>::PointLocator(const Mesh<D>& mesh) : mesh_(mesh), id_(++last_locator_id) {
  if (mesh.element_count() == 0) return;
  Vec<D> low = mesh.vertex(0), high = mesh.vertex(0);
  for (const auto& p : mesh.vertices())
    for (int i = 0; i < D; ++i) {
      low[i] = std::min(low[i], p[i]);
      high[i] = std::max(high[i], p[i]);
    }
  // About two elements per cell: a cold start walks a few steps at most.
  double box = 1;
  for (int i = 0; i < D; ++i) box *= std::max(high[i] - low[i], 1e-300);
  double target_cells = std::max(1.0, mesh.element_count() / 2.0);
  grid_cell_size_ = std::pow(box / target_cells, 1.0 / D);
  std::size_t cells = 1;
  for (int i = 0; i < D; ++i) {
    grid_cells_[i] = std::clamp(static_cast<int>(std::ceil((high[i] - low[i]) / grid_cell_size_)), 1, 1 << 20);
    cells *= static_cast<std::size_t>(grid_cells_[i]);
  }
  grid_origin_ = low;
  for (int i = 0; i < D; ++i) coordinate_scale_ = std::max({coordinate_scale_, std::abs(low[i]), std::abs(high[i])});
  grid_elements_.assign(cells, kNoIndex);

  auto cell_of = [&](const Vec<D>& x) {
    std::size_t cell = 0;
    for (int i = D - 1; i >= 0; --i) {
      int c = std::clamp(static_cast<int>((x[i] - grid_origin_[i]) / grid_cell_size_), 0, grid_cells_[i] - 1);
      cell = cell * static_cast<std::size_t>(grid_cells_[i]) + static_cast<std::size_t>(c);
    }
    return cell;
  };
  std::deque<std::size_t> filled;
  for (Index k = 0; k < mesh.element_count(); ++k) {
    Vec<D> centroid{};
    for (Index v : mesh.element(k)) centroid += mesh.vertex(v) * (1.0 / (D + 1));
    std::size_t cell = cell_of(centroid);
    if (grid_elements_[cell] == kNoIndex) filled.push_back(cell);
    grid_elements_[cell] = k;
  }
  // Empty cells borrow an element from the nearest filled cell (breadth-first over the grid).
  while (!filled.empty()) {
    std::size_t cell = filled.front();
    filled.pop_front();
    std::size_t stride = 1;
    for (int i = 0; i < D; ++i) {
      auto n = static_cast<std::size_t>(grid_cells_[i]);
      std::size_t coordinate = (cell / stride) % n;
      if (coordinate > 0 && grid_elements_[cell - stride] == kNoIndex) {
        grid_elements_[cell - stride] = grid_elements_[cell];
        filled.push_back(cell - stride);
      }
      if (coordinate + 1 < n && grid_elements_[cell + stride] == kNoIndex) {
        grid_elements_[cell + stride] = grid_elements_[cell];
        filled.push_back(cell + stride);
      }
      stride *= n;
    }
  }
  index_boundary_balls();
}

template <int D>
bool PointLocator<D>::contains(const Barycentrics<D>& lambda) {
  return lambda[most_negative<D>(lambda)] >= -kInsideTolerance;
}

template <int D>
SimplexPoints<D> PointLocator<D>::element_points(Index k) const {
  SimplexPoints<D> points;
  for (int i = 0; i <= D; ++i) points[i] = mesh_.vertex(mesh_.element(k)[i]);
  return points;
}

template <int D>
Index PointLocator<D>::grid_element(const Vec<D>& x) const {
  std::size_t cell = 0;
  for (int i = D - 1; i >= 0; --i) {
    double position = (x[i] - grid_origin_[i]) / grid_cell_size_;
    int c = std::isfinite(position) ? static_cast<int>(std::clamp(position, 0.0, grid_cells_[i] - 1.0)) : 0;
    cell = cell * static_cast<std::size_t>(grid_cells_[i]) + static_cast<std::size_t>(c);
  }
  return grid_elements_[cell];
}

template <int D>
Index PointLocator<D>::walk(const Vec<D>& x, Index start, Barycentrics<D>& lambda, int& exit_face) const {
  Index k = start, previous = kNoIndex;
  for (int step = 0; step < kMaxWalkSteps; ++step) {
    lambda = barycentric_coordinates<D>(element_points(k), x);
    if (contains(lambda)) {
      exit_face = -1;
      return k;
    }
    int face = most_negative<D>(lambda);
    Index next = mesh_.neighbor(k, face);
    if (next == previous) {
      // Going straight back would cycle: take the next most negative face instead.
      Barycentrics<D> others = lambda;
      others[face] = std::numeric_limits<double>::infinity();
      int second = most_negative<D>(others);
      if (others[second] < -kInsideTolerance) {
        face = second;
        next = mesh_.neighbor(k, face);
      }
    }
    if (next == kNoIndex) {
      exit_face = face;
      return k;
    }
    previous = k;
    k = next;
  }
  return kNoIndex;
}

template <int D>
Localization<D> PointLocator<D>::localize(const Vec<D>& x, Index hint, LocatorScratch& scratch) const {
  Barycentrics<D> lambda;
  int exit_face = -1;
  Index grid_start = grid_element(x);
  Index k = walk(x, hint != kNoIndex ? hint : grid_start, lambda, exit_face);
  if (k != kNoIndex && exit_face >= 0 && hint != kNoIndex && hint != grid_start) {
    // A walk from afar may hit a concave boundary: retry from an element near x.
    k = walk(x, grid_start, lambda, exit_face);
  }
  if (k == kNoIndex) return exhaustive_search(x);
  if (exit_face < 0) return {k, lambda, true};
  return closest_boundary_element(x, k, exit_face, scratch);
}

template <int D>
void PointLocator<D>::index_boundary_balls() {
  std::vector<char> on_boundary(static_cast<std::size_t>(mesh_.vertex_count()), 0);
  for (Index k = 0; k < mesh_.element_count(); ++k)
    for (int face = 0; face <= D; ++face)
      if (mesh_.neighbor(k, face) == kNoIndex)
        for (int i = 0; i < D; ++i) on_boundary[mesh_.element(k)[face_vertices<D>(face)[i]]] = 1;
  std::vector<Index> ball;
  boundary_ball_start_.assign(1, 0);
  for (Index v = 0; v < mesh_.vertex_count(); ++v) {
    if (on_boundary[v]) {
      collect_ball(mesh_, v, ball);
      for (Index k : ball)
        if (is_boundary_element(k)) boundary_ball_elements_.push_back(k);
    }
    boundary_ball_start_.push_back(static_cast<Index>(boundary_ball_elements_.size()));
  }
}

template <int D>
std::span<const Index> PointLocator<D>::boundary_ball(Index v) const {
  const auto begin = static_cast<std::size_t>(boundary_ball_start_[v]);
  return std::span<const Index>(boundary_ball_elements_).subspan(begin, static_cast<std::size_t>(boundary_ball_start_[v + 1]) - begin);
}

template <int D>
bool PointLocator<D>::is_boundary_element(Index k) const {
  for (int face = 0; face <= D; ++face)
    if (mesh_.neighbor(k, face) == kNoIndex) return true;
  return false;
}

template <int D>
Localization<D> PointLocator<D>::closest_boundary_element(const Vec<D>& x, Index near_element, int near_face,
                                                          LocatorScratch& scratch) const {
  // Kept in the scratch for the next call (and reused: no allocation per call).
  if (scratch.locator_id != id_ || scratch.element != near_element || scratch.face != near_face) {
    scratch.locator_id = id_;
    scratch.element = near_element;
    scratch.face = near_face;
    scratch.candidates.clear();
    // An element met again in a later ball cannot win (closest_among keeps the first of equals):
    // each boundary element once, at its first place in the balls' order.
    for (int i = 0; i < D; ++i)
      for (Index k : boundary_ball(mesh_.element(near_element)[face_vertices<D>(near_face)[i]]))
        if (std::find(scratch.candidates.begin(), scratch.candidates.end(), k) == scratch.candidates.end()) scratch.candidates.push_back(k);
  }
  // The exit face bounds the winner's distance from the start, so farther faces are skipped early; unless
  // its element is not a candidate (a vertex pinching two parts of the mesh: its ball lists one part).
  const auto& elements = scratch.candidates;
  if (std::find(elements.begin(), elements.end(), near_element) == elements.end()) return closest_among(x, elements);
  return closest_among(x, elements, squared_distance_to_face<D>(face_corners(near_element, near_face), x));
}

template <int D>
std::array<Vec<D>, D> PointLocator<D>::face_corners(Index k, int face) const {
  std::array<Vec<D>, D> corners;
  for (int i = 0; i < D; ++i) corners[i] = mesh_.vertex(mesh_.element(k)[face_vertices<D>(face)[i]]);
  return corners;
}

template <int D>
Localization<D> PointLocator<D>::closest_among(const Vec<D>& x, const std::vector<Index>& candidates, double upper_bound2) const {
  // A face whose bounding box is farther from x than the bound by more than the rounding of
  // squared_distance_to_face (its closest point is a convex combination of the corners, so lies in the
  // box up to a few ulps of the coordinates) has a distance above the bound: it can neither win nor tie.
  double scale = coordinate_scale_;
  for (int i = 0; i < D; ++i) scale = std::max(scale, std::abs(x[i]));
  const double rounding = 1e-12 * (1 + scale);
  auto farther_limit2 = [&](double bound2) {
    double limit = std::sqrt(bound2) + rounding;
    return limit * limit;
  };
  Index best = kNoIndex;
  double best_distance2 = std::numeric_limits<double>::infinity();
  double skip_beyond2 = farther_limit2(upper_bound2);
  for (Index k : candidates)
    for (int face = 0; face <= D; ++face) {
      if (mesh_.neighbor(k, face) != kNoIndex) continue;
      const std::array<Vec<D>, D> corners = face_corners(k, face);
      if (squared_distance_to_box<D>(corners, x) > skip_beyond2) continue;
      double distance2 = squared_distance_to_face<D>(corners, x);
      // Strictly closer only: the first of equals keeps the win (part of the documented rule).
      if (distance2 < best_distance2) {
        best_distance2 = distance2;
        best = k;
        skip_beyond2 = farther_limit2(std::min(best_distance2, upper_bound2));
      }
    }
  if (best == kNoIndex) return {};
  return {best, barycentric_coordinates<D>(element_points(best), x), false};
}

template <int D>
Localization<D> PointLocator<D>::exhaustive_search(const Vec<D>& x) const {
  std::vector<Index> boundary_elements;
  for (Index k = 0; k < mesh_.element_count(); ++k) {
    auto lambda = barycentric_coordinates<D>(element_points(k), x);
    if (lambda[most_negative<D>(lambda)] >= -kInsideTolerance) return {k, lambda, true};
    if (is_boundary_element(k)) boundary_elements.push_back(k);
  }
  return closest_among(x, boundary_elements);
}

template class PointLocator<2>;
template class PointLocator<3>;

}  // namespace hocav
