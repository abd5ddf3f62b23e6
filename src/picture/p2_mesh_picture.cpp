#include "picture/p2_mesh_picture.hpp"

namespace hocav {

SvgPath p2_triangle_path(const P2Element<2>& element, const PageTransform& transform) {
  // The page map is affine, so it maps Bézier control points to Bézier control points.
  const BezierControlNet<2> net = control_net(element);
  SvgPath path;
  path.move_to(transform(element.vertex(0)));
  for (int edge = 0; edge < Simplex<2>::kEdges; ++edge) {
    const auto& ends = edge_vertices<2>(edge);
    path.quadratic_to(transform(net.of_pair(ends[0], ends[1])), transform(element.vertex(ends[1])));
  }
  return path.close();
}

SvgCanvas p2_mesh_picture(const Mesh<2>& mesh, std::span<const double> element_values, const MeshFigureOptions& options) {
  std::vector<P2Element<2>> elements;
  std::vector<Vec2> all_points;
  for (Index k = 0; k < mesh.element_count(); ++k) {
    elements.push_back(gather_p2_element(mesh, k));
    all_points.insert(all_points.end(), elements.back().nodes.begin(), elements.back().nodes.end());
  }
  return mesh_figure(bounding_rect(all_points), options, [&](SvgCanvas& canvas, const PanelView& view) {
    for (std::size_t k = 0; k < elements.size(); ++k) {
      // The Lagrange nodes' box is close enough to the triangle's for skipping what is far outside.
      if (!view.visible.intersects(bounding_rect(elements[k].nodes))) continue;
      canvas.path(p2_triangle_path(elements[k], view.transform), {options.colors(element_values[k]).hex(), "#1a1a1a", view.line_width});
    }
  });
}

}  // namespace hocav
