// The boundary's feature lines (docs/surface.md, "Feature lines"): where the facets around a
// vertex split into two sides along exactly two edges (a ridge passing through, not a corner), the
// ridge curve's tangent there comes from the feature line itself — the tangent at the vertex of the
// circle through it and its two neighbours along the line — rather than from n_A × n_B. That is
// exact on circular and straight features, and it does not degrade when the two sides' normals are
// nearly parallel (a shallow ridge, a fillet's tangent edge), where the cross product's direction is
// lost in their errors. Both sides' normals at the vertex are then made orthogonal to the tangent,
// so every patch stays tangent to its side's plane (G1 at vertices) and both patches of a ridge edge
// get the same edge curve (it depends on the line only).
//
// Where the two sides meet at a sharp ridge (their normals more than 15° apart), the tangent is
// n_A × n_B instead: exact with exact normals, where the circle errs on curves of varying curvature
// (the ellipse where a slanted plane cuts a cylinder). Shallow ridges keep the circle.
//
// The input's corners (Gamma `Corners` and `RequiredVertices`) end the lines through them: no
// circle is drawn across such a vertex. Where the line turns there, or at a shallow ridge, each
// ridge edge leaves it along its own branch (branch_tangent); where it goes on with one tangent
// (a CAD point between a straight edge and a fillet's arc), or where one branch leaves along the
// sides' n_A × n_B (the other's one-sided circle misled by a varying curvature), a sharp ridge
// uses n_A × n_B.
#pragma once

#include <vector>

#include "mesh/mesh.hpp"
#include "surface/surface_topology.hpp"
#include "surface/vertex_normals.hpp"

namespace hocav {

// Sides whose normals are farther apart than this (15°) meet at a sharp ridge: there their
// normals' cross product gives the line's tangent, which the fitted normals make exact on planes,
// cylinders and spheres where a circle through three vertices is not (an ellipse's ends).
inline constexpr double kSharpRidgeSine = 0.2588;

template <int D>
struct FeatureLines {
  // Per vertex: the unit tangent of the line through it (either orientation), or zero where no
  // line passes through (a smooth vertex, a corner, an end). 2D: all zero (features are points).
  std::vector<Vec<D>> tangents;
  // Per vertex: the vertices joined to it by a feature edge (one whose facets are on different sides).
  std::vector<std::vector<Index>> neighbours;
  // Per vertex: listed in the input's Corners or RequiredVertices.
  std::vector<bool> input_corners;
  // Per vertex: an input corner on a single line that turns there (its two branches' tangents more
  // than 15° from opposite, and at a sharp ridge neither within 5° of n_A × n_B). Where the line
  // goes on with one tangent (a straight edge into an arc), n_A × n_B serves both branches; where
  // more lines meet, each pair of sides has its own.
  std::vector<bool> turns;
};

// Where the tangent of a line through a vertex comes from.
enum class LineTangents {
  kCircle,            // always the circle through the vertex and its two neighbours
  kSharpFromNormals,  // n_A × n_B at sharp ridges (kSharpRidgeSine), for the final, fitted normals
};

// Finds the lines and adjusts the normals of the sides at their vertices as said above.
template <int D>
FeatureLines<D> find_feature_lines(const Mesh<D>& mesh, const SurfaceTopology<D>& topology, VertexNormals<D>& normals,
                                   LineTangents rule = LineTangents::kSharpFromNormals);

// The unit tangent at vertex v of the feature line's branch toward its neighbour w, for a line that
// ends at v: the tangent of the circle through v, w and w's other neighbour when the line passes
// through w, else the chord toward w. Depends on the line's points only, so both patches of the
// edge (v, w) get it bit for bit.
Vec3 branch_tangent(const Mesh<3>& mesh, const FeatureLines<3>& lines, Index v, Index w);

}  // namespace hocav
