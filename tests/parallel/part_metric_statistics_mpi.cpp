// The output's figures measured in parts (distributed_metric_statistics, docs/distributed.md §The
// end in the parts), run by ctest under `mpirun -np N` (N = 2, 3, 4). Rank
// 0 holds a square and a cube with four materials and tags, as they are and with their vertices
// renumbered, and every process takes the metric at its vertices from one analytic field (the same
// value wherever a vertex lies). All on rank 0, and scattered element by element so that parts touch
// at many vertices and edges, the figures must be compute_metric_statistics's of the whole mesh: the
// counts, histograms and extremes exactly, the means to rounding (their sums run in another order).
// Exit code 0 when all holds on every process, 1 otherwise.
#include <cmath>
#include <iostream>
#include <string>

#include "cases/structured.hpp"
#include "io/node_metrics.hpp"
#include "metric/analytic_metric.hpp"
#include "mpi_test_main.hpp"
#include "parallel/communicator.hpp"
#include "parallel/part_metric_statistics.hpp"
#include "tagged_meshes.hpp"

namespace hocav {
namespace {

bool fail(const std::string& what) {
  std::cerr << "part metric statistics (rank " << process_rank() << "): " << what << '\n';
  return false;
}

// Anisotropic and varying: sizes from 0.02 to 0.3 across y (the mesh's elements are about 0.1-0.2),
// so the edges fill every bin of lengths.
AnalyticMetricSpec field() {
  AnalyticMetricSpec spec;
  spec.name = "linear";
  spec.axis = 1;
  spec.h_min = 0.02;
  spec.h_max = 0.3;
  spec.center = 0.3;
  return spec;
}

template <int D>
std::vector<double> metric_rows(const Mesh<D>& mesh) {
  return rows_of_metrics(analytic_metric_at_vertices(field(), mesh)).values;
}

bool close(double a, double b) { return std::abs(a - b) <= 1e-12 * std::max(1.0, std::abs(b)); }

// The figures of the parts against the whole mesh's (rank 0 compares).
template <int D>
bool same_figures(const Mesh<D>& mesh, int (*destination)(Index), const std::string& name) {
  const MeshPart<D> part = scattered(mesh, destination);
  const MetricStatistics parts = distributed_metric_statistics(part, metric_rows(part.mesh), 2);
  if (process_rank() != 0) return true;
  const MetricStatistics whole = compute_metric_statistics(mesh, metric_rows(mesh), 1);
  bool ok = true;
  if (parts.edge_count != whole.edge_count || parts.histogram != whole.histogram)
    ok = fail(name + ": " + std::to_string(parts.edge_count) + " edges measured, the whole mesh has " + std::to_string(whole.edge_count));
  if (parts.quality_histogram != whole.quality_histogram) ok = fail(name + ": the qualities' histogram differs");
  if (parts.min != whole.min || parts.max != whole.max || parts.quality_min != whole.quality_min ||
      parts.max_anisotropy != whole.max_anisotropy || parts.unit_share != whole.unit_share ||
      parts.low_quality_share != whole.low_quality_share)
    ok = fail(name + ": the extremes or shares differ");
  if (!close(parts.mean, whole.mean) || !close(parts.quality_mean, whole.quality_mean))
    ok = fail(name + ": the means differ beyond rounding");
  const std::size_t filled = std::count_if(whole.histogram.begin(), whole.histogram.end(), [](Index n) { return n > 0; });
  if (filled < 4) ok = fail(name + ": the lengths fill only " + std::to_string(filled) + " bins (a weak check)");
  return ok;
}

template <int D>
bool check(const Mesh<D>& mesh, const std::string& name) {
  return same_figures(mesh, to_rank_0, name + " on rank 0") & same_figures(mesh, spread, name + " spread");
}

}  // namespace
}  // namespace hocav

int main(int argc, char** argv) {
  return hocav::run_mpi_test(argc, argv, "part metric statistics", [] {
    const hocav::Mesh<2> square = hocav::tagged_mesh(hocav::generate_square(12));
    const hocav::Mesh<3> cube = hocav::tagged_mesh(hocav::generate_cube(6));
    return hocav::check(square, "square") & hocav::check(hocav::shuffled(square), "shuffled square") & hocav::check(cube, "cube") &
           hocav::check(hocav::shuffled(cube), "shuffled cube");
  });
}
