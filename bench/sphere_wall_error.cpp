// How far a curved mesh's wall on a sphere centred at the origin is from the true sphere, against
// the P3 surrogate's own error there (docs/benchmarks.md, "The boundary-layer shell's wall"): for
// every boundary edge of the facets with the given ref, the distance | |x| − R | of the edge's P2
// node, and of the surrogate's point for it: the closest point of the surrogate of INPUT (the
// geometry `hocav adapt` follows) to the node. Also the wall's vertices' distance.
// Prints one Markdown row: edges, node error max / mean, surrogate error max / mean, their ratios,
// the edges whose node is more than twice the surrogate's error (plus 1e-12) from the sphere, and
// the vertices' error max / mean.
//
//   hocav_sphere_wall_error OUTPUT INPUT [ref R]     (default: ref 1, R 0.5: the inner wall of the shells)
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <set>
#include <string>
#include <variant>

#include "base/error.hpp"
#include "io/mesh_file.hpp"
#include "surface/p3_surrogate.hpp"

namespace hocav {
namespace {

struct WallError {
  Index edges = 0, over_twice = 0, vertices = 0;
  double node_max = 0, node_sum = 0, surrogate_max = 0, surrogate_sum = 0, vertex_max = 0, vertex_sum = 0;
};

WallError measure(const Mesh<3>& mesh, const Mesh<3>& input, int ref, double radius) {
  const P3Surrogate<3> surrogate(input);
  std::set<std::uint64_t> edges;
  std::set<Index> vertices;
  for (Index f = 0; f < mesh.facet_count(); ++f)
    if (mesh.facet_ref(f) == ref) {
      for (const auto& ends : kPatchEdges<3>) edges.insert(Mesh<3>::edge_key(mesh.facet(f)[ends[0]], mesh.facet(f)[ends[1]]));
      vertices.insert(mesh.facet(f).begin(), mesh.facet(f).end());
    }
  WallError error;
  for (Index v : vertices) {
    const double distance = std::abs(norm(mesh.vertex(v)) - radius);
    ++error.vertices;
    error.vertex_max = std::max(error.vertex_max, distance);
    error.vertex_sum += distance;
  }
  for (std::uint64_t key : edges) {
    const Index a = static_cast<Index>(key >> 32), b = static_cast<Index>(key & 0xffffffffu);
    const Vec3 x = mesh.edge_node(mesh.find_edge(a, b));
    const double node = std::abs(norm(x) - radius);
    const double proposal = std::abs(norm(surrogate.project(x, {.ref = ref}).point) - radius);
    ++error.edges;
    error.node_max = std::max(error.node_max, node);
    error.node_sum += node;
    error.surrogate_max = std::max(error.surrogate_max, proposal);
    error.surrogate_sum += proposal;
    error.over_twice += node > 2 * proposal + 1e-12;
  }
  return error;
}

}  // namespace
}  // namespace hocav

int main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: hocav_sphere_wall_error OUTPUT INPUT [ref R]\n");
    return 2;
  }
  const int ref = argc > 3 ? std::atoi(argv[3]) : 1;
  const double radius = argc > 4 ? std::strtod(argv[4], nullptr) : 0.5;
  try {
    auto content = hocav::read_mesh_file(argv[1]), input = hocav::read_mesh_file(argv[2]);
    const auto* mesh = std::get_if<hocav::Mesh<3>>(&content.mesh);
    const auto* input_mesh = std::get_if<hocav::Mesh<3>>(&input.mesh);
    if (!mesh || mesh->edge_count() == 0) throw hocav::Error(std::string(argv[1]) + ": not a P2 tetrahedral mesh");
    if (!input_mesh) throw hocav::Error(std::string(argv[2]) + ": not a tetrahedral mesh");
    const hocav::WallError e = hocav::measure(*mesh, *input_mesh, ref, radius);
    const double edges = static_cast<double>(std::max<hocav::Index>(1, e.edges));
    const double vertices = static_cast<double>(std::max<hocav::Index>(1, e.vertices));
    std::printf(
        "| edges | node error max / mean | surrogate error max / mean | ratio max / mean | nodes over 2x surrogate "
        "| vertex error max / mean |\n");
    std::printf("|---|---|---|---|---|---|\n");
    std::printf("| %d | %.3e / %.3e | %.3e / %.3e | %.2f / %.2f | %d | %.3e / %.3e |\n", e.edges, e.node_max, e.node_sum / edges,
                e.surrogate_max, e.surrogate_sum / edges, e.node_max / e.surrogate_max, e.node_sum / e.surrogate_sum, e.over_twice,
                e.vertex_max, e.vertex_sum / vertices);
  } catch (const hocav::Error& error) {
    std::fprintf(stderr, "hocav_sphere_wall_error: %s\n", error.what());
    return 2;
  }
  return 0;
}
