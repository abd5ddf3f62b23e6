#include "io/mesh_file.hpp"

#include <algorithm>
#include <cctype>

#include "base/error.hpp"
#include "io/gamma_mesh.hpp"
#include "io/gmsh_msh.hpp"
#include "io/vtu_file.hpp"

namespace hocav {

std::string file_extension(const std::string& path) {
  auto slash = path.find_last_of('/');
  auto dot = path.find_last_of('.');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return "";
  std::string extension = path.substr(dot);
  std::transform(extension.begin(), extension.end(), extension.begin(), [](unsigned char c) { return std::tolower(c); });
  return extension;
}

bool is_gamma_path(const std::string& path) {
  const std::string extension = file_extension(path);
  return extension == ".mesh" || extension == ".meshb";
}

MeshFileContent read_mesh_file(const std::string& path) {
  std::string extension = file_extension(path);
  if (is_gamma_path(path)) return read_gamma_mesh(path);
  if (extension == ".msh") return read_gmsh_msh(path);
  throw Error(path + ": unknown mesh format '" + extension + "' (readable: .mesh .meshb .msh)");
}

int mesh_file_dimension(const std::string& path) {
  std::string extension = file_extension(path);
  if (is_gamma_path(path)) return gamma_mesh_dimension(path);
  if (extension == ".msh") return gmsh_msh_dimension(path);
  throw Error(path + ": unknown mesh format '" + extension + "' (readable: .mesh .meshb .msh)");
}

void check_writable_mesh_format(const std::string& path) {
  const std::string extension = file_extension(path);
  if (extension != ".mesh" && extension != ".meshb" && extension != ".msh" && extension != ".vtu")
    throw Error(path + ": unknown mesh format '" + extension + "' (writable: .mesh .meshb .msh .vtu)");
}

template <int D>
void write_mesh_file(const std::string& path, const Mesh<D>& mesh, const MeshWriteOptions& options) {
  check_writable_mesh_format(path);
  // A removed vertex, facet or line (or a hole in the edge ids) would be written as if it were there.
  if (!mesh.is_compact()) throw Error("internal error: " + path + ": the mesh holds removed entities; compact it before writing");
  const std::string extension = file_extension(path);
  if (extension == ".mesh") return write_gamma_mesh(path, mesh, false, 2);
  if (extension == ".meshb") return write_gamma_mesh(path, mesh, true, options.gamma_version);
  if (extension == ".msh") return write_gmsh_msh(path, mesh);
  write_vtu(path, mesh);  // the last writable format
}

template void write_mesh_file(const std::string&, const Mesh<2>&, const MeshWriteOptions&);
template void write_mesh_file(const std::string&, const Mesh<3>&, const MeshWriteOptions&);

}  // namespace hocav
