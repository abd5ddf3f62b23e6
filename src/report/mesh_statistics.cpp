#include "report/mesh_statistics.hpp"

#include <algorithm>
#include <cstdio>
#include <iomanip>
#include <limits>
#include <map>
#include <sstream>

#include "base/error.hpp"
#include "base/thread_pool.hpp"
#include "bezier/mesh_quality.hpp"
#include "curve/edge_length.hpp"
#include "geom/sym_functions.hpp"
#include "mesh/consistency.hpp"
#include "mesh/measure.hpp"
#include "mesh/vertex_graph.hpp"
#include "metric/metric_quality.hpp"
#include "report/json_writer.hpp"

namespace hocav {
namespace {

template <class RefOf>
std::vector<RefCount> count_refs(Index count, RefOf ref_of) {
  std::map<int, Index> counts;
  for (Index i = 0; i < count; ++i) ++counts[ref_of(i)];
  std::vector<RefCount> out;
  for (const auto& [ref, n] : counts) out.push_back({ref, n});
  return out;
}

// Calls value(i) for every i in [0, count) on the pool's threads, in chunks, and returns the
// values in order: the figures are then summed serially, the same for any thread count.
template <typename Value>
std::vector<double> values_on_threads(ThreadPool& pool, std::size_t count, const Value& value) {
  std::vector<double> values(count);
  run_chunked(pool, count, 1024, [&](std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i) values[i] = value(i);
  });
  return values;
}

// The qualities of the straight elements, each in the metric at its centroid.
template <int D>
std::vector<double> element_qualities(const Mesh<D>& mesh, const std::vector<SymMat<D>>& vertex_logs, ThreadPool& pool) {
  return values_on_threads(pool, static_cast<std::size_t>(mesh.element_count()), [&](std::size_t k) {
    SimplexPoints<D> corners;
    std::array<SymMat<D>, D + 1> logs;
    for (int i = 0; i <= D; ++i) {
      const Index v = mesh.element(static_cast<Index>(k))[i];
      corners[static_cast<std::size_t>(i)] = mesh.vertex(v);
      logs[static_cast<std::size_t>(i)] = vertex_logs[static_cast<std::size_t>(v)];
    }
    return centroid_metric_mean_ratio<D>(corners, logs);
  });
}

// The mesh's edges by their ends: the edge table's, in its order, when the mesh has one (a P2 mesh's
// nodes are per edge); else each pair of vertices an element joins, once, ordered by the lower end
// (vertex_graph: about a tenth of an edge table's memory, and with no copy of the mesh to build one
// on; the table was the adaptation's peak when it measured its output).
template <int D>
std::vector<std::array<Index, 2>> edge_ends(const Mesh<D>& mesh) {
  std::vector<std::array<Index, 2>> ends;
  if (mesh.has_edges()) {
    for (Index e = 0; e < mesh.edge_count(); ++e) ends.push_back(mesh.edge_vertices(e));
    return ends;
  }
  const VertexGraph graph = vertex_graph(mesh);
  for (Index v = 0; v < graph.vertex_count(); ++v)
    for (Index n : graph.neighbors_of(v))
      if (n > v) ends.push_back({v, n});
  return ends;
}

template <int D>
MetricValues metric_values(const Mesh<D>& mesh, std::span<const double> node_metrics, ThreadPool& pool) {
  constexpr std::size_t kComponents = SymMat<D>::kEntryCount;
  const auto vertex_count = static_cast<std::size_t>(mesh.vertex_count());
  const std::size_t rows = node_metrics.size() / kComponents;
  const bool with_edge_nodes = mesh.is_p2() && rows == vertex_count + static_cast<std::size_t>(mesh.edge_count());
  if (node_metrics.size() % kComponents != 0 || (rows != vertex_count && !with_edge_nodes))
    throw Error("the metric has " + std::to_string(rows) + " rows for " + std::to_string(vertex_count) + " vertices" +
                (mesh.is_p2() ? " and " + std::to_string(mesh.edge_count()) + " P2 nodes" : ""));
  auto log_metric_of_row = [&node_metrics](std::size_t row) {
    SymMat<D> metric;
    std::copy_n(node_metrics.begin() + static_cast<std::ptrdiff_t>(row * kComponents), kComponents, metric.entries.begin());
    return log_spd(metric);
  };
  MetricValues values;
  std::vector<SymMat<D>> vertex_logs(vertex_count);
  values.anisotropies = values_on_threads(pool, vertex_count, [&](std::size_t v) {
    vertex_logs[v] = log_metric_of_row(v);
    // Sizes are e^{−θ/2} for the eigenvalues θ of log M.
    Vec<D> theta = sym_eigen(vertex_logs[v]).values;
    return std::exp(0.5 * (theta[D - 1] - theta[0]));
  });
  values.qualities = element_qualities(mesh, vertex_logs, pool);
  values.edges = edge_ends(mesh);
  values.lengths = values_on_threads(pool, values.edges.size(), [&](std::size_t i) {
    const auto e = static_cast<Index>(i);  // the edge table's id, when the mesh has one
    const auto [a, b] = values.edges[i];
    const SymMat<D>& log_a = vertex_logs[static_cast<std::size_t>(a)];
    const SymMat<D>& log_b = vertex_logs[static_cast<std::size_t>(b)];
    EdgeLengthFunction<D> edge(mesh.vertex(a), mesh.vertex(b), log_a, log_b, high_precision_rule());
    Vec<D> node = mesh.is_p2() ? mesh.edge_node(e) : 0.5 * (mesh.vertex(a) + mesh.vertex(b));
    SymMat<D> log_node = with_edge_nodes ? log_metric_of_row(vertex_count + i) : 0.5 * (log_a + log_b);
    return edge.length(node, log_node);
  });
  return values;
}

template <int D>
JacobianStatistics jacobian_statistics(const Mesh<D>& mesh, int threads) {
  const std::vector<JacobianQuality> qualities = mesh_jacobian_quality(mesh, kReportedRefinement, threads);
  const MeshJacobianSummary summary = summarize_jacobian_quality(qualities);
  auto figures = [](const ValueSummary& values) {
    JacobianFigures f;
    f.min = values.min;
    f.average = values.average;
    f.max = values.max;
    return f;
  };
  JacobianStatistics s;
  s.min_normalized = figures(summary.min_normalized_jacobian);
  s.scaled = figures(summary.scaled_jacobian);
  s.invalid = summary.min_normalized_jacobian.invalid_count;
  s.straight = !mesh.is_p2();
  for (std::size_t k = 0; k < qualities.size(); ++k) {
    const std::size_t bin = jacobian_bin(qualities[k].min_normalized_jacobian);
    ++s.min_normalized.histogram[bin];
    ++s.scaled.histogram[jacobian_bin(qualities[k].scaled_jacobian)];
    if (bin == 0 && s.first_invalid_element == kNoIndex) s.first_invalid_element = static_cast<Index>(k);
  }
  return s;
}

std::string number(double value) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.6g", value);
  return buffer;
}

std::string bound(double value) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.3g", value);
  return buffer;
}

// "[0.3, 0.5)": bins below the unit bin are closed on the left, those above on the right.
std::string bin_label(std::size_t bin) {
  const auto& bounds = kEdgeLengthBinBounds;
  std::string label(1, bin <= kUnitEdgeBin ? '[' : '(');
  label.append(bin == 0 ? "0" : bound(bounds[bin - 1])).append(", ");
  label.append(bin == bounds.size() ? "inf" : bound(bounds[bin]));
  label.push_back(bin < kUnitEdgeBin || bin == bounds.size() ? ')' : ']');
  return label;
}

// "(-inf, 0]", "(0.01, 0.1]", "(1, inf)".
std::string jacobian_bin_label(std::size_t bin) {
  const auto& bounds = kJacobianBinBounds;
  std::string label("(");
  label.append(bin == 0 ? "-inf" : bound(bounds[bin - 1])).append(", ");
  label.append(bin == bounds.size() ? "inf" : bound(bounds[bin])).push_back(bin == bounds.size() ? ')' : ']');
  return label;
}

std::string percent(double share) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.1f%%", 100 * share);
  return buffer;
}

// "(-inf, 0.1)", "[0.1, 0.3)", "[0.9, 1]".
std::string quality_bin_label(std::size_t bin) {
  const auto& bounds = kQualityBinBounds;
  std::string label(bin == 0 ? "(" : "[");
  label.append(bin == 0 ? "-inf" : bound(bounds[bin - 1])).append(", ");
  label.append(bin == bounds.size() ? "1" : bound(bounds[bin])).push_back(bin == bounds.size() ? ']' : ')');
  return label;
}

// A histogram row of the table: the count and its share of `total`.
std::string count_and_share(Index count, Index total) {
  std::ostringstream text;
  text << std::right << std::setw(10) << count << std::setw(9) << percent(total > 0 ? static_cast<double>(count) / total : 0.0);
  return text.str();
}

std::string refs_text(const std::vector<RefCount>& refs) {
  if (refs.empty()) return "none";
  std::string text;
  for (const RefCount& r : refs) text += (text.empty() ? "" : "  ") + std::to_string(r.ref) + " (" + std::to_string(r.count) + ")";
  return text;
}

std::string memory_text(std::size_t bytes) {
  static constexpr const char* kUnits[] = {"KiB", "MiB", "GiB"};
  double amount = static_cast<double>(bytes) / 1024;
  std::size_t unit = 0;
  for (; unit + 1 < std::size(kUnits) && amount >= 1024; ++unit) amount /= 1024;
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%zu bytes (%.1f %s)", bytes, amount, kUnits[unit]);
  return buffer;
}

// The bounds of a histogram bin in JSON: "from" and "to", null for an infinite end.
void write_bin_bounds(JsonWriter& json, const std::string& label, std::optional<double> from, std::optional<double> to) {
  json.member("bin", label).key("from");
  if (from)
    json.value(*from);
  else
    json.null();
  json.key("to");
  if (to)
    json.value(*to);
  else
    json.null();
}

void write_jacobian_figures_json(JsonWriter& json, std::string_view name, const JacobianFigures& figures) {
  json.key(name).begin_object().member("min", figures.min).member("avg", figures.average).member("max", figures.max);
  json.end_object();
}

void write_refs_json(JsonWriter& json, std::string_view name, const std::vector<RefCount>& refs) {
  json.key(name).begin_array();
  for (const RefCount& r : refs) json.begin_object().member("ref", r.ref).member("count", r.count).end_object();
  json.end_array();
}

void write_quality_json(JsonWriter& json, const MetricStatistics& metric) {
  json.key("quality").begin_object().member("min", metric.quality_min).member("mean", metric.quality_mean);
  json.member("low_share", metric.low_quality_share).member("low_bound", kLowQuality);
  json.key("histogram").begin_array();
  for (std::size_t bin = 0; bin < metric.quality_histogram.size(); ++bin) {
    json.begin_object();
    write_bin_bounds(json, quality_bin_label(bin), bin == 0 ? std::nullopt : std::optional(kQualityBinBounds[bin - 1]),
                     bin < kQualityBinBounds.size() ? std::optional(kQualityBinBounds[bin]) : std::optional(1.0));
    json.member("count", metric.quality_histogram[bin]).end_object();
  }
  json.end_array().end_object();
}

}  // namespace

std::size_t edge_length_bin(double length) {
  std::size_t bin = 0;
  for (std::size_t i = 0; i < kEdgeLengthBinBounds.size(); ++i) {
    double bound = kEdgeLengthBinBounds[i];
    if (i + 1 == kUnitEdgeBin) bound *= 1 - kUnitBinSlack;
    if (i == kUnitEdgeBin) bound *= 1 + kUnitBinSlack;
    if (i < kUnitEdgeBin ? length >= bound : length > bound) bin = i + 1;
  }
  return bin;
}

std::size_t quality_bin(double quality) {
  std::size_t bin = 0;
  for (std::size_t i = 0; i < kQualityBinBounds.size(); ++i)
    if (quality >= kQualityBinBounds[i]) bin = i + 1;
  return bin;
}

std::size_t jacobian_bin(double value) {
  std::size_t bin = 0;
  for (std::size_t i = 0; i < kJacobianBinBounds.size(); ++i) {
    const bool last = i + 1 == kJacobianBinBounds.size();  // the bound 1
    if (value > kJacobianBinBounds[i] * (last ? 1 + kJacobianBinSlack : 1.0)) bin = i + 1;
  }
  return bin;
}

std::string invalidity_summary(const MeshStatistics& s) {
  std::string summary;
  const JacobianStatistics& jacobian = s.jacobian;
  if (jacobian.invalid > 0)
    summary = std::to_string(jacobian.invalid) + (jacobian.invalid == 1 ? " element" : " elements") +
              " with a non-positive Jacobian (first: element " + one_based(jacobian.first_invalid_element) + ")";
  if (!s.consistency_problems.empty())
    summary += (summary.empty() ? "" : "; ") + std::string("consistency: ") + std::to_string(s.consistency_problems.size()) +
               " problems (first: " + s.consistency_problems.front() + ")";
  return summary;
}

template <int D>
MeshStatistics compute_mesh_statistics(Mesh<D>& mesh, std::span<const double> node_metrics, int threads) {
  MeshStatistics s;
  s.memory_bytes = mesh.memory_bytes();
  if (!mesh.has_edges()) mesh.build_edges();
  s.dimension = D;
  s.order = mesh.order();
  s.vertices = mesh.vertex_count();
  s.elements = mesh.element_count();
  s.boundary_facets = mesh.facet_count();
  s.lines = mesh.line_count();
  s.edges = mesh.edge_count();
  s.p2_nodes = mesh.is_p2() ? mesh.edge_count() : 0;
  s.corners = static_cast<Index>(mesh.corners().size());
  s.ridges = static_cast<Index>(mesh.ridges().size());
  s.required_vertices = static_cast<Index>(mesh.required_vertices().size());
  s.element_refs = count_refs(mesh.element_count(), [&mesh](Index k) { return mesh.element_ref(k); });
  s.facet_refs = count_refs(mesh.facet_count(), [&mesh](Index f) { return mesh.facet_ref(f); });

  for (Index k = 0; k < mesh.element_count(); ++k) {
    double measure = element_measure(mesh, k);
    s.min_measure = k == 0 ? measure : std::min(s.min_measure, measure);
    s.max_measure = k == 0 ? measure : std::max(s.max_measure, measure);
    s.total_measure += measure;
    if (!(measure > 0)) ++s.non_positive_elements;
  }
  s.defects = find_mesh_defects(mesh);
  s.open_boundary_faces = s.defects.open_faces;

  ConsistencyOptions options;
  options.require_positive_orientation = !mesh.is_p2();  // a valid curved element may be an inverted P1 one
  s.consistency_problems = check_consistency(mesh, options);
  s.jacobian = jacobian_statistics(mesh, std::max(1, threads));
  if (!node_metrics.empty()) s.metric = compute_metric_statistics(mesh, node_metrics, threads);
  return s;
}

template MeshStatistics compute_mesh_statistics(Mesh<2>&, std::span<const double>, int);
template MeshStatistics compute_mesh_statistics(Mesh<3>&, std::span<const double>, int);

void MetricTally::add_length(double length) {
  ++edges;
  length_min = std::min(length_min, length);
  length_max = std::max(length_max, length);
  length_sum += length;
  ++length_histogram[edge_length_bin(length)];
}

void MetricTally::add_quality(double quality) {
  ++elements;
  quality_min = std::min(quality_min, quality);
  quality_sum += quality;
  ++quality_histogram[quality_bin(quality)];
}

void MetricTally::add(const MetricTally& other) {
  edges += other.edges;
  length_min = std::min(length_min, other.length_min);
  length_max = std::max(length_max, other.length_max);
  length_sum += other.length_sum;
  for (std::size_t i = 0; i < length_histogram.size(); ++i) length_histogram[i] += other.length_histogram[i];
  elements += other.elements;
  quality_min = std::min(quality_min, other.quality_min);
  quality_sum += other.quality_sum;
  for (std::size_t i = 0; i < quality_histogram.size(); ++i) quality_histogram[i] += other.quality_histogram[i];
  max_anisotropy = std::max(max_anisotropy, other.max_anisotropy);
}

MetricStatistics MetricTally::statistics() const {
  MetricStatistics s;
  s.max_anisotropy = max_anisotropy;
  if (elements > 0) {
    s.quality_min = quality_min;
    s.quality_mean = quality_sum / elements;
    s.quality_histogram = quality_histogram;
    s.low_quality_share = static_cast<double>(quality_histogram[0]) / elements;
  }
  s.edge_count = edges;
  if (edges > 0) {
    s.min = length_min;
    s.max = length_max;
    s.mean = length_sum / edges;
    s.histogram = length_histogram;
    s.unit_share = static_cast<double>(length_histogram[kUnitEdgeBin]) / edges;
  }
  return s;
}

template <int D>
MetricValues compute_metric_values(const Mesh<D>& mesh, std::span<const double> node_metrics, int threads) {
  ThreadPool pool(std::max(1, threads));
  return metric_values(mesh, node_metrics, pool);
}

template MetricValues compute_metric_values(const Mesh<2>&, std::span<const double>, int);
template MetricValues compute_metric_values(const Mesh<3>&, std::span<const double>, int);

template <int D>
MetricStatistics compute_metric_statistics(const Mesh<D>& mesh, std::span<const double> node_metrics, int threads) {
  const MetricValues values = compute_metric_values(mesh, node_metrics, threads);
  MetricTally tally;
  for (double anisotropy : values.anisotropies) tally.max_anisotropy = std::max(tally.max_anisotropy, anisotropy);
  for (double quality : values.qualities) tally.add_quality(quality);
  for (double length : values.lengths) tally.add_length(length);
  return tally.statistics();
}

template MetricStatistics compute_metric_statistics(const Mesh<2>&, std::span<const double>, int);
template MetricStatistics compute_metric_statistics(const Mesh<3>&, std::span<const double>, int);

void write_statistics_table(std::ostream& out, const MeshStatistics& s, const std::string& mesh_name, const std::string& metric_name) {
  auto row = [&out](const std::string& label, const std::string& value) { out << std::left << std::setw(22) << label << value << '\n'; };
  const char* measure_name = s.dimension == 2 ? "area" : "volume";
  row("mesh", mesh_name);
  row("dimension", std::to_string(s.dimension));
  row("order", std::string("P").append(std::to_string(s.order)));
  row("vertices", std::to_string(s.vertices));
  row("elements", std::to_string(s.elements) + (s.dimension == 2 ? " triangles" : " tetrahedra"));
  row("boundary facets", std::to_string(s.boundary_facets) + (s.dimension == 2 ? " edges" : " triangles"));
  row("lines", std::to_string(s.lines));
  row("edges", std::to_string(s.edges));
  row("P2 nodes", std::to_string(s.p2_nodes));
  row("corners", std::to_string(s.corners));
  row("ridges", std::to_string(s.ridges));
  row("required vertices", std::to_string(s.required_vertices));
  row("element refs", refs_text(s.element_refs));
  row("facet refs", refs_text(s.facet_refs));
  row(std::string("P1 ") + measure_name,
      "min " + number(s.min_measure) + "  max " + number(s.max_measure) + "  total " + number(s.total_measure));
  row("non-positive P1", std::to_string(s.non_positive_elements));
  row("open boundary faces", std::to_string(s.open_boundary_faces));
  if (s.consistency_problems.empty()) {
    row("consistency", "ok");
  } else {
    row("consistency", "FAILED (" + std::to_string(s.consistency_problems.size()) + " problems listed)");
    for (const std::string& problem : s.consistency_problems) row("", problem);
  }
  const JacobianStatistics& jacobian = s.jacobian;
  auto figures_text = [](const JacobianFigures& f) {
    return "min " + number(f.min) + "  avg " + number(f.average) + "  max " + number(f.max);
  };
  row("normalized Jacobian",
      figures_text(jacobian.min_normalized) +
          (jacobian.straight ? "  (straight P1 elements: 1, or -1 when inverted)" : "  (per element: certified min of J / |J straight|)"));
  row("scaled Jacobian", figures_text(jacobian.scaled) + "  (per element: min J / max J)");
  row("invalid elements", std::to_string(jacobian.invalid) +
                              (jacobian.invalid > 0 ? " (first: element " + one_based(jacobian.first_invalid_element) + ")" : ""));
  if (!jacobian.straight) {
    std::ostringstream header;
    header << std::right << std::setw(10) << "normalized" << std::setw(10) << "scaled";
    row("Jacobian histogram", header.str());
    for (std::size_t bin = 0; bin < jacobian.min_normalized.histogram.size(); ++bin) {
      std::ostringstream counts;
      counts << std::right << std::setw(10) << jacobian.min_normalized.histogram[bin] << std::setw(10) << jacobian.scaled.histogram[bin];
      row(std::string(2, ' ').append(jacobian_bin_label(bin)), counts.str());
    }
  }
  if (!s.defects.none()) row("defects", s.defects.summary());
  row("valid", !s.valid() ? "NO: " + invalidity_summary(s) : s.defects.none() ? "yes" : "yes, but with defects: " + s.defects.summary());
  row("memory", memory_text(s.memory_bytes));
  if (!s.metric) return;
  const MetricStatistics& metric = *s.metric;
  row("metric", metric_name);
  row("edge length", "min " + number(metric.min) + "  mean " + number(metric.mean) + "  max " + number(metric.max) + "  (" +
                         std::to_string(metric.edge_count) + " edges)");
  for (std::size_t bin = 0; bin < metric.histogram.size(); ++bin)
    row(std::string(2, ' ').append(bin_label(bin)), count_and_share(metric.histogram[bin], metric.edge_count));
  row("unit edges", percent(metric.unit_share) + " in " + bin_label(kUnitEdgeBin));
  row("element quality", "min " + number(metric.quality_min) + "  mean " + number(metric.quality_mean) +
                             "  (mean ratio in the metric at the centroid; 1: regular and unit)");
  for (std::size_t bin = 0; bin < metric.quality_histogram.size(); ++bin)
    row(std::string(2, ' ').append(quality_bin_label(bin)), count_and_share(metric.quality_histogram[bin], s.elements));
  row("poor elements", percent(metric.low_quality_share) + " with quality below " + bound(kLowQuality));
  row("max anisotropy", number(metric.max_anisotropy) + " (largest / smallest size at a vertex)");
}

void write_statistics_json(std::ostream& out, const MeshStatistics& s, const std::string& mesh_name, const std::string& metric_name) {
  JsonWriter json(out);
  json.begin_object();
  json.member("mesh", mesh_name).member("dimension", s.dimension).member("order", s.order);
  json.key("counts").begin_object();
  json.member("vertices", s.vertices).member("elements", s.elements).member("boundary_facets", s.boundary_facets);
  json.member("lines", s.lines).member("edges", s.edges).member("p2_nodes", s.p2_nodes);
  json.member("corners", s.corners).member("ridges", s.ridges).member("required_vertices", s.required_vertices);
  json.end_object();
  write_refs_json(json, "element_refs", s.element_refs);
  write_refs_json(json, "facet_refs", s.facet_refs);
  json.key("p1_measure").begin_object();
  json.member("min", s.min_measure).member("max", s.max_measure).member("total", s.total_measure);
  json.member("non_positive", s.non_positive_elements);
  json.end_object();
  json.member("open_boundary_faces", s.open_boundary_faces);
  json.key("defects").begin_object();
  json.member("non_manifold_vertices", s.defects.non_manifold_vertices).member("non_manifold_edges", s.defects.non_manifold_edges);
  json.member("overlap_vertices", s.defects.overlap_vertices).member("summary", s.defects.summary()).end_object();
  json.key("consistency").begin_object().member("consistent", s.consistency_problems.empty());
  json.key("problems").begin_array();
  for (const std::string& problem : s.consistency_problems) json.value(problem);
  json.end_array().end_object();
  const JacobianStatistics& jacobian = s.jacobian;
  json.key("jacobian").begin_object().member("straight", jacobian.straight);
  write_jacobian_figures_json(json, "min_normalized", jacobian.min_normalized);
  write_jacobian_figures_json(json, "scaled", jacobian.scaled);
  json.member("invalid", jacobian.invalid).key("first_invalid_element");
  if (jacobian.invalid > 0)
    json.value(jacobian.first_invalid_element + 1);
  else
    json.null();
  json.key("histogram").begin_array();
  for (std::size_t bin = 0; bin < jacobian.min_normalized.histogram.size(); ++bin) {
    json.begin_object();
    write_bin_bounds(json, jacobian_bin_label(bin), bin == 0 ? std::nullopt : std::optional(kJacobianBinBounds[bin - 1]),
                     bin < kJacobianBinBounds.size() ? std::optional(kJacobianBinBounds[bin]) : std::nullopt);
    json.member("min_normalized", jacobian.min_normalized.histogram[bin]);
    json.member("scaled", jacobian.scaled.histogram[bin]).end_object();
  }
  json.end_array().end_object();
  json.member("valid", s.valid());
  json.member("memory_bytes", s.memory_bytes);
  if (s.metric) {
    const MetricStatistics& metric = *s.metric;
    json.key("metric").begin_object().member("file", metric_name).member("edges", metric.edge_count);
    json.key("length").begin_object();
    json.member("min", metric.min).member("mean", metric.mean).member("max", metric.max).end_object();
    json.key("histogram").begin_array();
    for (std::size_t bin = 0; bin < metric.histogram.size(); ++bin) {
      json.begin_object();
      write_bin_bounds(json, bin_label(bin), bin == 0 ? 0.0 : kEdgeLengthBinBounds[bin - 1],
                       bin < kEdgeLengthBinBounds.size() ? std::optional(kEdgeLengthBinBounds[bin]) : std::nullopt);
      json.member("count", metric.histogram[bin]).end_object();
    }
    json.end_array();
    json.member("unit_share", metric.unit_share);
    write_quality_json(json, metric);
    json.member("max_anisotropy", metric.max_anisotropy).end_object();
  }
  json.end_object();
}

}  // namespace hocav
