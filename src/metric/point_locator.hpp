// Localization of points in the back mesh (docs/method.md §2, step 1): the back element containing a
// point and the point's barycentric coordinates there.
//
// A walk from a hint element moves across the face with the most negative barycentric coordinate
// until all are non-negative. Cold starts (no hint) begin at an element from a uniform grid over
// the bounding box. Points outside the back mesh (curved boundary nodes lie up to ~h²/8 outside a
// convex P1 boundary) get the documented closest-element rule: the boundary element, among those
// around the boundary face where the walk left the mesh, whose boundary face is closest to the
// point (the last-resort exhaustive search takes the closest over all boundary faces); its barycentrics are returned unclamped, so the
// log-metric is extended affinely (and stays differentiable) just outside the mesh.
#pragma once

#include <array>
#include <cstdint>
#include <limits>
#include <span>
#include <vector>

#include "geom/barycentric.hpp"
#include "mesh/mesh.hpp"

namespace hocav {

template <int D>
struct Localization {
  Index element = kNoIndex;
  Barycentrics<D> barycentrics{};  // of the point in `element`; some negative when !inside
  bool inside = true;
};

// What a localization may reuse from the previous ones of the same caller: the boundary elements near the
// face where the last walk left the mesh (an optimizer's trial points near a boundary leave it through the
// same face again and again) and a buffer for the balls that list them. One per thread, owned by the
// caller: the locator itself never changes, so threads share it.
struct LocatorScratch {
  std::uint64_t locator_id = 0;  // the locator the candidates are from (0: none yet)
  Index element = kNoIndex;      // and the boundary face they are around
  int face = -1;
  std::vector<Index> candidates;
};

template <int D>
class PointLocator {
 public:
  // The mesh must be P1-valid (positive elements), have its topology, and outlive the locator unchanged.
  explicit PointLocator(const Mesh<D>& mesh);

  // Thread-safe: reads only the locator. `hint` is an element near x (e.g. where a nearby point was found).
  Localization<D> localize(const Vec<D>& x, Index hint, LocatorScratch& scratch) const;
  // The same, nothing reused.
  Localization<D> localize(const Vec<D>& x, Index hint = kNoIndex) const {
    LocatorScratch scratch;
    return localize(x, hint, scratch);
  }

  // Whether barycentrics put their point in the element, as the walk decides it (faces included).
  static bool contains(const Barycentrics<D>& lambda);

  // The closest-element rule for a point x that left the mesh through boundary face `near_face` of
  // `near_element`: among the elements around the vertices of that face (the balls of its vertices, in
  // order), the one whose boundary face is closest to x; of equals, the first met.
  Localization<D> closest_boundary_element(const Vec<D>& x, Index near_element, int near_face, LocatorScratch& scratch) const;

  const Mesh<D>& mesh() const { return mesh_; }
  SimplexPoints<D> element_points(Index k) const;

 private:
  Index grid_element(const Vec<D>& x) const;
  // Walks from `start`; returns the element reached and, when the walk left the mesh, the
  // boundary face it left through (else -1).
  Index walk(const Vec<D>& x, Index start, Barycentrics<D>& lambda, int& exit_face) const;
  bool is_boundary_element(Index k) const;
  // The boundary elements of each boundary vertex's ball, in collect_ball's order (the closest-element
  // rule's candidates, listed once: the rule runs for every point just outside the mesh).
  void index_boundary_balls();
  std::span<const Index> boundary_ball(Index v) const;
  // The element whose boundary face is closest to x, among `candidates` (the first of equals), given a bound
  // of the winner's squared distance (e.g. that of one of their faces).
  Localization<D> closest_among(const Vec<D>& x, const std::vector<Index>& candidates,
                                double upper_bound2 = std::numeric_limits<double>::infinity()) const;
  std::array<Vec<D>, D> face_corners(Index k, int face) const;
  // Every element, then every boundary face: the last resort when a walk cycles.
  Localization<D> exhaustive_search(const Vec<D>& x) const;

  const Mesh<D>& mesh_;
  std::uint64_t id_;  // keys the candidates a LocatorScratch holds
  Vec<D> grid_origin_{};
  double grid_cell_size_ = 1;
  double coordinate_scale_ = 0;  // the largest coordinate magnitude of the mesh
  std::array<int, D> grid_cells_{};
  std::vector<Index> grid_elements_;
  std::vector<Index> boundary_ball_start_, boundary_ball_elements_;  // ball v: [start[v], start[v + 1])
};

extern template class PointLocator<2>;
extern template class PointLocator<3>;

}  // namespace hocav
