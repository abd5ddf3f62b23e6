// The command side of gmsh_services.hpp: the gmsh entry points of src/cases/ and the CAD reader,
// each opening hocav-gmsh.so on its first call and forwarding to it. The module is looked for
// beside the command (the build tree) and then where `cmake --install` puts it
// (HOCAV_PLUGIN_FROM_BIN, the install's plugin folder relative to its bin folder).
#include <dlfcn.h>

#include <filesystem>
#include <vector>

#include "base/error.hpp"
#include "plugin/gmsh_services.hpp"
#include "surface/boundary_choice.hpp"

namespace hocav {
namespace {

constexpr const char* kModuleName = "hocav-gmsh.so";

std::vector<std::filesystem::path> module_candidates() {
  const std::filesystem::path folder = std::filesystem::read_symlink("/proc/self/exe").parent_path();
  return {folder / kModuleName, (folder / HOCAV_PLUGIN_FROM_BIN / kModuleName).lexically_normal()};
}

const GmshServices& open_gmsh_module() {
  const std::vector<std::filesystem::path> candidates = module_candidates();
  for (const std::filesystem::path& path : candidates) {
    if (!std::filesystem::exists(path)) continue;
    // Never closed: the process keeps gmsh once it has needed it.
    void* module = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (module == nullptr) throw Error("cannot load gmsh's module " + path.string() + ": " + dlerror());
    using Entry = const GmshServices* (*)();
    auto entry = reinterpret_cast<Entry>(dlsym(module, "hocav_gmsh_services"));
    if (entry == nullptr) throw Error(path.string() + " is not hocav's gmsh module (no hocav_gmsh_services)");
    const GmshServices* services = entry();
    if (services->version != GmshServices::kVersion)
      throw Error(path.string() + " is the gmsh module of another hocav build (version " + std::to_string(services->version) +
                  ", this command's " + std::to_string(GmshServices::kVersion) + ")");
    return *services;
  }
  throw Error("gmsh's module " + std::string(kModuleName) + " is neither at " + candidates[0].string() + " nor at " +
              candidates[1].string() + ": the gmsh-meshed cases and CAD models need it");
}

// Opened once per process, on the first call (thread-safe); the table never changes after.
const GmshServices& gmsh_services() {
  static const GmshServices& services = open_gmsh_module();
  return services;
}

}  // namespace

Mesh<2> generate_annulus(const ShellParameters& parameters) { return gmsh_services().generate_annulus(parameters); }

Mesh<3> generate_sphere_shell(const ShellParameters& parameters) { return gmsh_services().generate_sphere_shell(parameters); }

Mesh<3> generate_machined_part(const MachinedPartParameters& parameters) { return gmsh_services().generate_machined_part(parameters); }

void check_cad_path(const std::string& path) { gmsh_services().check_cad_path(path); }

template <int D>
void write_shell_cad(double inner_radius, double outer_radius, const std::string& path) {
  const GmshServices& services = gmsh_services();
  (D == 2 ? services.write_annulus_cad : services.write_sphere_shell_cad)(inner_radius, outer_radius, path);
}

void write_machined_part_cad(const MachinedPartParameters& parameters, const std::string& path) {
  gmsh_services().write_machined_part_cad(parameters, path);
}

template <int D>
std::unique_ptr<BoundaryGeometry<D>> make_cad_boundary(const std::string& cad_path, const Mesh<D>& mesh) {
  if constexpr (D == 2) {
    return gmsh_services().make_cad_boundary_2(cad_path, mesh);
  } else {
    return gmsh_services().make_cad_boundary_3(cad_path, mesh);
  }
}

template void write_shell_cad<2>(double, double, const std::string&);
template void write_shell_cad<3>(double, double, const std::string&);
template std::unique_ptr<BoundaryGeometry<2>> make_cad_boundary(const std::string&, const Mesh<2>&);
template std::unique_ptr<BoundaryGeometry<3>> make_cad_boundary(const std::string&, const Mesh<3>&);

}  // namespace hocav
