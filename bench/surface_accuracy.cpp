// Accuracy of curved boundaries on the sphere shell (r_in = 0.5, r_out = 1), docs/method.md §9: the largest
// distance to the true spheres of
//   - the P1 boundary,
//   - P2 boundaries whose mid-edge nodes are hocav's proposals: on the P3 surrogate with vertex
//     normals from the facets (angle, area and Max weights) or from the exact spheres, and the exact
//     projection of the straight midpoints,
//   - gmsh's own P2 mesh of the same model (setOrder(2): mid nodes placed on the CAD),
// all on the same triangulation (gmsh's, at sizes h), each boundary triangle sampled at 136 points.
// Prints a Markdown table: the figures of docs/benchmarks.md.
//
//   hocav_surface_accuracy [h ...]     (default: 0.25 0.125)
#include <gmsh.h>

#include <cstdio>
#include <cstdlib>
#include <map>
#include <string>
#include <vector>

#include "cases/concentric_shell.hpp"
#include "cases/gmsh_model.hpp"
#include "surface/analytic_boundary.hpp"
#include "surface/boundary_distance.hpp"
#include "surface/boundary_proposals.hpp"
#include "surface/p3_surrogate.hpp"

namespace hocav {
namespace {

constexpr double kInnerRadius = 0.5, kOuterRadius = 1.0;
constexpr int kSamplesPerSide = 15;  // 136 points per triangle
constexpr int kGmshTriangle6 = 9;

struct ShellBoundaries {
  Mesh<3> straight;  // gmsh's boundary triangles, outward, refs 1 inner and 2 outer
  Mesh<3> gmsh_p2;   // the same with gmsh's mid nodes
};

// Meshes the shell with gmsh at order 2 and keeps its boundary triangles.
ShellBoundaries mesh_shell_boundary(double h) {
  GmshSession session("sphere-shell-p2");
  const std::vector<GmshBoundaryEntity> entities = build_shell_model<3>(kInnerRadius, kOuterRadius);
  std::vector<std::size_t> node_tags;
  std::vector<double> coordinates, parametric;
  std::map<int, std::vector<std::size_t>> triangle_nodes_of_ref;
  call_gmsh([&] {
    gmsh::option::setNumber("Mesh.MeshSizeMin", h);
    gmsh::option::setNumber("Mesh.MeshSizeMax", h);
    gmsh::model::mesh::generate(3);
    gmsh::model::mesh::setOrder(2);
    gmsh::model::mesh::getNodes(node_tags, coordinates, parametric, -1, -1, true, false);
    for (const GmshBoundaryEntity& entity : entities) {
      std::vector<std::size_t> element_tags;
      gmsh::model::mesh::getElementsByType(kGmshTriangle6, element_tags, triangle_nodes_of_ref[entity.ref], entity.tag);
    }
  });
  std::map<std::size_t, Vec3> node_point;
  for (std::size_t i = 0; i < node_tags.size(); ++i)
    node_point[node_tags[i]] = Vec3{{coordinates[3 * i], coordinates[3 * i + 1], coordinates[3 * i + 2]}};

  ShellBoundaries result;
  std::map<std::size_t, Index> vertex_of_tag;
  std::vector<std::pair<std::array<Index, 3>, std::array<Vec3, 3>>> mid_nodes;
  for (const auto& [ref, nodes] : triangle_nodes_of_ref)
    for (std::size_t first = 0; first < nodes.size(); first += 6) {
      std::array<Index, 3> facet;
      for (int i = 0; i < 3; ++i) {
        auto [slot, inserted] = vertex_of_tag.try_emplace(nodes[first + i], result.straight.vertex_count());
        if (inserted) result.straight.add_vertex(node_point.at(nodes[first + i]));
        facet[i] = slot->second;
      }
      // gmsh's tri6 mid nodes are on edges (0,1), (1,2), (2,0).
      std::array<Vec3, 3> middles{node_point.at(nodes[first + 3]), node_point.at(nodes[first + 4]), node_point.at(nodes[first + 5])};
      // Outward from the shell: toward the centre on the inner sphere, away from it on the outer.
      const Vec3& p0 = result.straight.vertex(facet[0]);
      const double outward = dot(cross(result.straight.vertex(facet[1]) - p0, result.straight.vertex(facet[2]) - p0), p0);
      if ((ref == 1) == (outward > 0)) {
        std::swap(facet[1], facet[2]);
        middles = {middles[2], middles[1], middles[0]};
      }
      result.straight.add_facet(facet, ref);
      mid_nodes.push_back({facet, middles});
    }
  result.gmsh_p2 = result.straight;
  result.gmsh_p2.make_p2();
  for (const auto& [facet, middles] : mid_nodes)
    for (int e = 0; e < 3; ++e) result.gmsh_p2.edge_node(result.gmsh_p2.find_edge(facet[e], facet[(e + 1) % 3])) = middles[e];
  return result;
}

// The largest distance of the mesh's boundary edge nodes to the spheres.
double max_node_distance(const Mesh<3>& mesh, const BoundaryGeometry<3>& spheres) {
  double worst = 0;
  for (Index f = 0; f < mesh.facet_count(); ++f)
    for (int e = 0; e < 3; ++e) {
      const Vec3& node = mesh.edge_node(mesh.find_edge(mesh.facet(f)[e], mesh.facet(f)[(e + 1) % 3]));
      worst = std::max(worst, spheres.project(node, {.ref = mesh.facet_ref(f)}).distance);
    }
  return worst;
}

std::string scientific(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.2e", value);
  return text;
}

struct Row {
  std::string name;
  double boundary = 0, nodes = 0;
};

Row curved_with(const std::string& name, const Mesh<3>& straight, const BoundaryGeometry<3>& spheres, const BoundaryGeometry<3>& geometry) {
  BoundaryProposals<3> proposals(straight, geometry);
  Mesh<3> curved = straight;
  apply_boundary_proposals(curved, proposals);
  return {name, max_boundary_distance(curved, spheres, kSamplesPerSide), max_node_distance(curved, spheres)};
}

void report(double h) {
  const ShellBoundaries shell = mesh_shell_boundary(h);
  const Mesh<3>& straight = shell.straight;
  const AnalyticBoundary<3> spheres = concentric_shell_boundary<3>(kInnerRadius, kOuterRadius);
  auto surrogate = [&straight](const SurrogateOptions<3>& options) { return P3Surrogate<3>(straight, options); };
  std::vector<Row> rows;
  rows.push_back({"(P1, straight)", max_boundary_distance(straight, spheres, kSamplesPerSide), 0});
  constexpr TangentLength kThird = TangentLength::kProjectedThird;
  const VertexNormalOptions<3> angle{.quadric_fit = false}, exact{.normal_source = &spheres};
  rows.push_back(curved_with("surrogate, thirds, angle-weighted normals (the usual rule)", straight, spheres,
                             surrogate({.normals = angle, .tangent_length = kThird})));
  rows.push_back(
      curved_with("surrogate, thirds, exact normals", straight, spheres, surrogate({.normals = exact, .tangent_length = kThird})));
  rows.push_back(curved_with("surrogate, arcs, angle-weighted normals", straight, spheres, surrogate({.normals = angle})));
  rows.push_back(curved_with("surrogate, arcs, area-weighted normals", straight, spheres,
                             surrogate({.normals = {.weights = NormalWeights::kArea, .quadric_fit = false}})));
  rows.push_back(curved_with("surrogate, arcs, Max-weighted normals", straight, spheres,
                             surrogate({.normals = {.weights = NormalWeights::kMax, .quadric_fit = false}})));
  rows.push_back(curved_with("**surrogate, arcs, quadric-fit normals (default)**", straight, spheres, surrogate({})));
  rows.push_back(curved_with("surrogate, arcs, exact normals", straight, spheres, surrogate({.normals = exact})));
  rows.push_back(curved_with("midpoints projected on the exact spheres", straight, spheres, spheres));
  rows.push_back({"gmsh setOrder(2) (CAD-placed nodes)", max_boundary_distance(shell.gmsh_p2, spheres, kSamplesPerSide),
                  max_node_distance(shell.gmsh_p2, spheres)});

  const double p1 = rows.front().boundary, gmsh = rows.back().boundary;
  std::printf("\nh = %g: %d boundary triangles, %d boundary vertices\n\n", h, straight.facet_count(), straight.vertex_count());
  std::printf("| P2 mid nodes from | max distance to the spheres | P1 / this | this / gmsh P2 | max mid-node distance |\n");
  std::printf("|---|---|---|---|---|\n");
  for (const Row& row : rows)
    std::printf("| %s | %.2e | %.0f | %.2f | %s |\n", row.name.c_str(), row.boundary, p1 / row.boundary, row.boundary / gmsh,
                row.nodes > 0 ? scientific(row.nodes).c_str() : "—");
}

}  // namespace
}  // namespace hocav

int main(int argc, char** argv) {
  std::vector<double> sizes;
  for (int i = 1; i < argc; ++i) sizes.push_back(std::strtod(argv[i], nullptr));
  if (sizes.empty()) sizes = {0.25, 0.125};
  try {
    for (double h : sizes) hocav::report(h);
  } catch (const hocav::Error& error) {
    std::fprintf(stderr, "hocav_surface_accuracy: %s\n", error.what());
    return 2;
  }
  return 0;
}
