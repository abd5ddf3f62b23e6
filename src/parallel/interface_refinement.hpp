// The interfaces of a distributed iteration's parts refined before the parts' loops
// (docs/distributed.md §Interfaces refined first): a part cannot change its frozen interface faces,
// and a coarse one leaves the elements next to it poor, where the serial loop would have cut the
// whole region alike. So the sides of each long interface edge split it at its middle together, and
// in 3D an interface face whose three edges were split becomes the four triangles of a uniform
// refinement (its corners' and its middle's), as the serial loop's cut of a lattice makes it.
#pragma once

#include "adapt/adaptation_metric.hpp"
#include "parallel/mesh_parts.hpp"
#include "surface/boundary_geometry.hpp"

namespace hocav {

// Over every process: the interface edges split (each once), and (3D) the interface faces made the
// four triangles of a uniform refinement.
struct InterfaceRefinement {
  Index edges_split = 0, faces_turned = 0;
};

// Every process at once: the part's interface edges longer than √2 in `metric` split at their
// middles on every side that holds them; an edge is kept when a side holds it on a feature line, on
// a facet of the domain's boundary where `geometry` (null: none) does not put its middle where it is
// (a curved side, or no geometry), in elements of two refs or in separate fans, at a vertex it holds
// in separate fans, or when the operator would refuse its split. The new vertices are interface vertices (required),
// numbered from `next_global_id` (which advances by as many on every process). Then (3D) each
// interface face whose three edges were split has the median its bisections left turned, where both
// sides can (their stars valid, no other turn next to them): its corner triangles and its middle
// one. Throws Error if the sides' meshes disagree.
template <int D>
InterfaceRefinement refine_interfaces(MeshPart<D>& part, const AdaptationMetric<D>& metric, const BoundaryGeometry<D>* geometry,
                                      Index& next_global_id);

}  // namespace hocav
