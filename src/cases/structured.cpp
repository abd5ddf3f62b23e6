#include "cases/structured.hpp"

#include <cmath>
#include <string>

#include "base/error.hpp"
#include "base/memory_budget.hpp"
#include "mesh/measure.hpp"

namespace hocav {

int cells_for_size(double h) {
  if (!(h > 0) || !std::isfinite(h)) throw Error("size h must be positive, got " + std::to_string(h));
  double cells = std::ceil(1.0 / h - 1e-9);
  if (cells > 2000) throw Error("size h = " + std::to_string(h) + " is too small for a structured case");
  return static_cast<int>(cells);
}

Mesh<2> generate_square(int n) {
  if (n < 1) throw Error("a structured case needs at least one cell per side");
  check_memory_fits("the square of " + std::to_string(n) + " cells per side", 2.0 * n * n, kMeshBytesPerElement);
  Mesh<2> mesh;
  auto id = [n](int i, int j) { return static_cast<Index>(j * (n + 1) + i); };
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) mesh.add_vertex({{double(i) / n, double(j) / n}});
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      mesh.add_element({id(i, j), id(i + 1, j), id(i + 1, j + 1)}, 1);
      mesh.add_element({id(i, j), id(i + 1, j + 1), id(i, j + 1)}, 1);
    }
  for (int i = 0; i < n; ++i) {
    mesh.add_facet({id(i, 0), id(i + 1, 0)}, 1);
    mesh.add_facet({id(n, i), id(n, i + 1)}, 2);
    mesh.add_facet({id(i + 1, n), id(i, n)}, 3);
    mesh.add_facet({id(0, i + 1), id(0, i)}, 4);
  }
  mesh.corners() = {id(0, 0), id(n, 0), id(n, n), id(0, n)};
  mesh.build_topology();
  return mesh;
}

Mesh<3> generate_cube(int n) {
  if (n < 1) throw Error("a structured case needs at least one cell per side");
  check_memory_fits("the cube of " + std::to_string(n) + " cells per side", 6.0 * n * n * n, kMeshBytesPerElement);
  Mesh<3> mesh;
  auto id = [n](int i, int j, int k) { return static_cast<Index>((k * (n + 1) + j) * (n + 1) + i); };
  for (int k = 0; k <= n; ++k)
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i <= n; ++i) mesh.add_vertex({{double(i) / n, double(j) / n, double(k) / n}});
  // Kuhn subdivision: one tetrahedron per path from corner 000 to 111 along the axes; every cell
  // uses the same main diagonal, so faces match between neighbouring cells.
  static constexpr int kAxisOrders[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i)
        for (const auto& axes : kAxisOrders) {
          int c[3] = {i, j, k};
          Mesh<3>::Element tet;
          tet[0] = id(c[0], c[1], c[2]);
          for (int step = 0; step < 3; ++step) {
            ++c[axes[step]];
            tet[step + 1] = id(c[0], c[1], c[2]);
          }
          if (signed_measure(mesh.vertex(tet[0]), mesh.vertex(tet[1]), mesh.vertex(tet[2]), mesh.vertex(tet[3])) < 0)
            std::swap(tet[2], tet[3]);
          mesh.add_element(tet, 1);
        }
  mesh.build_topology();
  // Boundary facets: the element faces without a neighbour, oriented outward, ref by cube side.
  for (Index t = 0; t < mesh.element_count(); ++t)
    for (int face = 0; face < 4; ++face) {
      if (mesh.neighbor(t, face) != kNoIndex) continue;
      Mesh<3>::Facet facet;
      Vec3 centre{};
      for (int i = 0; i < 3; ++i) {
        facet[i] = mesh.element(t)[face_vertices<3>(face)[i]];
        centre += mesh.vertex(facet[i]) * (1.0 / 3);
      }
      int ref = 0;
      for (int axis = 0; axis < 3; ++axis) {
        if (centre[axis] < 1e-12) ref = 2 * axis + 1;
        if (centre[axis] > 1 - 1e-12) ref = 2 * axis + 2;
      }
      mesh.add_facet(facet, ref);
    }
  for (int k = 0; k <= n; k += n)
    for (int j = 0; j <= n; j += n)
      for (int i = 0; i <= n; i += n) mesh.corners().push_back(id(i, j, k));
  // The cube's 12 edges as ridge lines.
  for (int a = 0; a <= n; a += n)
    for (int b = 0; b <= n; b += n)
      for (int s = 0; s < n; ++s) {
        mesh.ridges().push_back(mesh.add_line({id(s, a, b), id(s + 1, a, b)}, 1));
        mesh.ridges().push_back(mesh.add_line({id(a, s, b), id(a, s + 1, b)}, 1));
        mesh.ridges().push_back(mesh.add_line({id(a, b, s), id(a, b, s + 1)}, 1));
      }
  mesh.build_topology();
  return mesh;
}

}  // namespace hocav
