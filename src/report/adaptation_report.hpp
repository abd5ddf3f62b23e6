// The figures of an adaptation run (`hocav adapt --report`): the operations of every pass, the
// adapted P1 mesh's edge lengths and element qualities in the metric, times, peak memory, and the
// Table-1 figures of the curving that follows it.
#pragma once

#include <iosfwd>
#include <optional>

#include "adapt/adaptation_loop.hpp"
#include "report/curving_report.hpp"
#include "report/mesh_statistics.hpp"

namespace hocav {

struct QualitySummary {
  double min = 0, mean = 0;
  double share_below_0_1 = 0;  // of the elements
};

struct AdaptationReport {
  int dimension = 3;
  Index input_vertices = 0, input_elements = 0;
  Index output_vertices = 0, output_elements = 0;
  AdaptationRun run;
  MetricStatistics lengths;  // of the adapted P1 mesh, 16-point Gauss
  QualitySummary quality;    // metric mean ratio of the adapted P1 mesh, mean vertex metric per element
  double seconds_adapt = 0, seconds_curve = 0;
  long long peak_memory_bytes = 0;
  std::optional<CurvingReport> curving;
};

// The metric mean ratio of every element of a P1 mesh (metrics at its vertices, .sol order rows).
template <int D>
QualitySummary metric_quality_summary(const Mesh<D>& mesh, std::span<const double> vertex_metrics);

void write_adaptation_report_json(std::ostream& out, const AdaptationReport& report);
void write_adaptation_report_table(std::ostream& out, const AdaptationReport& report);

}  // namespace hocav
