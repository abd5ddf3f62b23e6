// Where the P3 surrogate of the machined part (docs/cases.md) leaves the CAD (docs/surface.md,
// Accuracy): every boundary edge's surrogate midpoint (the node `hocav curve --surface p3` proposes)
// and its straight midpoint, measured against the CAD surfaces of its facets' refs (both for a
// ridge edge, whose node belongs on the curve they share), grouped by those refs.
// Prints the totals for face and ridge edges, then the groups by decreasing largest error.
//
//   hocav_part_surrogate_error [size h] [wall]     (default: 0.03 0.03, the part of docs/benchmarks.md)
#include <gmsh.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "cases/machined_part.hpp"
#include "surface/cad_boundary_gmsh.hpp"
#include "surface/p3_surrogate.hpp"

namespace hocav {
namespace {

struct Errors {
  Index count = 0;
  double straight_max = 0, surrogate_sum = 0, surrogate_max = 0, exact_normals_max = 0;
  Vec3 worst{};
  double worst_length = 0;

  void add(double straight, double surrogate, double exact_normals, const Vec3& at, double length) {
    ++count;
    straight_max = std::max(straight_max, straight);
    exact_normals_max = std::max(exact_normals_max, exact_normals);
    surrogate_sum += surrogate;
    if (surrogate > surrogate_max) {
      surrogate_max = surrogate;
      worst = at;
      worst_length = length;
    }
  }
};

// The largest distance from x to the CAD surfaces of the refs.
double distance_to_refs(const CadBoundary<3>& cad, const Vec3& x, const std::set<int>& refs) {
  double distance = 0;
  for (int ref : refs) distance = std::max(distance, cad.project(x, {.ref = ref}).distance);
  return distance;
}

std::string surface_types(const CadBoundary<3>& cad, const std::set<int>& refs) {
  std::string text;
  for (int ref : refs) {
    std::string type;
    call_gmsh([&] { gmsh::model::getType(2, cad.entity_of_ref(ref), type); });
    text += (text.empty() ? "" : " / ") + std::to_string(ref) + " " + type;
  }
  return text;
}

void print_row(const char* name, const Errors& errors) {
  std::printf("| %s | %d | %.3g | %.3g | %.3g | %.1f | %.3g |\n", name, errors.count, errors.straight_max,
              errors.surrogate_sum / errors.count, errors.surrogate_max, errors.straight_max / errors.surrogate_max,
              errors.exact_normals_max);
}

void report(const MachinedPartParameters& parameters) {
  const Mesh<3> mesh = generate_machined_part(parameters);
  const std::string path = (std::filesystem::temp_directory_path() / "hocav_part_surrogate_error.step").string();
  write_machined_part_cad(parameters, path);
  const CadBoundary<3> cad(path, mesh);
  std::filesystem::remove(path);
  const P3Surrogate<3> surrogate(mesh);
  const P3Surrogate<3> with_cad_normals(mesh, {.normals = {.normal_source = &cad}});

  std::map<std::uint64_t, std::set<int>> refs_of_edge;
  for (Index f = 0; f < mesh.facet_count(); ++f)
    for (const auto& ends : kPatchEdges<3>)
      refs_of_edge[Mesh<3>::edge_key(mesh.facet(f)[ends[0]], mesh.facet(f)[ends[1]])].insert(mesh.facet_ref(f));
  std::map<std::set<int>, Errors> groups;
  Errors face, ridge;
  for (const auto& [key, refs] : refs_of_edge) {
    const Index a = static_cast<Index>(key >> 32), b = static_cast<Index>(key & 0xffffffffu);
    const Vec3 middle = 0.5 * (mesh.vertex(a) + mesh.vertex(b));
    const double length = norm(mesh.vertex(b) - mesh.vertex(a));
    const double straight = distance_to_refs(cad, middle, refs);
    const double curved = distance_to_refs(cad, *surrogate.edge_midpoint(a, b), refs);
    const double exact_normals = distance_to_refs(cad, *with_cad_normals.edge_midpoint(a, b), refs);
    groups[refs].add(straight, curved, exact_normals, middle, length);
    (refs.size() > 1 ? ridge : face).add(straight, curved, exact_normals, middle, length);
  }
  std::printf("\nmachined part, h = %g, wall = %g: %d boundary triangles, %zu corners\n\n", parameters.size, parameters.wall,
              mesh.facet_count(), mesh.corners().size());
  std::printf("| edges | count | P1 max | surrogate mean | surrogate max | P1 max / surrogate max | with CAD normals, max |\n");
  std::printf("|---|---|---|---|---|---|---|\n");
  print_row("face", face);
  print_row("ridge", ridge);
  std::vector<std::pair<std::set<int>, Errors>> sorted(groups.begin(), groups.end());
  std::sort(sorted.begin(), sorted.end(), [](const auto& a, const auto& b) { return a.second.surrogate_max > b.second.surrogate_max; });
  std::printf("\n| refs (CAD surface types) | edges | P1 max | surrogate mean | surrogate max | with CAD normals | at | edge length |\n");
  std::printf("|---|---|---|---|---|---|---|---|\n");
  for (const auto& [refs, errors] : sorted)
    std::printf("| %s | %d | %.3g | %.3g | %.3g | %.3g | (%.3f, %.3f, %.3f) | %.3f |\n", surface_types(cad, refs).c_str(), errors.count,
                errors.straight_max, errors.surrogate_sum / errors.count, errors.surrogate_max, errors.exact_normals_max, errors.worst[0],
                errors.worst[1], errors.worst[2], errors.worst_length);
}

}  // namespace
}  // namespace hocav

int main(int argc, char** argv) {
  hocav::MachinedPartParameters parameters;
  if (argc > 1) parameters.size = std::strtod(argv[1], nullptr);
  if (argc > 2) parameters.wall = std::strtod(argv[2], nullptr);
  try {
    hocav::report(parameters);
  } catch (const hocav::Error& error) {
    std::fprintf(stderr, "hocav_part_surrogate_error: %s\n", error.what());
    return 2;
  }
  return 0;
}
