// Where a curved (P2) mesh meets a plane, to draw a cut through it: the curves in which P2 triangles,
// and the boundaries of P2 tetrahedra, cross the plane.
//
// A triangle is sampled on the lattice of its parameter space split into subdivisions² sub-triangles,
// each sample mapped through the P2 map, and the crossing is found on each sub-triangle by marching
// triangles (the plane's signed distance linear between samples), so a curved edge's cut is a
// curve, exact at the lattice edges it crosses and within O(1/subdivisions²) between them. A sample
// exactly on the plane counts as on its positive side, so every crossing is well defined and the
// curves of a closed surface close. Crossing points are named by the lattice edge they lie on, which
// chains them into curves with no tolerance.
#pragma once

#include <array>
#include <vector>

#include "bezier/p2_element.hpp"
#include "mesh/mesh.hpp"

namespace hocav {

struct CutPlane {
  Vec3 origin;
  Vec3 u{{1, 0, 0}}, v{{0, 1, 0}};  // orthonormal directions in the plane: the picture's x and y

  Vec3 normal() const { return cross(u, v); }
  double signed_distance(const Vec3& x) const { return dot(x - origin, normal()); }
  // Coordinates along u and v from the origin.
  Vec2 coordinates(const Vec3& x) const { return {{dot(x - origin, u), dot(x - origin, v)}}; }
};

struct CutCurve {
  std::vector<Vec3> points;
  bool closed = false;  // the last point joins the first
};

// The cut of a P2 triangle with nodes in hocav's order (v0 v1 v2 m01 m12 m20): open curves from
// edge to edge (closed ones only where the plane grazes a bulge). subdivisions in [1, 64].
std::vector<CutCurve> cut_p2_triangle(const std::array<Vec3, 6>& nodes, const CutPlane& plane, int subdivisions);

// The outline of a P2 tetrahedron's section: closed curves on its boundary.
std::vector<CutCurve> cut_p2_tetrahedron(const P2Element<3>& element, const CutPlane& plane, int subdivisions);

// One closed outline of an element's section, in plane coordinates.
struct CutCell {
  Index element = kNoIndex;
  std::vector<Vec2> outline;
};

// The sections of every element the plane crosses.
std::vector<CutCell> cut_p2_mesh(const Mesh<3>& mesh, const CutPlane& plane, int subdivisions);

}  // namespace hocav
