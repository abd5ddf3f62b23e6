// The surface metric (docs/method.md §10): at the vertices of the boundary facets,
//   M = h_n⁻² n nᵀ + h_t⁻² (I − n nᵀ),
// size h_n along the unit normal n and h_t in the tangent plane. n is the area-weighted vertex
// normal: the sum of the outward normals of the boundary facets around the vertex, each as long as
// its facet is large (length in 2D, area in 3D), normalized. Where that sum vanishes (a vertex
// between facets facing opposite ways, e.g. on a sheet) there is no normal and M = h_n⁻² I, the
// smaller size in every direction.
// Interior vertices (on no boundary facet) start from the isotropic size h_interior, meant to be
// large (`hocav metric` uses the bounding-box diagonal): the gradation of the result (gradation.hpp)
// is what carries the boundary sizes into the volume, shrinking the interior sizes near the boundary.
#pragma once

#include <vector>

#include "geom/sym_mat.hpp"
#include "mesh/mesh.hpp"

namespace hocav {

struct SurfaceSizes {
  double normal = 0.01;     // h_n
  double tangential = 0.1;  // h_t
  double interior = 1;      // the isotropic size of the interior vertices before gradation
};

// Unit outward normals at the vertices of the boundary facets (zero elsewhere, and where the
// facet normals cancel). Outward: away from the element the facet lies on; on a facet inside the
// domain, as Mesh::orient_boundary_facets_outward orients it (away from the side of the smaller
// element ref; a baffle like its patch's first facet), so that the facets of an inner surface add
// up instead of cancelling (until the fifty-sixth session, away from whichever element it was
// linked to). Needs the topology.
template <int D>
std::vector<Vec<D>> boundary_vertex_normals(const Mesh<D>& mesh);

// The metric of a vertex on no boundary facet: the isotropic size sizes.interior.
template <int D>
SymMat<D> surface_interior_metric(const SurfaceSizes& sizes) {
  return (1 / (sizes.interior * sizes.interior)) * SymMat<D>::identity();
}

// One metric per vertex. Throws Error for a non-positive size or a mesh without its topology.
template <int D>
std::vector<SymMat<D>> surface_metric_at_vertices(const Mesh<D>& mesh, const SurfaceSizes& sizes);

// The same at the vertices of a mesh's boundary alone (no elements, its facets oriented outward as
// Mesh::orient_boundary_facets_outward leaves them; docs/distributed.md §Adapting from pieces).
template <int D>
std::vector<SymMat<D>> surface_metric_at_boundary(const Mesh<D>& boundary, const SurfaceSizes& sizes);

}  // namespace hocav
