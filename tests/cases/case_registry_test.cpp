#include "cases/case_registry.hpp"

#include <gtest/gtest.h>

#include <set>

#include "base/error.hpp"
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
  EXPECT_EQ(names, (std::set<std::string>{"square", "cube", "annulus", "sphere-shell"}));
  EXPECT_EQ(find_case("annulus").dimension, 2);
  EXPECT_EQ(find_case("sphere-shell").dimension, 3);
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

TEST(Cases, EveryCaseGeneratesAConsistentMeshOfItsDimension) {
  for (const CaseDefinition& definition : case_definitions()) {
    SCOPED_TRACE(definition.name);
    CaseValues coarse{{"h", definition.dimension == 2 ? 0.2 : 0.4}};
    AnyMesh mesh = generate_case(definition, coarse);
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

}  // namespace
}  // namespace hocav
