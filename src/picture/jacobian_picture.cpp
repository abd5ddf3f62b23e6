#include "picture/jacobian_picture.hpp"

#include "base/error.hpp"
#include "bezier/mesh_quality.hpp"
#include "picture/p2_mesh_picture.hpp"
#include "picture/section_picture.hpp"

namespace hocav {
namespace {

MeshFigureOptions figure_options(const JacobianPictureOptions& options) {
  return {options.title, options.subtitle, kJacobianColors, "min normalized Jacobian", options.detail};
}

}  // namespace

template <int D>
std::vector<double> min_normalized_jacobians(const Mesh<D>& mesh) {
  std::vector<double> values;
  for (const JacobianQuality& quality : mesh_jacobian_quality(mesh, kReportedRefinement)) values.push_back(quality.min_normalized_jacobian);
  return values;
}

SvgCanvas jacobian_picture(const Mesh<2>& mesh, std::span<const double> jacobians, const JacobianPictureOptions& options) {
  return p2_mesh_picture(mesh, jacobians, figure_options(options));
}

SvgCanvas jacobian_picture(const Mesh<3>& mesh, std::span<const double> jacobians, const JacobianPictureOptions& options) {
  const std::vector<CutCell> cells = cut_p2_mesh(mesh, options.cut, kCutSubdivisions);
  if (cells.empty()) throw Error("the cut plane meets no element of the mesh");
  return section_picture(cells, jacobians, figure_options(options));
}

template std::vector<double> min_normalized_jacobians(const Mesh<2>&);
template std::vector<double> min_normalized_jacobians(const Mesh<3>&);

}  // namespace hocav
