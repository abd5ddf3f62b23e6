// The figures of an adaptation run (`hocav adapt --report`): the operations of every pass, the
// adapted P1 mesh's edge lengths and element qualities in the metric, times, peak memory, and the
// Table-1 figures of the curving that follows it.
#pragma once

#include <iosfwd>
#include <optional>
#include <string>

#include "adapt/adaptation_loop.hpp"
#include "adapt/boundary_settling.hpp"
#include "adapt/curved_adaptation.hpp"
#include "parallel/distributed_iteration.hpp"
#include "report/curving_report.hpp"
#include "report/mesh_statistics.hpp"

namespace hocav {

struct AdaptationReport {
  int dimension = 3;
  Index input_vertices = 0, input_elements = 0;
  Index output_vertices = 0, output_elements = 0;
  // The input's vertices whose metric the Hausdorff bound (--hausd) made finer before the loop.
  Index hausdorff_bounded_vertices = 0;
  AdaptationRun run;
  // With a geometry: the boundary vertices the loop left off it, moved onto it after the loop.
  std::optional<BoundarySettling> settling;
  // The adapted P1 mesh in its metric (`hocav stats --metric`'s figures): edge lengths by 16-point
  // Gauss, element qualities with the metric at the centroid.
  MetricStatistics measures;
  double seconds_adapt = 0, seconds_curve = 0;
  long long peak_memory_bytes = 0;
  std::optional<CurvingReport> curving;              // with --curved, measured after the curved passes
  std::optional<CurvedAdaptationRun> curved_passes;  // `adapt --curved` (docs/adaptation.md §Curved passes)
  // With curving: the output's curved edge lengths and curved quality in the metric.
  std::optional<CurvedMeasures> curved_measures;
  // Under mpirun (docs/distributed.md): each iteration of the distributed loop, and whether every
  // process read its piece of the input (§Adapting from pieces) rather than rank 0 the whole.
  std::vector<DistributedIteration> distributed_iterations;
  bool input_read_in_pieces = false;
};

void write_adaptation_report_json(std::ostream& out, const AdaptationReport& report);
// "" when the loop converged; else why the user should look: "not converged after N passes (the last
// split ... and collapsed ... edges; X% of edges unit); raise --iterations, or check ...".
std::string non_convergence_summary(const AdaptationReport& report);
void write_adaptation_report_table(std::ostream& out, const AdaptationReport& report);

}  // namespace hocav
