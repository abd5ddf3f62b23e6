#include "cases/case_registry.hpp"

#include <cmath>

#include "cases/concentric_shell.hpp"
#include "cases/cubed_sphere_shell.hpp"
#include "cases/machined_part.hpp"
#include "cases/parameter_checks.hpp"
#include "cases/polar_annulus.hpp"
#include "cases/shear_circle_case.hpp"
#include "cases/structured.hpp"

namespace hocav {
namespace {

CaseOption size_option(double default_value) { return {"h", "target edge length", default_value}; }

ShellParameters shell_parameters(const CaseValues& values) { return {values.at("r-in"), values.at("r-out"), values.at("h")}; }

const std::vector<CaseOption> kShellOptions{{"r-in", "inner radius", 0.5}, {"r-out", "outer radius", 1.0}};

const std::vector<CaseOption> kBoundaryLayerOptions{
    {"first-layer", "thickness of the layer on a wall; 0 = the inner wall's tangential size / 50", 0},
    {"growth", "ratio of the thicknesses of neighbouring layers", 1.2},
    {"layers", "layers per wall; 0 = until they are as thick as the cells are wide (inner) or until the fronts meet (both)", 0}};

// The shells' CAD model: the two circles or spheres of the case's radii.
template <int D>
void write_shell_model(const CaseValues& values, const std::string& path) {
  write_shell_cad<D>(values.at("r-in"), values.at("r-out"), path);
}

int whole_number(const CaseValues& values, const std::string& name) {
  const double value = values.at(name);
  if (!(std::abs(value) < 1e9 && value == std::round(value))) throw Error(name + " must be a whole number, got " + number_text(value));
  return static_cast<int>(value);
}

ShellLayering shell_layering(const CaseValues& values, LayerWalls walls) {
  ShellLayering layering{values.at("r-in"), values.at("r-out"), walls};
  if (walls != LayerWalls::kNone) {
    layering.first_layer = values.at("first-layer");
    layering.growth = values.at("growth");
    layering.layers = whole_number(values, "layers");
  }
  return layering;
}

// The structured shell cases of one dimension: isotropic, boundary layer on the inner wall, on both.
void add_layered_shells(std::vector<CaseDefinition>& definitions, int dimension) {
  const bool three_d = dimension == 3;
  const std::string name = three_d ? "cubed-shell" : "polar-annulus";
  const std::string domain = three_d
                                 ? "between two concentric spheres, structured (cubed sphere x radial layers, 6 tetrahedra per hexahedron)"
                                 : "between two concentric circles, structured (polar grid, 2 triangles per cell)";
  const CaseOption target = three_d ? CaseOption{"target-tets", "number of tetrahedra wanted (the resolution nearest it)", 1e5}
                                    : CaseOption{"target-triangles", "number of triangles wanted (the resolution nearest it)", 1e4};
  const struct {
    const char* suffix;
    const char* layers;
    LayerWalls walls;
  } variants[] = {{"", "isotropic layers", LayerWalls::kNone},
                  {"-bl-inner", "boundary layer on the inner wall", LayerWalls::kInner},
                  {"-bl-both", "boundary layers on both walls, meeting", LayerWalls::kBoth}};
  for (const auto& variant : variants) {
    std::vector<CaseOption> options = kShellOptions;
    options.push_back(target);
    if (variant.walls != LayerWalls::kNone) options.insert(options.end(), kBoundaryLayerOptions.begin(), kBoundaryLayerOptions.end());
    const LayerWalls walls = variant.walls;
    const std::string target_name = target.name;
    definitions.push_back({name + variant.suffix, domain + ", " + variant.layers + "; facet refs 1 inner, 2 outer", dimension, options,
                           [walls, three_d, target_name](const CaseValues& values) {
                             const ShellLayering layering = shell_layering(values, walls);
                             return three_d ? AnyMesh(generate_cubed_sphere_shell(layering, values.at(target_name)))
                                            : AnyMesh(generate_polar_annulus(layering, values.at(target_name)));
                           },
                           three_d ? write_shell_model<3> : write_shell_model<2>});
  }
}

CaseDefinition shear_circle_definition() {
  const AnalyticMetricSpec defaults;
  std::vector<CaseOption> options = kShellOptions;
  options.insert(options.end(), {{"radius", "radius r0 of the shear layer", defaults.radius},
                                 {"width", "width of the shear layer", defaults.width},
                                 {"h-min", "size across the circle r = r0", defaults.h_min},
                                 {"h-max", "size along the circles, and across them far from r0", defaults.h_max}});
  return {"shear-circle",
          "polar annulus, a unit mesh of the shear-circle metric of the same options (the paper's Fig. 1); facet refs "
          "1 inner, 2 outer",
          2,
          options,
          [](const CaseValues& values) {
            AnalyticMetricSpec metric;
            metric.name = "shear-circle";
            metric.radius = values.at("radius");
            metric.width = values.at("width");
            metric.h_min = values.at("h-min");
            metric.h_max = values.at("h-max");
            return AnyMesh(generate_shear_circle_annulus(values.at("r-in"), values.at("r-out"), metric));
          },
          write_shell_model<2>};
}

MachinedPartParameters part_parameters(const CaseValues& values) { return {values.at("h"), values.at("wall")}; }

CaseDefinition machined_part_definition() {
  return {"part",
          "a machined part (gmsh OpenCASCADE): block with rounded corners, a slanted face, a through hole, a spherical "
          "pocket and a thin-walled pocket with a filleted floor; facet refs = CAD surface tags",
          3,
          {size_option(0.03), {"wall", "thickness of the pocket's side walls", 0.03}},
          [](const CaseValues& values) { return AnyMesh(generate_machined_part(part_parameters(values))); },
          [](const CaseValues& values, const std::string& path) { write_machined_part_cad(part_parameters(values), path); }};
}

std::vector<CaseDefinition> make_definitions() {
  std::vector<CaseDefinition> definitions{
      {"square",
       "unit square [0,1]^2, right triangles; facet refs 1 bottom, 2 right, 3 top, 4 left",
       2,
       {size_option(0.1)},
       [](const CaseValues& values) { return AnyMesh(generate_square(cells_for_size(values.at("h")))); },
       nullptr},
      {"cube",
       "unit cube [0,1]^3, 6 tetrahedra per cell; facet refs 1/2 x=0/1, 3/4 y=0/1, 5/6 z=0/1",
       3,
       {size_option(0.25)},
       [](const CaseValues& values) { return AnyMesh(generate_cube(cells_for_size(values.at("h")))); },
       nullptr},
      {"annulus",
       "region between two concentric circles (gmsh); facet refs 1 inner, 2 outer",
       2,
       {kShellOptions[0], kShellOptions[1], size_option(0.1)},
       [](const CaseValues& values) { return AnyMesh(generate_annulus(shell_parameters(values))); },
       write_shell_model<2>},
      {"sphere-shell",
       "region between two concentric spheres (gmsh); facet refs 1 inner, 2 outer",
       3,
       {kShellOptions[0], kShellOptions[1], size_option(0.25)},
       [](const CaseValues& values) { return AnyMesh(generate_sphere_shell(shell_parameters(values))); },
       write_shell_model<3>},
  };
  add_layered_shells(definitions, 2);
  definitions.push_back(shear_circle_definition());
  add_layered_shells(definitions, 3);
  definitions.push_back(machined_part_definition());
  return definitions;
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
