#include "report/curving_report.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>
#include <ostream>
#include <utility>

#include "base/thread_pool.hpp"
#include "curve/edge_optimizer.hpp"
#include "geom/sym_eigen.hpp"
#include "mesh/boundary_vertices.hpp"
#include "report/json_writer.hpp"

namespace hocav {

namespace {

// Vertex v of `mesh` with its metric, and a back element near it to start the field's searches
// from: the back mesh's own vertex v when the mesh keeps it where it was (`hocav curve`'s output keeps
// the input's vertices), else the field sampled there (the curved passes of `adapt --curved`
// renumber the vertices of the mesh the field was made on).
template <int D>
std::pair<EdgeEndpoint<D>, Index> endpoint_in_field(const Mesh<D>& mesh, const MetricField<D>& field, Index v) {
  const Mesh<D>& back = field.back_mesh();
  if (v < back.vertex_count() && back.vertex(v) == mesh.vertex(v))
    return {edge_endpoint(mesh.vertex(v), field.vertex_log_metric(v)), back.vertex_element(v)};
  const auto sample = field.sample(mesh.vertex(v));
  return {edge_endpoint(mesh.vertex(v), sample.log_metric), sample.where.element};
}

}  // namespace

template <int D>
EdgeGain edge_gain(const Mesh<D>& mesh, const MetricField<D>& field, Index e) {
  const auto [a, b] = mesh.edge_vertices(e);
  const Vec<D> straight = 0.5 * (mesh.vertex(a) + mesh.vertex(b));
  // A straight edge (most of them) gains nothing: no length to compute.
  if (mesh.edge_node(e) == straight) return {};
  const auto [end_a, hint] = endpoint_in_field(mesh, field, a);
  const EdgeEndpoint<D> end_b = endpoint_in_field(mesh, field, b).first;
  const auto straight_sample = field.sample(straight, hint), curved_sample = field.sample(mesh.edge_node(e), hint);
  const double straight_length = high_precision_edge_length(end_a, end_b, straight, straight_sample.log_metric);
  const double curved_length = high_precision_edge_length(end_a, end_b, mesh.edge_node(e), curved_sample.log_metric);
  return {1 - curved_length / straight_length, straight_sample.where.inside && curved_sample.where.inside};
}

template <int D>
std::vector<double> volume_edge_gains(const Mesh<D>& mesh, const MetricField<D>& field, int threads) {
  const std::vector<bool> on_boundary = boundary_vertex_flags(mesh);
  // Per edge whether it is measured and its gain; then the measured ones in order.
  const auto edge_count = static_cast<std::size_t>(mesh.edge_count());
  std::vector<char> measured(edge_count, 0);
  std::vector<double> per_edge(edge_count, 0);
  ThreadPool pool(std::max(1, threads));
  run_chunked(pool, edge_count, kMeasuredChunk, [&](std::size_t begin, std::size_t end) {
    for (auto e = static_cast<Index>(begin); e < static_cast<Index>(end); ++e) {
      auto [a, b] = mesh.edge_vertices(e);
      measured[e] = a != kNoIndex && !(on_boundary[a] && on_boundary[b]);
      if (measured[e]) per_edge[e] = edge_gain(mesh, field, e).value;
    }
  });
  std::vector<double> gains;
  for (std::size_t e = 0; e < edge_count; ++e)
    if (measured[e]) gains.push_back(per_edge[e]);
  return gains;
}

template <int D>
CurvingReport make_curving_report(const Mesh<D>& mesh, const MetricField<D>& field, Index points_before, const ReinsertionResult& result,
                                  Index boundary_proposals_left, int threads) {
  CurvingReport report = curving_run_report(field, points_before, result, boundary_proposals_left);
  measure_curved_output(report, mesh, field, threads);
  return report;
}

template <int D>
double anisotropy_of(const SymMat<D>& log_metric) {
  const auto eigen = sym_eigen(log_metric);
  // Sizes are e^(−θ/2): their ratio is e^((θmax − θmin)/2).
  return std::exp(0.5 * (eigen.values[D - 1] - eigen.values[0]));
}

template <int D>
CurvingReport curving_run_report(double max_anisotropy, Index points_before, const ReinsertionResult& result,
                                 Index boundary_proposals_left) {
  CurvingReport report;
  report.dimension = D;
  report.points_before = points_before;
  report.seconds = result.seconds;
  report.counters = result.counters;
  report.edges_optimized_per_second = result.seconds > 0 ? static_cast<double>(result.counters.edges_optimized) / result.seconds : 0;
  report.boundary_proposals_left = boundary_proposals_left;
  report.max_anisotropy = max_anisotropy;
  return report;
}

template <int D>
CurvingReport curving_run_report(const MetricField<D>& field, Index points_before, const ReinsertionResult& result,
                                 Index boundary_proposals_left) {
  double largest = 0;
  for (Index v = 0; v < field.back_mesh().vertex_count(); ++v) largest = std::max(largest, anisotropy_of(field.vertex_log_metric(v)));
  return curving_run_report<D>(largest, points_before, result, boundary_proposals_left);
}

template <int D>
void measure_curved_output(CurvingReport& report, const Mesh<D>& mesh, const MetricField<D>& field, int threads) {
  summarize_curved_output(report, mesh, mesh_jacobian_quality(mesh, kReportedRefinement, threads), volume_edge_gains(mesh, field, threads));
}

template <int D>
void summarize_curved_output(CurvingReport& report, const Mesh<D>& mesh, std::span<const JacobianQuality> elements,
                             std::span<const double> gains) {
  report.elements = mesh.element_count();
  report.points_after = mesh.vertex_count() + mesh.edge_count();
  auto summary = summarize_jacobian_quality(elements);
  report.normalized_jacobian = summary.min_normalized_jacobian;
  report.scaled_jacobian = summary.scaled_jacobian;
  report.average_gain = report.max_gain = 0;
  if (!gains.empty()) {
    report.average_gain = std::accumulate(gains.begin(), gains.end(), 0.0) / static_cast<double>(gains.size());
    report.max_gain = std::max(0.0, *std::max_element(gains.begin(), gains.end()));
  }
}

namespace {

void write_summary(JsonWriter& json, std::string_view name, const ValueSummary& summary) {
  json.key(name).begin_object();
  json.member("min", summary.min).member("avg", summary.average).member("max", summary.max);
  json.member("invalid", summary.invalid_count);
  json.end_object();
}

}  // namespace

void write_curving_report_json(std::ostream& out, const CurvingReport& report) {
  JsonWriter json(out);
  write_curving_report_object(json, report);
  out << '\n';
}

void write_curving_report_object(JsonWriter& json, const CurvingReport& report) {
  json.begin_object();
  json.member("dimension", report.dimension);
  json.member("elements", report.elements);
  json.member("points_before", report.points_before);
  json.member("points_after", report.points_after);
  json.member("max_anisotropy", report.max_anisotropy);
  json.member("edges_optimized_per_second", report.edges_optimized_per_second);
  json.member("seconds_without_io", report.seconds);
  json.member("threads", report.threads);
  write_summary(json, "normalized_jacobian", report.normalized_jacobian);
  write_summary(json, "scaled_jacobian", report.scaled_jacobian);
  json.member("average_gain", report.average_gain);
  json.member("max_gain", report.max_gain);
  json.member("boundary_proposals_left", report.boundary_proposals_left);
  const ProposalCompletion& b = report.boundary_completion;
  json.key("boundary_completion").begin_object();
  json.member("placed", b.placed).member("already_placed", b.already_placed);
  json.member("pulled_back", b.pulled_back).member("blocked", b.blocked).member("absent", b.absent);
  json.member("bends", b.bends).member("volume_nodes_bent", b.volume_nodes_bent);
  json.member("largest_gap", b.largest_gap).member("elements_certified", b.elements_certified);
  json.member("sweeps", b.sweeps).member("seconds", b.seconds);
  json.end_object();
  const P2CavityCounters& c = report.counters;
  json.key("cavities").begin_object();
  json.member("tried", c.cavities).member("accepted", c.accepted);
  json.member("rejected_topology", c.rejected_topology).member("rejected_curving", c.rejected_curving);
  json.member("edges_optimized", c.edges_optimized).member("optimizer_iterations", c.optimizer_iterations);
  json.member("edges_kept_optimal", c.edges_kept_optimal);
  json.member("boundary_nodes_applied", c.boundary_nodes_applied).member("corrections", c.corrections);
  json.member("elements_certified", c.elements_certified).member("certificates_kept", c.certificates_kept);
  json.end_object();
  json.key("seconds_per_phase").begin_object();
  json.member("plan", c.seconds_plan).member("optimize", c.seconds_optimize);
  json.member("certify", c.seconds_certify).member("commit", c.seconds_commit);
  json.end_object();
  json.end_object();
}

void write_curving_report_table(std::ostream& out, const CurvingReport& report) {
  char line[160];
  auto row = [&](const char* name, const char* format, auto... values) {
    std::snprintf(line, sizeof line, format, values...);
    out << "  " << name << std::string(std::max<std::size_t>(1, 32 - std::string_view(name).size()), ' ') << line << '\n';
  };
  row(report.dimension == 3 ? "tetrahedra" : "triangles", "%d", report.elements);
  row("points before / after", "%d / %d", report.points_before, report.points_after);
  row("max anisotropy", "%.3g", report.max_anisotropy);
  row("edges optimized per second", "%.0f", report.edges_optimized_per_second);
  row("time without I/O", "%.3f s", report.seconds);
  row("normalized Jacobian min/avg/max", "%.3g / %.3g / %.3g", report.normalized_jacobian.min, report.normalized_jacobian.average,
      report.normalized_jacobian.max);
  row("scaled Jacobian min", "%.3g", report.scaled_jacobian.min);
  row("gain avg / max", "%.2f%% / %.1f%%", 100 * report.average_gain, 100 * report.max_gain);
  row("cavities accepted / tried", "%lld / %lld", report.counters.accepted, report.counters.cavities);
  row("rejected (topology / curving)", "%lld / %lld", report.counters.rejected_topology, report.counters.rejected_curving);
  row("edges optimized / kept optimal", "%lld / %lld", report.counters.edges_optimized, report.counters.edges_kept_optimal);
  row("elements certified / kept", "%lld / %lld", report.counters.elements_certified, report.counters.certificates_kept);
  row("corrections", "%lld", report.counters.corrections);
  row("boundary nodes applied / left", "%lld / %d", report.counters.boundary_nodes_applied, report.boundary_proposals_left);
  const ProposalCompletion& b = report.boundary_completion;
  row("  placed by the last pass", "%d (+%d already there)", b.placed, b.already_placed);
  row("  layers bent / their nodes", "%d / %d", b.bends, b.volume_nodes_bent);
  row("  left: pulled back / blocked", "%d / %d (largest gap %.2g)", b.pulled_back, b.blocked, b.largest_gap);
}

template std::vector<double> volume_edge_gains(const Mesh<2>&, const MetricField<2>&, int);
template std::vector<double> volume_edge_gains(const Mesh<3>&, const MetricField<3>&, int);
template EdgeGain edge_gain(const Mesh<2>&, const MetricField<2>&, Index);
template EdgeGain edge_gain(const Mesh<3>&, const MetricField<3>&, Index);
template void summarize_curved_output(CurvingReport&, const Mesh<2>&, std::span<const JacobianQuality>, std::span<const double>);
template void summarize_curved_output(CurvingReport&, const Mesh<3>&, std::span<const JacobianQuality>, std::span<const double>);
template double anisotropy_of(const SymMat<2>&);
template double anisotropy_of(const SymMat<3>&);
template CurvingReport curving_run_report<2>(double, Index, const ReinsertionResult&, Index);
template CurvingReport curving_run_report<3>(double, Index, const ReinsertionResult&, Index);
template CurvingReport curving_run_report(const MetricField<2>&, Index, const ReinsertionResult&, Index);
template CurvingReport curving_run_report(const MetricField<3>&, Index, const ReinsertionResult&, Index);
template void measure_curved_output(CurvingReport&, const Mesh<2>&, const MetricField<2>&, int);
template void measure_curved_output(CurvingReport&, const Mesh<3>&, const MetricField<3>&, int);
template CurvingReport make_curving_report(const Mesh<2>&, const MetricField<2>&, Index, const ReinsertionResult&, Index, int);
template CurvingReport make_curving_report(const Mesh<3>&, const MetricField<3>&, Index, const ReinsertionResult&, Index, int);

}  // namespace hocav
