// Gamma/Medit meshes: .mesh (ASCII) and .meshb (binary, versions 1-4). Keywords and layouts are in
// docs/formats.md, "Gamma / Medit"; P2 node order follows the *P2Ordering keywords when present.
#pragma once

#include <string>
#include <vector>

#include "io/mesh_file.hpp"
#include "io/record_run.hpp"

namespace hocav {

// Reads .mesh or .meshb (chosen by content for binary: the endianness code). Unknown keywords are
// skipped with a warning on stderr.
MeshFileContent read_gamma_mesh(const std::string& path);

// Writes .mesh (version 2) or .meshb (version: 0 = 3, or 4 when counts need 64 bits; 1-4 forced).
template <int D>
void write_gamma_mesh(const std::string& path, const Mesh<D>& mesh, bool binary, int version = 0);

// One slice of a P1 Gamma mesh, for reading a file in pieces (docs/distributed.md §Reading in
// pieces): its vertices, elements and facets cut into `count` runs of consecutive records of
// nearly equal length, run `index` of each; the feature lines (3D Edges) and the tag lists whole.
// Entities by 0-based file ids. A binary file's other runs are passed over by seeking, a text
// file's read and dropped: the slice holds only its runs.
template <int D>
struct GammaMeshSlice {
  Index vertex_count = 0, element_count = 0, facet_count = 0;  // the file's
  Index first_vertex = 0, first_element = 0, first_facet = 0;  // the file ids of the runs' first entities
  std::vector<Vec<D>> points;
  std::vector<int> point_refs;
  std::vector<typename Mesh<D>::Element> elements;
  std::vector<int> element_refs;
  std::vector<typename Mesh<D>::Facet> facets;
  std::vector<int> facet_refs;
  std::vector<typename Mesh<D>::Line> lines;  // 3D: every one of the file
  std::vector<int> line_refs;
  // Corners, RequiredVertices: file vertex ids; Ridges, RequiredEdges: ids of Edges entities (the
  // facets in 2D, the lines in 3D); RequiredTriangles: ids of 3D facets.
  std::vector<Index> corners, ridges, required_vertices, required_edges, required_triangles;
};

// Throws Error on a file of another Dimension, with P2 entities, with an entity whose vertex is out
// of range, or with an element of the run that repeats a vertex (naming the file, the keyword and
// the entity, as read_gamma_mesh does).
template <int D>
GammaMeshSlice<D> read_gamma_mesh_slice(const std::string& path, int index, int count);

// The Dimension a .mesh/.meshb file declares.
int gamma_mesh_dimension(const std::string& path);

// Whether a .mesh/.meshb file has a P2 element or facet keyword (a .meshb's records are skipped, a
// .mesh's read through): a file read_gamma_mesh_slice refuses.
bool gamma_mesh_has_p2_keyword(const std::string& path);

}  // namespace hocav
