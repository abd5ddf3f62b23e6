// The last step of the P1 adaptation (docs/adaptation.md §Boundary settling): the boundary vertices
// the loop left off the geometry (a boundary split whose point on the geometry was refused puts its
// vertex at the straight middle of the edge) moved onto it, the volume moved along by the harmonic
// extension of their moves. The metric moves with the mesh: each vertex keeps the metric it had.
// No element keeps less than 70% of its quality, nor falls below kPoorQuality unless it was; a vertex
// of an element that would has its move halved, and after a few halvings dropped.
#pragma once

#include <span>

#include "adapt/adaptation_mesh.hpp"
#include "geom/sym_mat.hpp"
#include "mesh/mesh.hpp"
#include "surface/boundary_geometry.hpp"

namespace hocav {

struct BoundarySettling {
  Index off_geometry = 0;            // boundary vertices farther than the tolerance from their point on the geometry
  double largest_distance = 0;       // the largest of those distances
  Index settled = 0;                 // of those, moved onto the geometry
  Index partly = 0;                  // moved part of the way
  Index blocked = 0;                 // not moved
  double largest_distance_left = 0;  // the largest distance of a boundary vertex from its point after
  Index inner_vertices_moved = 0;    // inner vertices moved along
  int solver_iterations = 0;         // of the harmonic extension (conjugate gradients, summed over the coordinates)
  int rounds = 0;                    // of halvings
  double seconds = 0;
};

// On `mesh` (P1, with its topology), classified with the feature angle as the loop does (its ridges
// are tagged already), `metrics` at its vertices; qualities as the loop's (metric_measures.hpp).
// Serial: the same result for any thread count.
template <int D>
BoundarySettling settle_boundary(Mesh<D>& mesh, std::span<const SymMat<D>> metrics, const BoundaryGeometry<D>& geometry,
                                 double feature_angle_degrees);

// The same at the start of a pass of the loop (after am.start_pass()), on its mesh (which has a
// geometry), with its classes and vertex metrics, for the boundary vertices changed since the
// previous pass began (the others were settled, or refused, as they are): each vertex it moves then
// takes the metric at its new point and the qualities of its elements follow, so that the pass's
// collapses, swaps and moves mend what the moves left poor, and the next settling goes further
// (docs/adaptation.md §Boundary settling).
template <int D>
BoundarySettling settle_boundary_between_passes(AdaptationMesh<D>& am);

}  // namespace hocav
