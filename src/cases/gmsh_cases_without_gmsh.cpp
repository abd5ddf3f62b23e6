// The gmsh entry points of src/cases/ in a build without gmsh (CMake option HOCAV_WITH_GMSH=OFF): the
// same interface as gmsh_model.cpp, concentric_shell.cpp and machined_part.cpp, every call an Error that says what needed
// gmsh, so that the command line reports it in one line and the rest of hocav works without it.
#include "base/error.hpp"
#include "cases/concentric_shell.hpp"
#include "cases/gmsh_model.hpp"
#include "cases/machined_part.hpp"

namespace hocav {
namespace {

// `alternative`: what to use instead, if anything.
[[noreturn]] void throw_gmsh_missing(const std::string& what, const std::string& alternative = "") {
  throw Error(what + " needs gmsh, and this hocav was built without it (HOCAV_WITH_GMSH=OFF)" +
              (alternative.empty() ? "" : "; " + alternative));
}

}  // namespace

bool gmsh_available() { return false; }

GmshSession::GmshSession(const std::string& model_name) { throw_gmsh_missing(model_name); }

GmshSession::~GmshSession() = default;

template <int D>
Mesh<D> extract_gmsh_mesh(const std::vector<GmshBoundaryEntity>&, int) {
  throw_gmsh_missing("extracting a gmsh mesh");
}

// The gmsh-meshed cases; the structured ones (polar-annulus, cubed-shell, shear-circle) need no gmsh.
Mesh<2> generate_annulus(const ShellParameters&) { throw_gmsh_missing("case annulus", "the structured polar-annulus case needs none"); }

Mesh<3> generate_sphere_shell(const ShellParameters&) {
  throw_gmsh_missing("case sphere-shell", "the structured cubed-shell case needs none");
}

Mesh<3> generate_machined_part(const MachinedPartParameters&) { throw_gmsh_missing("case part"); }

std::vector<GmshBoundaryEntity> build_machined_part_model(const MachinedPartParameters&) { throw_gmsh_missing("a CAD model"); }

void write_machined_part_cad(const MachinedPartParameters&, const std::string& path) {
  throw_gmsh_missing("writing the CAD model " + path);
}

template <int D>
std::vector<GmshBoundaryEntity> build_shell_model(double, double) {
  throw_gmsh_missing("a CAD model");
}

template <int D>
void write_shell_cad(double, double, const std::string& path) {
  throw_gmsh_missing("writing the CAD model " + path);
}

// Called before a run that would write a CAD model, so that it stops before any work.
void check_cad_path(const std::string& path) { throw_gmsh_missing("writing the CAD model " + path); }

template Mesh<2> extract_gmsh_mesh(const std::vector<GmshBoundaryEntity>&, int);
template Mesh<3> extract_gmsh_mesh(const std::vector<GmshBoundaryEntity>&, int);
template std::vector<GmshBoundaryEntity> build_shell_model<2>(double, double);
template std::vector<GmshBoundaryEntity> build_shell_model<3>(double, double);
template void write_shell_cad<2>(double, double, const std::string&);
template void write_shell_cad<3>(double, double, const std::string&);

}  // namespace hocav
