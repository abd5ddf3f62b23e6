#include "cases/machined_part.hpp"

#include <gmsh.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <numbers>
#include <set>

#include "base/quiet_stdout.hpp"
#include "cases/concentric_shell.hpp"
#include "cases/parameter_checks.hpp"

namespace hocav {
namespace {

constexpr double kLength = 1.0, kWidth = 0.6, kHeight = 0.4;
constexpr double kCornerRadius = 0.06, kHoleRadius = 0.1, kPocketRadius = 0.15, kFloorFilletRadius = 0.04;
constexpr double kSlantDegrees = 20;
constexpr double kPocketFloor = 0.12;  // height of the rectangular pocket's floor
// OpenCASCADE pads bounding boxes by 1e-7; entities are picked with a margin above that.
constexpr double kMargin = 1e-5;

void check_parameters(const MachinedPartParameters& p) {
  check_positive("size h", p.size);
  check_positive("wall", p.wall);
  if (p.wall > 0.1) throw Error("wall = " + number_text(p.wall) + " is too thick for the part (at most 0.1)");
  // A regular tetrahedron of edge h has volume h³ / (6√2); the part's volume is below the block's.
  const double elements = kLength * kWidth * kHeight / (std::pow(p.size, 3) / (6 * std::sqrt(2.0)));
  check_case_size(p.size, elements);
}

// The curves of the current model lying inside a box.
std::vector<int> curves_in(double x0, double y0, double z0, double x1, double y1, double z1) {
  gmsh::vectorpair found;
  gmsh::model::occ::getEntitiesInBoundingBox(x0 - kMargin, y0 - kMargin, z0 - kMargin, x1 + kMargin, y1 + kMargin, z1 + kMargin, found, 1);
  std::vector<int> tags;
  for (const auto& entity : found) tags.push_back(entity.second);
  return tags;
}

int block_with_rounded_corners() {
  namespace occ = gmsh::model::occ;
  const int box = occ::addBox(0, 0, 0, kLength, kWidth, kHeight);
  occ::synchronize();
  std::vector<int> vertical;
  for (int curve : curves_in(0, 0, 0, kLength, kWidth, kHeight)) {
    double x0, y0, z0, x1, y1, z1;
    occ::getBoundingBox(1, curve, x0, y0, z0, x1, y1, z1);
    if (std::abs(z1 - z0 - kHeight) < kMargin) vertical.push_back(curve);
  }
  gmsh::vectorpair rounded;
  occ::fillet({box}, vertical, {kCornerRadius}, rounded);
  return rounded.front().second;
}

int pocket_tool(double wall) {
  namespace occ = gmsh::model::occ;
  const double x0 = 0.72;
  const int box = occ::addBox(x0, wall, kPocketFloor, kLength - wall - x0, kWidth - 2 * wall, kHeight);
  occ::synchronize();
  gmsh::vectorpair filleted;
  occ::fillet({box}, curves_in(x0, 0, kPocketFloor, kLength, kWidth, kPocketFloor), {kFloorFilletRadius}, filleted);
  return filleted.front().second;
}

// The CAD points where three or more surfaces meet: the ends of the model's curves, where the
// feature lines turn or change curvature (a straight edge running into a fillet's arc).
std::vector<Vec3> corner_points() {
  gmsh::vectorpair points;
  gmsh::model::getEntities(points, 0);
  std::vector<Vec3> corners;
  for (const auto& point : points) {
    std::vector<int> curves, unused, surfaces;
    gmsh::model::getAdjacencies(0, point.second, curves, unused);
    std::set<int> around;
    for (int curve : curves) {
      gmsh::model::getAdjacencies(1, curve, surfaces, unused);
      around.insert(surfaces.begin(), surfaces.end());
    }
    if (around.size() < 3) continue;
    std::vector<double> xyz, parametric;
    gmsh::model::getValue(0, point.second, parametric, xyz);
    corners.push_back(Vec3{{xyz[0], xyz[1], xyz[2]}});
  }
  return corners;
}

// Lists the mesh vertices at the corner points as Corners (gmsh puts a node on every model point).
void add_corners(Mesh<3>& mesh, const std::vector<Vec3>& points) {
  std::map<std::array<double, 3>, Index> vertex_at;
  for (Index v = 0; v < mesh.vertex_count(); ++v) vertex_at[mesh.vertex(v).c] = v;
  for (const Vec3& point : points)
    if (const auto found = vertex_at.find(point.c); found != vertex_at.end()) mesh.corners().push_back(found->second);
  std::sort(mesh.corners().begin(), mesh.corners().end());
}

}  // namespace

std::vector<GmshBoundaryEntity> build_machined_part_model(const MachinedPartParameters& p) {
  check_parameters(p);
  return call_gmsh([&p] {
    namespace occ = gmsh::model::occ;
    const int block = block_with_rounded_corners();
    const int wedge = occ::addBox(-0.5, -0.5, 0, 0.5, kWidth + 1, 1);
    occ::rotate({{3, wedge}}, 0, 0, kHeight, 0, 1, 0, kSlantDegrees * std::numbers::pi / 180);
    occ::translate({{3, wedge}}, 0.12, 0, 0);
    const int hole = occ::addCylinder(0.27, 0.3, -0.1, 0, 0, kHeight + 0.2, kHoleRadius);
    const int sphere = occ::addSphere(0.55, 0.3, kHeight + 0.07, kPocketRadius);
    const int pocket = pocket_tool(p.wall);
    gmsh::vectorpair part;
    std::vector<gmsh::vectorpair> ancestry;
    occ::cut({{3, block}}, {{3, wedge}, {3, hole}, {3, sphere}, {3, pocket}}, part, ancestry);
    occ::synchronize();
    gmsh::vectorpair surfaces;
    gmsh::model::getEntities(surfaces, 2);
    std::vector<GmshBoundaryEntity> boundary;
    for (const auto& surface : surfaces) boundary.push_back({surface.second, surface.second});
    return boundary;
  });
}

Mesh<3> generate_machined_part(const MachinedPartParameters& p) {
  check_parameters(p);
  GmshSession session("machined-part");
  const auto boundary = build_machined_part_model(p);
  const std::vector<Vec3> corners = call_gmsh([&p] {
    gmsh::option::setNumber("Mesh.MeshSizeMin", p.size);
    gmsh::option::setNumber("Mesh.MeshSizeMax", p.size);
    gmsh::model::mesh::generate(3);
    return corner_points();
  });
  Mesh<3> mesh = extract_gmsh_mesh<3>(boundary, 1);
  add_corners(mesh, corners);
  return mesh;
}

void write_machined_part_cad(const MachinedPartParameters& p, const std::string& path) {
  check_cad_path(path);
  GmshSession session("machined-part");
  build_machined_part_model(p);
  call_gmsh([&path] {
    QuietStdout quiet;
    gmsh::write(path);
  });
}

}  // namespace hocav
