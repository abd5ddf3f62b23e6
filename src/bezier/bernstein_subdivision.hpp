// Regular subdivision of a polynomial in Bernstein form over a simplex (docs/method.md §8: de Casteljau,
// 4 sub-triangles, 8 sub-tetrahedra), used to tighten the bounds that coefficients give on J.
//
// Children are the regular ("red") refinement: the D + 1 corner children, then the inner
// triangle (2D) or the four tetrahedra of the inner octahedron cut along the diagonal m02–m13 with
// Bey's vertex order (3D), so that repeated refinement keeps at most three shapes and every level
// halves the diameter. The coefficients of a child are the blossom of the polynomial at the
// child's vertices (b'_β = blossom(Q_0^β0, …, Q_D^βD)); since the children's vertices are corners
// and edge midpoints this is a fixed linear map per child with non-negative weights summing to one,
// tabulated at compile time.
#pragma once

#include <array>

#include "bezier/jacobian_coefficients.hpp"

namespace hocav {

template <int D>
inline constexpr int kSubdivisionChildCount = 1 << D;

// A child vertex as a pair of parent vertices: their midpoint, or the vertex itself when equal.
using ParentVertexPair = std::array<int, 2>;

template <int D>
using SubdivisionChildVertices = std::array<std::array<ParentVertexPair, D + 1>, kSubdivisionChildCount<D>>;

template <int D>
inline constexpr SubdivisionChildVertices<D> kSubdivisionChildVertices = [] {
  if constexpr (D == 2)
    return SubdivisionChildVertices<2>{
        {{{{0, 0}, {0, 1}, {0, 2}}}, {{{0, 1}, {1, 1}, {1, 2}}}, {{{0, 2}, {1, 2}, {2, 2}}}, {{{1, 2}, {0, 2}, {0, 1}}}}};
  else
    return SubdivisionChildVertices<3>{{{{{0, 0}, {0, 1}, {0, 2}, {0, 3}}},
                                        {{{0, 1}, {1, 1}, {1, 2}, {1, 3}}},
                                        {{{0, 2}, {1, 2}, {2, 2}, {2, 3}}},
                                        {{{0, 3}, {1, 3}, {2, 3}, {3, 3}}},
                                        {{{0, 1}, {0, 2}, {0, 3}, {1, 3}}},
                                        {{{0, 1}, {0, 2}, {1, 2}, {1, 3}}},
                                        {{{0, 2}, {0, 3}, {1, 3}, {2, 3}}},
                                        {{{0, 2}, {1, 2}, {1, 3}, {2, 3}}}}};
}();

// Barycentric coordinates (in the parent) of vertex `vertex` of child `child`.
template <int D>
constexpr Barycentrics<D> subdivision_child_vertex(int child, int vertex) {
  Barycentrics<D> lambda{};
  for (int end : kSubdivisionChildVertices<D>[child][vertex]) lambda[end] += 0.5;
  return lambda;
}

template <int D>
using SubdivisionChildren = std::array<JacobianCoefficients<D>, kSubdivisionChildCount<D>>;

// The Bernstein coefficients, over every child, of the polynomial given over the parent.
template <int D>
void subdivide_bernstein(const JacobianCoefficients<D>& parent, SubdivisionChildren<D>& children);

}  // namespace hocav
