#include "cases/cubed_sphere_shell.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <string>

#include "base/index_hash_map.hpp"
#include "base/memory_budget.hpp"
#include "cases/parameter_checks.hpp"
#include "cases/target_resolution.hpp"
#include "mesh/measure.hpp"

namespace hocav {
namespace {

using Triangle = std::array<Index, 3>;

// The cube's surface grid on the unit sphere: unit directions and outward triangles.
struct SphereGrid {
  std::vector<Vec3> directions;
  std::vector<Triangle> triangles;
};

SphereGrid cubed_sphere_grid(int n) {
  SphereGrid grid;
  const auto side = static_cast<std::uint64_t>(n) + 1;
  grid.directions.reserve(6 * static_cast<std::size_t>(n) * static_cast<std::size_t>(n) + 2);
  grid.triangles.reserve(12 * static_cast<std::size_t>(n) * static_cast<std::size_t>(n));
  // Lattice points of the cube {0..n}³'s surface, each numbered once (edges and corners are shared
  // by faces): key = its position in the (n + 1)³ lattice.
  IndexHashMap ids(grid.directions.capacity());
  auto id = [&](const std::array<int, 3>& lattice) {
    const std::uint64_t key = (static_cast<std::uint64_t>(lattice[0]) * side + static_cast<std::uint64_t>(lattice[1])) * side +
                              static_cast<std::uint64_t>(lattice[2]);
    const Index candidate = static_cast<Index>(grid.directions.size());
    const Index found = ids.insert(key, candidate);
    if (found == candidate) {
      Vec3 direction;
      for (int axis = 0; axis < 3; ++axis)
        direction[axis] = std::tan(std::numbers::pi / 4 * (2.0 * lattice[static_cast<std::size_t>(axis)] / n - 1));
      grid.directions.push_back(direction * (1 / norm(direction)));
    }
    return found;
  };
  auto add_outward = [&grid](Triangle t) {
    if (determinant(grid.directions[t[0]], grid.directions[t[1]], grid.directions[t[2]]) < 0) std::swap(t[1], t[2]);
    grid.triangles.push_back(t);
  };
  for (int axis = 0; axis < 3; ++axis)
    for (int level : {0, n})
      for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
          Index corner[4];
          const int offsets[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
          for (int c = 0; c < 4; ++c) {
            std::array<int, 3> lattice{};
            lattice[static_cast<std::size_t>(axis)] = level;
            lattice[static_cast<std::size_t>((axis + 1) % 3)] = i + offsets[c][0];
            lattice[static_cast<std::size_t>((axis + 2) % 3)] = j + offsets[c][1];
            corner[c] = id(lattice);
          }
          // The shorter diagonal: near the cube's corners the cells are rhombi with 60° and 120°
          // angles, and this diagonal makes near-equilateral triangles there.
          const auto& u = grid.directions;
          if (norm(u[corner[0]] - u[corner[2]]) <= norm(u[corner[1]] - u[corner[3]])) {
            add_outward({corner[0], corner[1], corner[2]});
            add_outward({corner[0], corner[2], corner[3]});
          } else {
            add_outward({corner[0], corner[1], corner[3]});
            add_outward({corner[1], corner[2], corner[3]});
          }
        }
  return grid;
}

}  // namespace

double cubed_sphere_angular_step(int cells_per_side) { return std::numbers::pi / (2.0 * cells_per_side); }

double cubed_sphere_shell_tet_count(int cells_per_side, std::size_t radii) {
  return 36.0 * cells_per_side * cells_per_side * (static_cast<double>(radii) - 1);
}

Mesh<3> generate_cubed_sphere_shell(int n, std::span<const double> radii) {
  if (n < 1) throw Error("a cubed-sphere shell needs at least one cell per cube side, got " + std::to_string(n));
  check_layer_radii(radii);
  const auto layers = radii.size() - 1;
  checked_index((6 * static_cast<std::size_t>(n) * static_cast<std::size_t>(n) + 2) * radii.size(), "vertices");
  checked_index(36 * static_cast<std::size_t>(n) * static_cast<std::size_t>(n) * layers, "tetrahedra");
  check_memory_fits("the cubed-sphere shell", cubed_sphere_shell_tet_count(n, radii.size()), kMeshBytesPerElement);
  const SphereGrid grid = cubed_sphere_grid(n);
  const auto surface_vertices = static_cast<Index>(grid.directions.size());

  Mesh<3> mesh;
  for (double radius : radii)
    for (const Vec3& direction : grid.directions) mesh.add_vertex(radius * direction);
  for (std::size_t layer = 0; layer < layers; ++layer) {
    const Index lower = static_cast<Index>(layer) * surface_vertices, upper = lower + surface_vertices;
    for (Triangle t : grid.triangles) {
      std::sort(t.begin(), t.end());
      const auto [a, b, c] = t;
      for (Mesh<3>::Element tet :
           {Mesh<3>::Element{lower + a, lower + b, lower + c, upper + c}, Mesh<3>::Element{lower + a, lower + b, upper + b, upper + c},
            Mesh<3>::Element{lower + a, upper + a, upper + b, upper + c}}) {
        if (signed_measure(mesh.vertex(tet[0]), mesh.vertex(tet[1]), mesh.vertex(tet[2]), mesh.vertex(tet[3])) < 0)
          std::swap(tet[2], tet[3]);
        mesh.add_element(tet, 1);
      }
    }
  }
  // Outward from the domain: toward the origin on the inner sphere, away from it on the outer one.
  const Index outer = static_cast<Index>(layers) * surface_vertices;
  for (const auto& [a, b, c] : grid.triangles) mesh.add_facet({a, c, b}, 1);
  for (const auto& [a, b, c] : grid.triangles) mesh.add_facet({outer + a, outer + b, outer + c}, 2);
  mesh.build_topology();
  return mesh;
}

Mesh<3> generate_cubed_sphere_shell(const ShellLayering& layering, double target_tets) {
  const auto [n, radii] = layered_resolution_for_target("target-tets", target_tets, 1, layering, cubed_sphere_angular_step,
                                                        cubed_sphere_shell_tet_count);
  return generate_cubed_sphere_shell(n, radii);
}

}  // namespace hocav
