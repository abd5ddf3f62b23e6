// The .vtu of a curved mesh for ParaView (docs/formats.md): the metric at every node as a tensor
// and, per element, the certified Jacobian figures of docs/validity.md.
#pragma once

#include <string>
#include <vector>

#include "io/solution_file.hpp"
#include "io/vtu_file.hpp"
#include "metric/metric_field.hpp"

namespace hocav {

// Metric rows (SolutionField, .sol order) as a ParaView tensor field (9 components, row-major; the
// z row and column are 0 in 2D).
template <int D>
VtuField metric_tensor_field(const SolutionField& metric);

// Per element: "min_normalized_jacobian" (min of J / |J_straight|) and "scaled_jacobian" (min J /
// max J, gmsh's measure), refined bounds, for the .vtu cell data.
template <int D>
std::vector<VtuField> jacobian_cell_fields(const Mesh<D>& mesh);

// The data of a curved mesh's .vtu: the metric at every node (sampled from `field`) and
// jacobian_cell_fields.
template <int D>
VtuData curved_vtu_data(const Mesh<D>& mesh, const MetricField<D>& field);

// The curved mesh as a .vtu with curved_vtu_data.
template <int D>
void write_curved_vtu(const std::string& path, const Mesh<D>& mesh, const MetricField<D>& field);

}  // namespace hocav
