// Metric sources that `hocav metric` and `hocav adapt` share (docs/usage.md): each gives the metric at
// the vertices of a mesh read from a file.
#pragma once

#include <optional>
#include <vector>

#include "geom/sym_mat.hpp"
#include "io/mesh_file.hpp"
#include "mesh/mesh.hpp"
#include "metric/hessian_source.hpp"

namespace hocav {

// The Lp metric of the source's field at the mesh's vertices (the file's field read at its nodes).
template <int D>
std::vector<SymMat<D>> hessian_source_metrics(const Mesh<D>& mesh, const MeshFileContent& file, const HessianSource& source);

// The surface metric (docs/metrics.md): size `normal` across the boundary and `tangential` along it;
// inside, h_max (default the bounding-box diagonal) until a gradation carries the boundary's sizes in.
template <int D>
std::vector<SymMat<D>> surface_source_metrics(const Mesh<D>& mesh, double normal, double tangential, std::optional<double> h_max);

}  // namespace hocav
