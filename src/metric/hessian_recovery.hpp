// Recovery of the Hessian of a scalar field known at the vertices (docs/method.md §10, the input of the
// Hessian-based Lp metric). Method: a least-squares quadratic fit on the vertex's neighbourhood.
// At vertex v with value u_v, find the gradient g and the symmetric H minimizing
//   Σ_j ( u_v + g·d_j + ½ d_jᵀ H d_j − u_j )²,   d_j = x_j − x_v,
// over the vertices j joined to v by an edge (its 1-ring). When those are too few or lie too
// flat to determine the D + D(D+1)/2 unknowns (corners, some boundary vertices), the 2-ring, then
// the 3-ring, is used. The fit reproduces every quadratic field exactly (to round-off), at interior
// and boundary vertices alike. It is solved by Householder QR on the scaled, column-equilibrated
// system, so stretched neighbourhoods stay well conditioned.
#pragma once

#include <optional>
#include <span>
#include <vector>

#include "geom/sym_mat.hpp"
#include "mesh/mesh.hpp"

namespace hocav {

// The rings a vertex's stencil may grow to.
constexpr int kHessianMaxRings = 3;

// The fit at a point of `value` on its stencil, the points and values of its neighbours in the
// order the rings list them (the least squares above); nothing when they are too few or lie too flat
// to determine a quadratic.
template <int D>
std::optional<SymMat<D>> fit_hessian(const Vec<D>& point, double value, std::span<const Vec<D>> stencil_points,
                                     std::span<const double> stencil_values);

// One Hessian per vertex from one value per vertex. Throws Error naming the vertex whose 3-ring
// cannot determine a quadratic (e.g. a mesh of one element), or for a wrong number of values.
template <int D>
std::vector<SymMat<D>> recover_hessians(const Mesh<D>& mesh, std::span<const double> vertex_values);

}  // namespace hocav
