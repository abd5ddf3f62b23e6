#include "cases/case_registry.hpp"

#include "cases/concentric_shell.hpp"
#include "cases/structured.hpp"

namespace hocav {
namespace {

CaseOption size_option(double default_value) { return {"h", "target edge length", default_value}; }

ShellParameters shell_parameters(const CaseValues& values) {
  return {values.at("r-in"), values.at("r-out"), values.at("h")};
}

std::vector<CaseDefinition> make_definitions() {
  std::vector<CaseOption> shell_options{{"r-in", "inner radius", 0.5}, {"r-out", "outer radius", 1.0}};
  return {
      {"square", "unit square [0,1]^2, right triangles; facet refs 1 bottom, 2 right, 3 top, 4 left", 2,
       {size_option(0.1)}, [](const CaseValues& values) { return AnyMesh(generate_square(cells_for_size(values.at("h")))); }},
      {"cube", "unit cube [0,1]^3, 6 tetrahedra per cell; facet refs 1/2 x=0/1, 3/4 y=0/1, 5/6 z=0/1", 3,
       {size_option(0.25)}, [](const CaseValues& values) { return AnyMesh(generate_cube(cells_for_size(values.at("h")))); }},
      {"annulus", "region between two concentric circles (gmsh); facet refs 1 inner, 2 outer", 2,
       {shell_options[0], shell_options[1], size_option(0.1)},
       [](const CaseValues& values) { return AnyMesh(generate_annulus(shell_parameters(values))); }},
      {"sphere-shell", "region between two concentric spheres (gmsh); facet refs 1 inner, 2 outer", 3,
       {shell_options[0], shell_options[1], size_option(0.25)},
       [](const CaseValues& values) { return AnyMesh(generate_sphere_shell(shell_parameters(values))); }},
  };
}

}  // namespace

const std::vector<CaseDefinition>& case_definitions() {
  static const std::vector<CaseDefinition> definitions = make_definitions();
  return definitions;
}

const CaseDefinition& find_case(const std::string& name) {
  std::string known;
  for (const CaseDefinition& definition : case_definitions()) {
    if (definition.name == name) return definition;
    known += (known.empty() ? "" : ", ") + definition.name;
  }
  throw Error("unknown case '" + name + "' (known: " + known + ")");
}

AnyMesh generate_case(const CaseDefinition& definition, const CaseValues& values) {
  CaseValues complete;
  for (const CaseOption& option : definition.options) complete[option.name] = option.default_value;
  for (const auto& [name, value] : values) {
    if (!complete.contains(name)) throw Error("case " + definition.name + " has no option '" + name + "'");
    complete[name] = value;
  }
  return definition.make(complete);
}

}  // namespace hocav
