// The picture of a planar cut through a curved 3D mesh: each element's section (planar_cut.hpp) a
// closed curve, filled with the colour of the element's value.
#pragma once

#include <span>
#include <vector>

#include "picture/mesh_figure.hpp"
#include "picture/planar_cut.hpp"

namespace hocav {

// `element_values[k]`: the value element k is coloured by.
SvgCanvas section_picture(const std::vector<CutCell>& cells, std::span<const double> element_values, const MeshFigureOptions& options);

}  // namespace hocav
