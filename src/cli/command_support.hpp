// What the commands share: the dimension of a mesh read from a file, the metric (or scalar field)
// that goes with a mesh file (checked and renumbered to hocav's node order), the curving run of
// `hocav curve` and its .vtu (also run by `hocav demo`), and a one-line mesh summary.
#pragma once

#include <algorithm>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include "geom/sym_mat.hpp"
#include "io/mesh_file.hpp"
#include "io/solution_file.hpp"
#include "io/vtu_file.hpp"
#include "metric/metric_field.hpp"
#include "report/curving_report.hpp"
#include "surface/boundary_geometry.hpp"

namespace hocav {

// The default of --threads: every core the machine has.
inline int every_core() { return static_cast<int>(std::max(1u, std::thread::hardware_concurrency())); }

inline int dimension_of(const AnyMesh& mesh) { return std::holds_alternative<Mesh<2>>(mesh) ? 2 : 3; }

// Reads the metric file given with a mesh file and checks it against that file (a symmetric matrix
// per file node, finite and positive definite). Returns its rows in the node order every writer
// uses: the mesh's vertices, then, when with_edge_nodes (a P2 mesh read as P2), each edge's node.
SolutionField read_metric_for_mesh(const std::string& metric_path, const MeshFileContent& mesh_file, bool with_edge_nodes);

// The scalar field of a solution file given with a mesh file (the first scalar field, one finite
// value per file node), at the mesh's vertices.
std::vector<double> read_scalar_for_mesh(const std::string& solution_path, const MeshFileContent& mesh_file);

// Metric rows in .sol order and the matrices they hold, both ways.
template <int D>
std::vector<SymMat<D>> metrics_of_rows(const SolutionField& rows);
template <int D>
SolutionField rows_of_metrics(const std::vector<SymMat<D>>& metrics);

// Metric rows (SolutionField, .sol order) as a ParaView tensor field (9 components, row-major; the
// z row and column are 0 in 2D).
template <int D>
VtuField metric_tensor_field(const SolutionField& metric);

// Per element: "min_normalized_jacobian" (min of J / |J_straight|) and "scaled_jacobian" (min J /
// max J, gmsh's measure), refined bounds, for the .vtu cell data.
template <int D>
std::vector<VtuField> jacobian_cell_fields(const Mesh<D>& mesh);

// Refuses an input mesh that `hocav stats` calls inconsistent, naming its first problem, and warns on
// stderr of the defects curving works around (open boundary, non-manifold parts, overlaps).
template <int D>
void check_input_mesh(const Mesh<D>& mesh, const std::string& path);

// The options of a curving run (`hocav curve`).
struct CurvingSettings {
  std::string surface = "p3";  // boundary curvature: p3, cad:FILE or none
  std::string quadrature = "simpson";
  double jacobian_floor = 0.01;
  int passes = 1;
  int threads = 1;
  bool progress = false;  // a progress line on stderr, if a terminal, for meshes large enough to wait for
};

// The geometry of `--surface`: none (nullptr), p3 (the P3 surrogate of the mesh's boundary) or
// cad:FILE (a STEP or BREP model).
template <int D>
std::unique_ptr<BoundaryGeometry<D>> boundary_geometry(const std::string& surface, const Mesh<D>& mesh);

// The paper's algorithm on `mesh` (P1 or P2; its P1 copy is the field's back mesh): boundary
// curvature proposed from `settings.surface`, every volume vertex reinserted with the P2 cavity
// operator, the result checked consistent and measured.
template <int D>
CurvingReport curve_in_metric(Mesh<D>& mesh, const MetricField<D>& field, const CurvingSettings& settings);

// The curved mesh as a .vtu for ParaView: the metric at every node and jacobian_cell_fields.
template <int D>
void write_curved_vtu(const std::string& path, const Mesh<D>& mesh, const MetricField<D>& field);

// "2D P1: 356 vertices, 605 triangles, 95 boundary edges"
template <int D>
std::string mesh_summary(const Mesh<D>& mesh);

}  // namespace hocav
