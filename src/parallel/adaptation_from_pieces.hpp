// The set-up of a distributed adaptation that starts from pieces of its input (docs/distributed.md
// §Adapting from pieces): every process reads its piece of the mesh file and its run of the metric
// file's rows, and what set_up_adaptation makes of the whole input (the corners and feature lines,
// the size floor, the memory check, the loop's settings) is made of the pieces together. No process
// holds the whole mesh.
#pragma once

#include <array>
#include <memory>
#include <optional>
#include <string>

#include "adapt/adaptation_driver.hpp"
#include "metric/hessian_source.hpp"
#include "parallel/distributed_adaptation.hpp"
#include "parallel/mesh_file_pieces.hpp"

namespace hocav {

// What a process adapts its piece with: its start (the metric's fields made on the piece, used,
// and dropped), the geometry of the input's boundary (null for none), the loop's settings.
template <int D>
struct PieceSetup {
  PiecesStart<D> start;
  std::unique_ptr<BoundaryGeometry<D>> geometry;
  AdaptationSettings settings;
  Index hausdorff_bounded_vertices = 0;  // the whole mesh's vertices whose metric the Hausdorff bound made finer
};

// Where a run from pieces takes its metric: a metric file (`metric_path`: a metric or mmg's sizes per
// file vertex, each row checked by the process that reads it), or else the Lp metric of a field's
// Hessian (`hessian`: hessian_metric_by_runs), or else the surface metric of `hocav adapt
// --surface-sizes HN,HT` (its interior size `h_max`, or else the whole mesh's bounding-box
// diagonal), or else the job's analytic metric, or else the input's implied metric.
struct PieceMetricSource {
  std::string metric_path;
  std::optional<HessianSource> hessian;
  std::optional<std::array<double, 2>> surface_sizes;
  std::optional<double> h_max;
};

// Every process at once, with its piece of the mesh at `input` (read and prepared:
// piece_input_check.hpp) and its metric's `source`. `job` as `hocav adapt` makes it; its geometry is made of the whole
// boundary, which every process gathers (boundary_of_parts); the Hausdorff bound and the gradation
// are graded across the pieces (grade_piece_metrics), not the serial metric to the last bits. Its
// warnings, said once (give `warn` on rank 0 only), are the serial run's. Throws Error as the
// serial set-up does (a metric asking for more than the memory holds).
template <int D>
PieceSetup<D> set_up_piece(MeshFilePiece<D> piece, const std::string& input, const PieceMetricSource& source, const AdaptationJob<D>& job);

}  // namespace hocav
