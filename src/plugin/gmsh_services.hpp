// The gmsh entry points the command reaches through its module (README, "License, and hocav without gmsh").
// libgmsh and its ~90 libraries, bound at load, cost every process about 0.12 s of processor time
// at start; the command needs them only for the gmsh-meshed cases and CAD models. So the command
// links the code that calls gmsh from a shared module, hocav-gmsh.so, opened on the first call of
// one of these (gmsh_on_demand.cpp); the module (gmsh_plugin.cpp) hands this table of its
// functions. Both sides are built from the same sources, and the table's version guards against a
// module of another build.
#pragma once

#include <memory>
#include <string>

#include "cases/concentric_shell.hpp"
#include "cases/machined_part.hpp"
#include "mesh/mesh.hpp"
#include "surface/boundary_geometry.hpp"

namespace hocav {

struct GmshServices {
  // Raised whenever the table or a type it passes changes its layout.
  static constexpr int kVersion = 1;
  int version = kVersion;
  Mesh<2> (*generate_annulus)(const ShellParameters&) = nullptr;
  Mesh<3> (*generate_sphere_shell)(const ShellParameters&) = nullptr;
  Mesh<3> (*generate_machined_part)(const MachinedPartParameters&) = nullptr;
  void (*check_cad_path)(const std::string&) = nullptr;
  void (*write_annulus_cad)(double, double, const std::string&) = nullptr;
  void (*write_sphere_shell_cad)(double, double, const std::string&) = nullptr;
  void (*write_machined_part_cad)(const MachinedPartParameters&, const std::string&) = nullptr;
  std::unique_ptr<BoundaryGeometry<2>> (*make_cad_boundary_2)(const std::string&, const Mesh<2>&) = nullptr;
  std::unique_ptr<BoundaryGeometry<3>> (*make_cad_boundary_3)(const std::string&, const Mesh<3>&) = nullptr;
};

}  // namespace hocav

// The one symbol the module exports (gmsh_plugin.map).
extern "C" const hocav::GmshServices* hocav_gmsh_services();
