// hocav picture MESH -o OUT.svg [--cut AXIS=VALUE] [--detail XMIN YMIN XMAX YMAX] [--title TEXT]
// The picture `hocav demo` draws, of any mesh (P1 or P2): each element filled by its min normalized
// Jacobian, a 2D mesh whole with its curved edges drawn exactly, a 3D mesh cut by the plane
// x, y or z = VALUE (picture/jacobian_picture.hpp).
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>
#include <variant>

#include "base/error.hpp"
#include "cli/commands.hpp"
#include "cli/number_checks.hpp"
#include "io/mesh_file.hpp"
#include "io/output_set.hpp"
#include "picture/jacobian_picture.hpp"
#include "report/mesh_summary.hpp"

namespace hocav {
namespace {

struct PictureOptions {
  std::string mesh, output, cut, title;
  std::vector<double> detail;  // XMIN YMIN XMAX YMAX, or none
};

// "z=0" as a plane; the picture's axes are the two others, in order (x=: y, z; y=: x, z; z=: x, y).
CutPlane cut_plane(const std::string& cut) {
  const char* value = cut.c_str() + std::min<std::size_t>(2, cut.size());
  char* end = nullptr;
  const double at = std::strtod(value, &end);
  if (cut.size() < 3 || cut[1] != '=' || (cut[0] != 'x' && cut[0] != 'y' && cut[0] != 'z') || *end != '\0' || !std::isfinite(at))
    throw Error("--cut: AXIS=VALUE with AXIS x, y or z and a finite VALUE, not '" + cut + "'");
  const int axis = cut[0] - 'x', first = axis == 0 ? 1 : 0, second = axis == 2 ? 1 : 2;
  CutPlane plane;
  plane.origin = Vec3{};
  plane.origin[axis] = at;
  plane.u = plane.v = Vec3{};
  plane.u[first] = plane.v[second] = 1;
  return plane;
}

std::optional<Rect> detail_box(const std::vector<double>& detail) {
  if (detail.empty()) return std::nullopt;
  if (!(detail[0] < detail[2] && detail[1] < detail[3])) throw Error("--detail: XMIN YMIN XMAX YMAX with XMIN < XMAX and YMIN < YMAX");
  return Rect{{{detail[0], detail[1]}}, {{detail[2], detail[3]}}};
}

template <int D>
void draw(const Mesh<D>& mesh, const PictureOptions& options, OutputSet& outputs) {
  if (D == 2 && !options.cut.empty()) throw Error("--cut: " + options.mesh + " is 2D, drawn whole; a cut is for a 3D mesh");
  const std::string cut = options.cut.empty() ? "z=0" : options.cut;
  JacobianPictureOptions picture{options.title, mesh_summary(mesh) + "; each element filled by its min normalized Jacobian",
                                 detail_box(options.detail), cut_plane(cut)};
  if (picture.title.empty())
    picture.title = std::filesystem::path(options.mesh).filename().string() + (D == 3 ? ", cut by the plane " + cut : "");
  std::optional<SvgCanvas> canvas;
  try {
    canvas.emplace(jacobian_picture(mesh, min_normalized_jacobians(mesh), picture));
  } catch (const Error& error) {  // a cut that meets nothing
    throw Error(options.mesh + ": --cut " + cut + ": " + error.what());
  }
  write_svg(options.output, *canvas);
  outputs.commit();
  std::cout << "wrote " << options.output << '\n';
}

}  // namespace

void add_picture_command(CLI::App& app) {
  auto options = std::make_shared<PictureOptions>();
  CLI::App* command = app.add_subcommand(
      "picture", "Draw a mesh as SVG, each element filled by its min normalized Jacobian: a 2D mesh whole, a 3D mesh by a planar cut");
  command->add_option("mesh", options->mesh, "mesh to draw (.mesh, .meshb, .msh; P1 or P2)")->required();
  command->add_option("-o,--output", options->output, "picture to write (.svg)")->required();
  command->add_option("--cut", options->cut, "3D: the plane drawn, AXIS=VALUE with AXIS x, y or z (default z=0)");
  command->add_option("--detail", options->detail, "an enlarged view of the box XMIN YMIN XMAX YMAX of the picture's coordinates")
      ->expected(4)
      ->check(finite_number());
  command->add_option("--title", options->title, "the picture's title (default: the mesh's file name, and the plane)");
  command->callback([options] {
    if (file_extension(options->output) != ".svg") throw Error(options->output + ": a picture is written as .svg");
    OutputSet outputs;
    outputs.add_input(options->mesh, "the mesh");
    outputs.add_output(options->output, "-o");
    MeshFileContent file = read_mesh_file(options->mesh);
    std::visit([&](const auto& mesh) { draw(mesh, *options, outputs); }, file.mesh);
  });
}

}  // namespace hocav
