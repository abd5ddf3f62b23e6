#include "cases/concentric_shell.hpp"

#include <gmsh.h>

#include <cmath>
#include <numbers>
#include <string>

#include "base/quiet_stdout.hpp"
#include "cases/gmsh_model.hpp"
#include "cases/parameter_checks.hpp"
#include "io/mesh_file.hpp"

namespace hocav {
namespace {

template <int D>
double shell_measure(const ShellParameters& p) {
  if constexpr (D == 2)
    return std::numbers::pi * (p.outer_radius * p.outer_radius - p.inner_radius * p.inner_radius);
  else
    return 4.0 / 3.0 * std::numbers::pi * (std::pow(p.outer_radius, 3) - std::pow(p.inner_radius, 3));
}

template <int D>
void check_parameters(const ShellParameters& p) {
  check_shell_radii(p.inner_radius, p.outer_radius);
  check_positive("size h", p.size);
  // Measure of an equilateral triangle / regular tetrahedron of edge h.
  double element_measure = D == 2 ? std::sqrt(3.0) / 4 * p.size * p.size : std::pow(p.size, 3) / (6 * std::sqrt(2.0));
  const double elements = shell_measure<D>(p) / element_measure;
  check_case_size(p.size, elements);
}

}  // namespace

template <int D>
std::vector<GmshBoundaryEntity> build_shell_model(double inner_radius, double outer_radius) {
  check_shell_radii(inner_radius, outer_radius);
  return call_gmsh([inner_radius, outer_radius] {
    namespace occ = gmsh::model::occ;
    auto add_ball = [](double radius) { return D == 2 ? occ::addDisk(0, 0, 0, radius, radius) : occ::addSphere(0, 0, 0, radius); };
    int outer = add_ball(outer_radius);
    int inner = add_ball(inner_radius);
    gmsh::vectorpair shell;
    std::vector<gmsh::vectorpair> ancestry;
    occ::cut({{D, outer}}, {{D, inner}}, shell, ancestry);
    occ::synchronize();

    // Each boundary entity is one whole circle or sphere: its bounding box tells which.
    gmsh::vectorpair boundary_entities;
    gmsh::model::getEntities(boundary_entities, D - 1);
    std::vector<GmshBoundaryEntity> boundary;
    for (const auto& [dimension, tag] : boundary_entities) {
      double x_min, y_min, z_min, x_max, y_max, z_max;
      gmsh::model::getBoundingBox(dimension, tag, x_min, y_min, z_min, x_max, y_max, z_max);
      bool inner_side = std::abs(x_max - inner_radius) < std::abs(x_max - outer_radius);
      boundary.push_back({tag, inner_side ? 1 : 2});
    }
    return boundary;
  });
}

template <int D>
void write_shell_cad(double inner_radius, double outer_radius, const std::string& path) {
  check_cad_path(path);
  GmshSession session(D == 2 ? "annulus" : "sphere-shell");
  build_shell_model<D>(inner_radius, outer_radius);
  call_gmsh([&path] {
    QuietStdout quiet;
    gmsh::write(path);
  });
}

void check_cad_path(const std::string& path) {
  const std::string extension = file_extension(path);
  if (extension != ".brep" && extension != ".step" && extension != ".stp")
    throw Error(path + ": a CAD file must end in .brep, .step or .stp");
}

namespace {

template <int D>
Mesh<D> generate_shell(const ShellParameters& p, const std::string& name) {
  check_parameters<D>(p);
  GmshSession session(name);
  auto boundary = build_shell_model<D>(p.inner_radius, p.outer_radius);
  call_gmsh([&p] {
    gmsh::option::setNumber("Mesh.MeshSizeMin", p.size);
    gmsh::option::setNumber("Mesh.MeshSizeMax", p.size);
    gmsh::model::mesh::generate(D);
  });
  Mesh<D> mesh = extract_gmsh_mesh<D>(boundary, 1);
  // gmsh evaluates boundary nodes on the CAD surface; projecting them radially removes the last
  // rounding so that "on the boundary" holds exactly for the curving code and the tests.
  for (Index f = 0; f < mesh.facet_count(); ++f) {
    double radius = mesh.facet_ref(f) == 1 ? p.inner_radius : p.outer_radius;
    for (Index v : mesh.facet(f)) mesh.vertex(v) *= radius / norm(mesh.vertex(v));
  }
  return mesh;
}

}  // namespace

Mesh<2> generate_annulus(const ShellParameters& parameters) { return generate_shell<2>(parameters, "annulus"); }

Mesh<3> generate_sphere_shell(const ShellParameters& parameters) { return generate_shell<3>(parameters, "sphere-shell"); }

template std::vector<GmshBoundaryEntity> build_shell_model<2>(double, double);
template std::vector<GmshBoundaryEntity> build_shell_model<3>(double, double);
template void write_shell_cad<2>(double, double, const std::string&);
template void write_shell_cad<3>(double, double, const std::string&);

}  // namespace hocav
