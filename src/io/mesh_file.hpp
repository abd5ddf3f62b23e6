// Reading and writing meshes, dispatched on the file extension:
//   .mesh / .meshb  Gamma (Medit) ASCII / binary      read + write
//   .msh            Gmsh 4.1 ASCII                      read + write
//   .vtu            VTK XML unstructured grid           write only (see vtu_file.hpp for data)
//
// File node numbering. A file lists "nodes" (Gamma: Vertices; Gmsh: Nodes) that are both element
// corners and P2 mid-edge nodes. Mesh<D> keeps corners as vertices and mid nodes on edges, so a
// reader reports where each of them came from in the file, and every writer numbers the file's
// nodes as: the mesh's vertices 0..nv-1, then (P2) the node of edge e as nv + e. Per-node data such
// as a metric is carried with these maps.
#pragma once

#include <string>
#include <variant>
#include <vector>

#include "mesh/mesh.hpp"

namespace hocav {

using AnyMesh = std::variant<Mesh<2>, Mesh<3>>;

inline int dimension_of(const AnyMesh& mesh) { return std::holds_alternative<Mesh<2>>(mesh) ? 2 : 3; }

struct MeshFileContent {
  AnyMesh mesh;
  // The 0-based position in the file's node list of each mesh vertex, and of each edge's P2 node
  // (empty for a P1 mesh).
  std::vector<Index> vertex_file_ids;
  std::vector<Index> edge_node_file_ids;
  Index file_node_count = 0;
};

// Reads any supported mesh file. The mesh comes back with its topology built (and its edge table
// when P2). Throws Error with "<file>: <keyword>: <what>, line/entity N" on any malformed input.
MeshFileContent read_mesh_file(const std::string& path);

struct MeshWriteOptions {
  // Gamma binary version: 0 picks 3, or 4 when counts need 64 bits. ASCII .mesh is version 2.
  int gamma_version = 0;
};

// Throws Error unless the extension of `path` names a format hocav writes (for commands that check
// their outputs before the work).
void check_writable_mesh_format(const std::string& path);

// Writes a mesh; the format follows the extension. Writes to a temporary name, then renames.
template <int D>
void write_mesh_file(const std::string& path, const Mesh<D>& mesh, const MeshWriteOptions& options = {});

// The dimension a mesh file declares, without reading it all (for commands that must choose D).
int mesh_file_dimension(const std::string& path);

// The file's lower-case extension including the dot (".meshb"), or "" when there is none.
std::string file_extension(const std::string& path);

// Whether `path` names a Gamma file (.mesh or .meshb), which a distributed mesh can be written to in runs.
bool is_gamma_path(const std::string& path);

}  // namespace hocav
