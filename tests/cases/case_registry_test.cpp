#include "cases/case_registry.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "base/error.hpp"
#include "cases/gmsh_model.hpp"
#include "mesh/consistency.hpp"

namespace hocav {
namespace {

TEST(Cases, RegistryHoldsTheDocumentedCases) {
  std::set<std::string> names;
  for (const CaseDefinition& definition : case_definitions()) {
    names.insert(definition.name);
    EXPECT_FALSE(definition.description.empty());
    EXPECT_FALSE(definition.options.empty());
    EXPECT_TRUE(definition.make);
  }
  EXPECT_EQ(names, (std::set<std::string>{"square", "cube", "annulus", "sphere-shell", "polar-annulus", "polar-annulus-bl-inner",
                                          "polar-annulus-bl-both", "shear-circle", "cubed-shell", "cubed-shell-bl-inner",
                                          "cubed-shell-bl-both", "part"}));
  EXPECT_EQ(find_case("annulus").dimension, 2);
  EXPECT_EQ(find_case("sphere-shell").dimension, 3);
  EXPECT_EQ(find_case("shear-circle").dimension, 2);
  EXPECT_EQ(find_case("cubed-shell-bl-both").dimension, 3);
}

// Small values of each case's size option.
CaseValues coarse_values(const CaseDefinition& definition) {
  CaseValues values;
  for (const CaseOption& option : definition.options) {
    if (option.name == "h") values["h"] = definition.dimension == 2 ? 0.2 : 0.4;
    if (option.name == "target-tets") values["target-tets"] = 3000;
    if (option.name == "target-triangles") values["target-triangles"] = 500;
  }
  return values;
}

TEST(Cases, UnknownCaseAndOptionAreErrorsThatNameThem) {
  try {
    find_case("torus");
    FAIL() << "no error";
  } catch (const Error& error) {
    EXPECT_NE(std::string(error.what()).find("torus"), std::string::npos);
    EXPECT_NE(std::string(error.what()).find("sphere-shell"), std::string::npos);
  }
  EXPECT_THROW(generate_case(find_case("square"), {{"r-in", 0.1}}), Error);
}

// Built without gmsh, the cases gmsh meshes refuse with an Error saying so.
void expect_needs_gmsh(const CaseDefinition& definition) {
  try {
    generate_case(definition, coarse_values(definition));
    ADD_FAILURE() << "no error";
  } catch (const Error& error) {
    EXPECT_NE(std::string(error.what()).find("case " + definition.name + " needs gmsh"), std::string::npos) << error.what();
  }
}

TEST(Cases, EveryCaseGeneratesAConsistentMeshOfItsDimension) {
  const std::set<std::string> meshed_by_gmsh{"annulus", "sphere-shell", "part"};
  for (const CaseDefinition& definition : case_definitions()) {
    SCOPED_TRACE(definition.name);
    if (!gmsh_available() && meshed_by_gmsh.contains(definition.name)) {
      expect_needs_gmsh(definition);
      continue;
    }
    AnyMesh mesh = generate_case(definition, coarse_values(definition));
    EXPECT_EQ(mesh.index() + 2, static_cast<std::size_t>(definition.dimension));
    std::visit(
        [](const auto& m) {
          ConsistencyOptions options;
          options.require_boundary_facets = true;
          EXPECT_GT(m.element_count(), 0);
          EXPECT_EQ(check_consistency(m, options), std::vector<std::string>{});
        },
        mesh);
  }
}

TEST(Cases, SizeOptionControlsTheStructuredCases) {
  AnyMesh mesh = generate_case(find_case("square"), {{"h", 0.25}});
  EXPECT_EQ(std::get<Mesh<2>>(mesh).element_count(), 2 * 4 * 4);
  mesh = generate_case(find_case("cube"), {{"h", 0.5}});
  EXPECT_EQ(std::get<Mesh<3>>(mesh).element_count(), 6 * 2 * 2 * 2);
}

TEST(Cases, BoundaryLayerOptionsReachTheGenerator) {
  AnyMesh mesh = generate_case(find_case("cubed-shell-bl-inner"),
                               {{"target-tets", 2000}, {"first-layer", 0.004}, {"growth", 1.5}, {"layers", 3}});
  const auto& shell = std::get<Mesh<3>>(mesh);
  std::set<double> radii;
  for (const Vec3& x : shell.vertices()) radii.insert(std::round(norm(x) * 1e9) / 1e9);
  auto r = radii.begin();
  EXPECT_DOUBLE_EQ(*r, 0.5);
  EXPECT_DOUBLE_EQ(*++r, 0.504);
  EXPECT_DOUBLE_EQ(*++r, 0.51);
  EXPECT_DOUBLE_EQ(*++r, 0.519);
  EXPECT_THROW(generate_case(find_case("cubed-shell-bl-inner"), {{"layers", 2.5}}), Error);
  EXPECT_THROW(generate_case(find_case("cubed-shell"), {{"growth", 1.1}}), Error);  // no layers, no growth
  EXPECT_THROW(generate_case(find_case("polar-annulus-bl-both"), {{"growth", 0.8}}), Error);
}

TEST(Cases, TargetOptionPicksTheResolution) {
  for (double target : {2000.0, 20000.0}) {
    const AnyMesh shell_case = generate_case(find_case("cubed-shell"), {{"target-tets", target}});
    const auto& shell = std::get<Mesh<3>>(shell_case);
    EXPECT_NEAR(std::log(shell.element_count() / target), 0, std::log(1.3));
    const AnyMesh annulus_case = generate_case(find_case("polar-annulus"), {{"target-triangles", target}});
    const auto& annulus = std::get<Mesh<2>>(annulus_case);
    EXPECT_NEAR(std::log(annulus.element_count() / target), 0, std::log(1.3));
  }
}

}  // namespace
}  // namespace hocav
