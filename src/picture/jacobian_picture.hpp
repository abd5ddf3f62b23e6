// The picture of a mesh's validity, as `hocav demo` and `hocav picture` draw it: each element filled
// by its min normalized Jacobian (docs/validity.md), a 2D mesh whole and drawn exactly
// (p2_mesh_picture.hpp), a 3D mesh by a planar cut (section_picture.hpp); P1 or P2.
#pragma once

#include <optional>
#include <span>
#include <string>
#include <vector>

#include "mesh/mesh.hpp"
#include "picture/color_map.hpp"
#include "picture/planar_cut.hpp"
#include "picture/svg_canvas.hpp"

namespace hocav {

// Min normalized Jacobian colours: 0 (dark, a degenerate element) to 1 (yellow, as the straight
// element); elements above 1 stay yellow.
inline const ColorScale kJacobianColors{0, 1};
// Lattice subdivisions of each face for a cut: curved edges drawn with 8 pieces each.
inline constexpr int kCutSubdivisions = 8;

struct JacobianPictureOptions {
  std::string title, subtitle;
  std::optional<Rect> detail;  // an enlarged view of this box (in the picture's coordinates)
  CutPlane cut;                // 3D: the plane drawn (default z = 0)
};

// The min normalized Jacobian of each element, refined as the reports refine it.
template <int D>
std::vector<double> min_normalized_jacobians(const Mesh<D>& mesh);

// `jacobians`: min_normalized_jacobians(mesh), given when the caller has them already. A cut that
// meets no element throws Error.
SvgCanvas jacobian_picture(const Mesh<2>& mesh, std::span<const double> jacobians, const JacobianPictureOptions& options);
SvgCanvas jacobian_picture(const Mesh<3>& mesh, std::span<const double> jacobians, const JacobianPictureOptions& options);

}  // namespace hocav
