#include "surface/cad_boundary_gmsh.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>

#include "base/error.hpp"
#include "cases/concentric_shell.hpp"
#include "gmsh_requirement.hpp"
#include "surface/analytic_boundary.hpp"
#include "surface/boundary_proposals.hpp"
#if HOCAV_WITH_GMSH
#include <gmsh.h>  // the cylinder of RidgeCurveBetweenTwoSurfaces
#endif

namespace hocav {
namespace {

std::string cad_temporary_path(const std::string& name) { return (std::filesystem::path(::testing::TempDir()) / name).string(); }

// OpenCASCADE's projections onto its spheres are accurate to about this.
constexpr double kCadTolerance = 1e-9;

TEST(SurfaceCad, SphereShellBrepWithRefsAsTags) {
  HOCAV_SKIP_WITHOUT_GMSH();
  const std::string path = cad_temporary_path("hocav_shell.brep");
  write_shell_cad<3>(0.5, 1.0, path);
  const CadBoundary<3> cad(path);
  // Read back, OpenCASCADE numbers the outer sphere 1 and the inner one 2.
  const Vec3 x{{0.3, 0.4, 0.2}};
  EXPECT_NEAR(norm(cad.project(x, {.ref = 1}).point), 1.0, kCadTolerance);
  EXPECT_NEAR(norm(cad.project(x, {.ref = 2}).point), 0.5, kCadTolerance);
  const BoundaryPoint<3> closest = cad.project(x);
  EXPECT_EQ(closest.ref, 2);
  EXPECT_EQ(closest.patch, 2);
  EXPECT_NEAR(closest.distance, norm(x) - 0.5, kCadTolerance);
  EXPECT_LT(norm(closest.point - x * (0.5 / norm(x))), kCadTolerance);
  const Vec3 normal = cad.normal(x, {.ref = 1});
  EXPECT_NEAR(std::abs(dot(normal, x * (1 / norm(x)))), 1.0, 1e-9);
  EXPECT_THROW(cad.project(x, {.ref = 3}), Error);
  std::filesystem::remove(path);
}

TEST(SurfaceCad, SphereShellRefsMapByProximity) {
  HOCAV_SKIP_WITHOUT_GMSH();
  const ShellParameters parameters{0.5, 1.0, 0.5};
  const Mesh<3> mesh = generate_sphere_shell(parameters);
  const std::string path = cad_temporary_path("hocav_shell.step");
  write_shell_cad<3>(parameters.inner_radius, parameters.outer_radius, path);
  const CadBoundary<3> cad(path, mesh);
  EXPECT_EQ(cad.entity_of_ref(1), 2);  // the mesh's inner sphere is the CAD's surface 2
  EXPECT_EQ(cad.entity_of_ref(2), 1);
  // Proposals on the CAD are the analytic ones, to OpenCASCADE's accuracy.
  const BoundaryProposals<3> on_cad(mesh, cad), exact(mesh, concentric_shell_boundary<3>(0.5, 1.0));
  for (Index f = 0; f < mesh.facet_count(); ++f) {
    const Index a = mesh.facet(f)[0], b = mesh.facet(f)[1];
    EXPECT_LT(norm(*on_cad.find(a, b) - *exact.find(a, b)), kCadTolerance);
  }
  std::filesystem::remove(path);
}

TEST(SurfaceCad, AnnulusCurves) {
  HOCAV_SKIP_WITHOUT_GMSH();
  const ShellParameters parameters{0.5, 1.0, 0.2};
  const Mesh<2> mesh = generate_annulus(parameters);
  const std::string path = cad_temporary_path("hocav_annulus.brep");
  write_shell_cad<2>(parameters.inner_radius, parameters.outer_radius, path);
  const CadBoundary<2> cad(path, mesh);
  const Vec2 x{{0.3, 0.4}};
  EXPECT_NEAR(norm(cad.project(x, {.ref = 1}).point), 0.5, kCadTolerance);
  EXPECT_NEAR(norm(cad.project(x, {.ref = 2}).point), 1.0, kCadTolerance);
  EXPECT_NEAR(std::abs(dot(cad.normal(x, {.ref = 2}), Vec2{{0.6, 0.8}})), 1.0, 1e-9);
  std::filesystem::remove(path);
}

// A cylinder's side and top meet along a circle: edges across them are projected onto it.
TEST(SurfaceCad, RidgeCurveBetweenTwoSurfaces) {
  HOCAV_SKIP_WITHOUT_GMSH();
  const std::string path = cad_temporary_path("hocav_cylinder.brep");
#if HOCAV_WITH_GMSH
  {
    GmshSession session("cylinder");
    call_gmsh([&] {
      gmsh::model::occ::addCylinder(0, 0, 0, 0, 0, 1, 1);
      gmsh::model::occ::synchronize();
      gmsh::write(path);
    });
  }
#endif
  const CadBoundary<3> cad(path);
  // Find the side (the surface with a radial normal) and a cap among the tags.
  int side = 0, cap = 0;
  for (int tag = 1; tag <= 3; ++tag) {
    const Vec3 normal = cad.normal(Vec3{{0.5, 0.0, 0.9}}, {.ref = tag});
    (std::abs(normal[2]) < 1e-9 ? side : cap) = tag;
  }
  ASSERT_NE(side, 0);
  ASSERT_NE(cap, 0);
  const Vec3 rim = cad.project_on_intersection(Vec3{{0.8, 0.6, 1.1}}, side, cap);
  EXPECT_NEAR(std::hypot(rim[0], rim[1]), 1.0, kCadTolerance);
  EXPECT_NEAR(std::abs(rim[2] - 0.5), 0.5, kCadTolerance);
  std::filesystem::remove(path);
}

TEST(SurfaceCad, Errors) {
  HOCAV_SKIP_WITHOUT_GMSH();
  EXPECT_THROW(CadBoundary<3>(cad_temporary_path("no_such_file.brep")), Error);
  const std::string path = cad_temporary_path("hocav_shell_errors.brep");
  write_shell_cad<3>(0.5, 1.0, path);
  {
    const CadBoundary<3> cad(path);
    // gmsh is held by the CAD boundary: another session in this thread is refused, not a deadlock.
    EXPECT_THROW(GmshSession("second"), Error);
  }
  // A mesh that lies on no surface of the model.
  Mesh<3> far_away = generate_sphere_shell({2.0, 3.0, 1.0});
  EXPECT_THROW(CadBoundary<3>(path, far_away), Error);
  EXPECT_THROW(write_shell_cad<3>(0.5, 1.0, cad_temporary_path("shell.iges")), Error);
  std::filesystem::remove(path);
}

}  // namespace
}  // namespace hocav
