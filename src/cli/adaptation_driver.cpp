#include "cli/adaptation_driver.hpp"

#include <sys/resource.h>

#include <chrono>

namespace hocav {
namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

long long peak_memory_bytes() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<long long>(usage.ru_maxrss) * 1024;
}

template <int D>
std::vector<SymMat<D>> metrics_at_vertices(const Mesh<D>& mesh, const AdaptationMetric<D>& metric) {
  std::vector<SymMat<D>> metrics;
  Index hint = kNoIndex;
  for (const auto& x : mesh.vertices()) metrics.push_back(metric.metric_at(x, hint));
  return metrics;
}

}  // namespace

template <int D>
AdaptedMesh<D> adapt_and_curve(Mesh<D>& mesh, const AdaptationMetric<D>& metric, const BoundaryGeometry<D>* geometry,
                               const AdaptationSettings& settings, const std::optional<CurvingSettings>& curving) {
  AdaptedMesh<D> out;
  AdaptationReport& report = out.report;
  report.dimension = D;
  report.input_vertices = mesh.vertex_count();
  report.input_elements = mesh.element_count();
  auto start = std::chrono::steady_clock::now();
  report.run = adapt_to_metric(mesh, metric, geometry, settings);
  report.seconds_adapt = seconds_since(start);
  report.output_vertices = mesh.vertex_count();
  report.output_elements = mesh.element_count();

  const std::vector<SymMat<D>> metrics = metrics_at_vertices(mesh, metric);
  Mesh<D> copy = mesh;  // the statistics build an edge table
  report.measures = *compute_mesh_statistics(copy, rows_of_metrics(metrics).values).metric;
  out.field = std::make_unique<MetricField<D>>(mesh, metrics);
  if (curving) {
    start = std::chrono::steady_clock::now();
    report.curving = curve_in_metric(mesh, *out.field, *curving);
    report.seconds_curve = seconds_since(start);
  }
  report.peak_memory_bytes = peak_memory_bytes();
  return out;
}

template AdaptedMesh<2> adapt_and_curve(Mesh<2>&, const AdaptationMetric<2>&, const BoundaryGeometry<2>*, const AdaptationSettings&,
                                        const std::optional<CurvingSettings>&);
template AdaptedMesh<3> adapt_and_curve(Mesh<3>&, const AdaptationMetric<3>&, const BoundaryGeometry<3>*, const AdaptationSettings&,
                                        const std::optional<CurvingSettings>&);

}  // namespace hocav
