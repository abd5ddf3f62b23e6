// The module side of gmsh_services.hpp: the table of the functions of hocav_gmsh that call gmsh.
// Everything else of the module, hocav's library included, stays local to it (gmsh_plugin.map).
#include "plugin/gmsh_services.hpp"

#include "surface/boundary_choice.hpp"

namespace {

hocav::GmshServices make_services() {
  hocav::GmshServices services;
  services.generate_annulus = &hocav::generate_annulus;
  services.generate_sphere_shell = &hocav::generate_sphere_shell;
  services.generate_machined_part = &hocav::generate_machined_part;
  services.check_cad_path = &hocav::check_cad_path;
  services.write_annulus_cad = &hocav::write_shell_cad<2>;
  services.write_sphere_shell_cad = &hocav::write_shell_cad<3>;
  services.write_machined_part_cad = &hocav::write_machined_part_cad;
  services.make_cad_boundary_2 = &hocav::make_cad_boundary<2>;
  services.make_cad_boundary_3 = &hocav::make_cad_boundary<3>;
  return services;
}

}  // namespace

extern "C" const hocav::GmshServices* hocav_gmsh_services() {
  static const hocav::GmshServices services = make_services();
  return &services;
}
