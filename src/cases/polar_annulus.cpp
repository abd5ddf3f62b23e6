#include "cases/polar_annulus.hpp"

#include <cmath>
#include <numbers>
#include <string>

#include "base/memory_budget.hpp"
#include "cases/parameter_checks.hpp"
#include "cases/target_resolution.hpp"

namespace hocav {

double polar_angular_step(int sectors) { return 2 * std::numbers::pi / sectors; }

double polar_annulus_triangle_count(int sectors, std::size_t radii) { return 2.0 * sectors * (static_cast<double>(radii) - 1); }

Mesh<2> generate_polar_annulus(int sectors, std::span<const double> radii) {
  if (sectors < 3) throw Error("a polar annulus needs at least 3 sectors, got " + std::to_string(sectors));
  check_layer_radii(radii);
  checked_index(static_cast<std::size_t>(sectors) * radii.size() * 2, "triangles");
  check_memory_fits("the polar annulus", polar_annulus_triangle_count(sectors, radii.size()), kMeshBytesPerElement);
  Mesh<2> mesh;
  for (double radius : radii)
    for (int j = 0; j < sectors; ++j) {
      const double angle = polar_angular_step(sectors) * j;
      mesh.add_vertex({{radius * std::cos(angle), radius * std::sin(angle)}});
    }
  const Index m = sectors;
  auto id = [m](std::size_t layer, Index sector) { return static_cast<Index>(layer) * m + sector % m; };
  for (std::size_t layer = 0; layer + 1 < radii.size(); ++layer)
    for (Index j = 0; j < m; ++j) {
      mesh.add_element({id(layer, j), id(layer + 1, j), id(layer + 1, j + 1)}, 1);
      mesh.add_element({id(layer, j), id(layer + 1, j + 1), id(layer, j + 1)}, 1);
    }
  const std::size_t outer = radii.size() - 1;
  for (Index j = 0; j < m; ++j) mesh.add_facet({id(0, j + 1), id(0, j)}, 1);
  for (Index j = 0; j < m; ++j) mesh.add_facet({id(outer, j), id(outer, j + 1)}, 2);
  mesh.build_topology();
  return mesh;
}

Mesh<2> generate_polar_annulus(const ShellLayering& layering, double target_triangles) {
  const auto [sectors, radii] = layered_resolution_for_target("target-triangles", target_triangles, 3, layering, polar_angular_step,
                                                              polar_annulus_triangle_count);
  return generate_polar_annulus(sectors, radii);
}

}  // namespace hocav
