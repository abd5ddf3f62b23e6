#include "surface/boundary_choice.hpp"

#include <gtest/gtest.h>

#include "base/error.hpp"
#include "surface/p3_surrogate.hpp"
#include "surface_test_meshes.hpp"

namespace hocav {
namespace {

TEST(BoundaryChoice, NamesTheThreeKindsAndRefusesTheRest) {
  EXPECT_EQ(boundary_choice_named("none").kind, BoundaryKind::kNone);
  EXPECT_EQ(boundary_choice_named("p3").kind, BoundaryKind::kP3Surrogate);
  const BoundaryChoice cad = boundary_choice_named("cad:part.step");
  EXPECT_EQ(cad.kind, BoundaryKind::kCad);
  EXPECT_EQ(cad.cad_path, "part.step");
  EXPECT_THROW(boundary_choice_named("cad:"), Error);
  EXPECT_THROW(boundary_choice_named("P3"), Error);
}

// A CAD reader that records what it was asked for and answers with the mesh's surrogate.
std::string last_cad_path;
Index last_cad_mesh_vertices = 0;
std::unique_ptr<BoundaryGeometry<2>> recording_cad_reader(const std::string& cad_path, const Mesh<2>& mesh) {
  last_cad_path = cad_path;
  last_cad_mesh_vertices = mesh.vertex_count();
  return std::make_unique<P3Surrogate<2>>(mesh);
}

TEST(BoundaryChoice, MakesNoGeometryTheSurrogateOrWhatTheCadReaderReads) {
  const Mesh<2> circle = testing::circle_polygon(24);
  EXPECT_EQ(make_boundary_geometry<2>(boundary_choice_named("none"), circle, &recording_cad_reader), nullptr);
  const auto surrogate = make_boundary_geometry<2>(boundary_choice_named("p3"), circle, nullptr);
  EXPECT_NE(dynamic_cast<const P3Surrogate<2>*>(surrogate.get()), nullptr);
  EXPECT_TRUE(last_cad_path.empty());  // neither asked the reader

  const auto cad = make_boundary_geometry<2>(boundary_choice_named("cad:disk.brep"), circle, &recording_cad_reader);
  EXPECT_NE(cad, nullptr);
  EXPECT_EQ(last_cad_path, "disk.brep");
  EXPECT_EQ(last_cad_mesh_vertices, circle.vertex_count());
}

TEST(BoundaryChoice, ACadModelWithoutAReaderIsAnErrorNamingTheFile) {
  const Mesh<2> circle = testing::circle_polygon(24);
  try {
    make_boundary_geometry<2>(boundary_choice_named("cad:disk.brep"), circle, nullptr);
    FAIL() << "no error";
  } catch (const Error& error) {
    EXPECT_NE(std::string(error.what()).find("disk.brep"), std::string::npos) << error.what();
  }
}

}  // namespace
}  // namespace hocav
