#include "parallel/curving_in_parts.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <unordered_map>
#include <unordered_set>

#include "base/stopwatch.hpp"
#include "bezier/mesh_quality.hpp"
#include "geom/sym_functions.hpp"
#include "mesh/boundary_vertices.hpp"
#include "parallel/boundary_of_parts.hpp"
#include "parallel/byte_stream.hpp"
#include "parallel/communicator.hpp"
#include "parallel/element_partition.hpp"
#include "parallel/face_key.hpp"
#include "parallel/field_with_neighbours.hpp"
#include "parallel/part_curving.hpp"
#include "parallel/part_measures.hpp"
#include "parallel/part_shipment.hpp"
#include "report/curving_report.hpp"

namespace hocav {
namespace {

using EdgeEnds = std::array<Index, 2>;

// Collective: the part's interface edges (by global ends, low first) that a part of a lower rank
// holds too. Each is measured once, by the lowest rank that holds it; the holders meet where the
// edge's ends hash to.
template <int D>
std::vector<EdgeEnds> interface_edges_held_below(const MeshPart<D>& part) {
  std::vector<std::vector<FaceKey<2>>> outgoing(static_cast<std::size_t>(process_count()));
  for (const EdgeEnds& edge : interface_edges_by_global_ends(part))
    outgoing[static_cast<std::size_t>(meeting_process<2>(edge, process_count()))].push_back(edge);
  const std::vector<std::vector<FaceKey<2>>> arrived = exchange_values(outgoing);
  std::unordered_map<FaceKey<2>, std::size_t, FaceKeyHash<2>> lowest;  // the lowest rank holding each
  for (std::size_t r = 0; r < arrived.size(); ++r)
    for (const FaceKey<2>& edge : arrived[r]) lowest.emplace(edge, r);
  std::vector<std::vector<char>> answers(arrived.size());
  for (std::size_t r = 0; r < arrived.size(); ++r)
    for (const FaceKey<2>& edge : arrived[r]) answers[r].push_back(static_cast<char>(lowest.at(edge) < r));
  const std::vector<std::vector<char>> held = exchange_values(answers);
  std::vector<EdgeEnds> out;
  for (std::size_t r = 0; r < outgoing.size(); ++r)
    for (std::size_t i = 0; i < outgoing[r].size(); ++i)
      if (held[r].at(i)) out.push_back(outgoing[r][i]);
  return out;
}

// The elements near the interfaces, copied onto rank 0 from every part, with per vertex its
// log-metric (until the band's field takes them) and whether it lies on a first-round interface
// (pending: to reinsert).
template <int D>
struct Band {
  MeshPart<D> part;
  std::vector<SymMat<D>> log_metrics;
  std::vector<char> pending;
};

// A process's message to rank 0: the shipment of its `elements`, then its vertices' log-metrics (in
// `field`, on the part's mesh) and pending flags in the shipment's order.
template <int D>
std::vector<std::byte> band_message(const MeshPart<D>& part, std::span<const Index> elements, const MetricField<D>& field,
                                    const std::vector<char>& pending) {
  const Shipment<D> shipment = shipment_of(part, elements);
  const std::unordered_map<Index, Index> local = local_ids_of(part);
  std::vector<SymMat<D>> logs;
  std::vector<char> flags;
  for (Index g : shipment.vertex_ids) {
    logs.push_back(field.vertex_log_metric(local.at(g)));
    flags.push_back(pending[local.at(g)]);
  }
  ByteWriter out;
  out.put(shipment.bytes()), out.put(logs), out.put(flags);
  return std::move(out.bytes);
}

template <int D>
Band<D> band_of_messages(const std::vector<std::vector<std::byte>>& messages) {
  std::vector<Shipment<D>> arrived;
  std::vector<std::vector<SymMat<D>>> logs;
  std::vector<std::vector<char>> flags;
  for (const std::vector<std::byte>& message : messages) {
    ByteReader in(message);
    arrived.push_back(Shipment<D>::read(in.take<std::byte>()));
    logs.push_back(in.take<SymMat<D>>());
    flags.push_back(in.take<char>());
  }
  Band<D> band{part_of_shipments(arrived), {}, {}};
  const std::unordered_map<Index, Index> local = local_ids_of(band.part);
  band.log_metrics.resize(band.part.global_ids.size());
  band.pending.assign(band.part.global_ids.size(), 0);
  for (std::size_t s = 0; s < arrived.size(); ++s)
    for (std::size_t i = 0; i < arrived[s].vertex_ids.size(); ++i) {
      const Index v = local.at(arrived[s].vertex_ids[i]);
      band.log_metrics[v] = logs[s].at(i);
      band.pending[v] = static_cast<char>(band.pending[v] | flags[s].at(i));
    }
  return band;
}

// The volume-edge gains: summed, counted, the largest.
struct GainTally {
  double sum = 0, largest = 0;
  Index count = 0;

  void add(double gain) {
    sum += gain;
    largest = count++ == 0 ? gain : std::max(largest, gain);
  }
};

// Collective: every part's Jacobian summaries merged in rank order.
MeshJacobianSummary merged_over_processes(const MeshJacobianSummary& own) {
  const auto bytes_of = [](const ValueSummary& s, ByteWriter& out) {
    out.put(std::vector<double>{s.min, s.average, s.max, s.histogram_lower, s.histogram_upper});
    out.put(std::vector<Index>{s.count, s.invalid_count, s.below, s.above});
    out.put(s.histogram);
  };
  const auto read = [](ByteReader& in) {
    ValueSummary s;
    const auto reals = in.take<double>();
    const auto counts = in.take<Index>();
    s.min = reals.at(0), s.average = reals.at(1), s.max = reals.at(2), s.histogram_lower = reals.at(3), s.histogram_upper = reals.at(4);
    s.count = counts.at(0), s.invalid_count = counts.at(1), s.below = counts.at(2), s.above = counts.at(3);
    s.histogram = in.take<Index>();
    return s;
  };
  ByteWriter out;
  bytes_of(own.min_normalized_jacobian, out);
  bytes_of(own.scaled_jacobian, out);
  MeshJacobianSummary all;
  bool first = true;
  for (const std::vector<std::byte>& bytes : all_gather_bytes(out.bytes)) {
    ByteReader in(bytes);
    const ValueSummary normalized = read(in), scaled = read(in);
    all.min_normalized_jacobian = first ? normalized : merge_summaries(all.min_normalized_jacobian, normalized);
    all.scaled_jacobian = first ? scaled : merge_summaries(all.scaled_jacobian, scaled);
    first = false;
  }
  return all;
}

// The run on every process: its part, its vertices' metric field, and rank 0's band with its own.
template <int D>
struct PartsRun {
  MeshPart<D>& part;
  std::optional<MetricField<D>> field;  // on the part's mesh (the curving keeps its vertices and elements; the curved passes do not)
  const MeshPart<D>& boundary;
  const BoundaryGeometry<D>* geometry;
  const CurvingOptions& options;
  CurvingInParts out;
  std::vector<Index> band_elements;  // the part's elements in the band
  std::optional<Band<D>> band;       // rank 0's
  std::optional<MetricField<D>> band_field;

  // Round 1: every part with its interfaces frozen.
  PartCurving curve_parts() {
    const auto start = std::chrono::steady_clock::now();
    const std::vector<Index> geometry_ids = boundary_indices(part, boundary.global_ids);
    const PartCurving own = curve_part(part, *field, {}, geometry_ids, geometry, options);
    PartCurving round;
    for (const PartCurving& each : all_gather_value(own)) add_part(round, each);
    DistributedCurvingRound& figures = out.rounds[0];
    figures.round = 1;
    figures.rounds = 2;
    figures.interface_faces = sum_over_processes(interface_facet_count(part.mesh)) / 2;
    figures.cavities = round.counters.cavities;
    figures.seconds = max_over_processes(seconds_since(start));
    return round;
  }

  // Round 2: the band copied onto rank 0, its pending vertices reinserted there, the nodes it wrote
  // sent to every part.
  PartCurving curve_band() {
    const auto start = std::chrono::steady_clock::now();
    DistributedCurvingRound& figures = out.rounds[1];
    figures.round = figures.rounds = 2;
    const std::vector<char> pending = interface_vertex_flags(part.mesh);
    const std::vector<char> near = elements_near(part.mesh, pending, kBandRings);
    for (Index k = 0; k < part.mesh.element_count(); ++k)
      if (near[k]) band_elements.push_back(k);
    std::vector<std::vector<std::byte>> outgoing(static_cast<std::size_t>(process_count()));
    outgoing[0] = band_message(part, band_elements, *field, pending);
    const long long bytes = process_rank() == 0 ? 0 : static_cast<long long>(outgoing[0].size());
    const std::vector<std::vector<std::byte>> arrived = exchange_bytes(outgoing);
    PartCurving round;
    std::vector<NodeUpdate<D>> updates;
    if (process_rank() == 0) {
      band = band_of_messages<D>(arrived);
      out.rounds[0].interface_vertices = static_cast<Index>(std::count(band->pending.begin(), band->pending.end(), 1));
      figures.interface_faces = interface_facet_count(band->part.mesh);
      const std::vector<char> border = interface_vertex_flags(band->part.mesh);
      for (std::size_t v = 0; v < border.size(); ++v) figures.old_interface_vertices_frozen_again += border[v] && band->pending[v];
      figures.interface_vertices = static_cast<Index>(std::count(border.begin(), border.end(), 1));
      band_field = MetricField<D>::from_log_metrics(band->part.mesh, std::move(band->log_metrics));
      round = curve_part(band->part, *band_field, band->pending, boundary_indices(band->part, boundary.global_ids), geometry, options);
      for (const EdgeNodeRecord<D>& record : edge_node_records(band->part))
        if (!record.frozen) updates.push_back({record.ends, record.node});
    }
    broadcast_values(updates);
    apply_node_updates<D>(part, updates);
    figures.cavities = round.counters.cavities;
    figures.bytes_sent = sum_over_processes(bytes) + static_cast<long long>(updates.size() * sizeof(NodeUpdate<D>)) * (process_count() - 1);
    std::vector<PartCurving> shared{round};
    broadcast_values(shared);
    figures.seconds = max_over_processes(seconds_since(start));
    return shared.at(0);
  }

  // The output's Jacobians and gains: each part measures its own elements and its volume edges
  // (an interface edge once, by the lowest rank holding it); an edge whose samples fall outside its
  // part is measured by rank 0 in the band when the band holds it, else in the part's field.
  void measure(const std::vector<EdgeEnds>& held_below) {
    const std::vector<bool> on_boundary_mesh = boundary_vertex_flags(boundary.mesh);
    std::vector<char> on_boundary;
    for (Index id : boundary_indices(part, boundary.global_ids)) on_boundary.push_back(id != kNoIndex && on_boundary_mesh[id]);
    const PartMeasures measures = measure_part(part, *field, on_boundary, held_below, options.threads);
    GainTally gains;
    for (double gain : measures.gains) gains.add(gain);
    std::unordered_set<std::uint64_t> band_edges;
    for (Index k : band_elements)
      for (int e = 0; e < Simplex<D>::kEdges; ++e) {
        const auto& ends = part.mesh.edge_vertices(part.mesh.element_edge(k, e));
        band_edges.insert(global_edge_key({part.global_ids[ends[0]], part.global_ids[ends[1]]}));
      }
    std::vector<std::vector<EdgeEnds>> to_band(static_cast<std::size_t>(process_count()));
    Index in_part = 0;
    for (std::size_t i = 0; i < measures.deferred.size(); ++i)
      if (band_edges.contains(global_edge_key(measures.deferred[i])))
        to_band[0].push_back(measures.deferred[i]);
      else
        gains.add(measures.deferred_in_part[i]), ++in_part;
    out.deferred_gains_in_parts = sum_over_processes(in_part);
    const std::vector<EdgeEnds> deferred = exchange_values_joined(to_band);
    if (band && !deferred.empty()) {
      const std::unordered_map<Index, Index> local = local_ids_of(band->part);
      for (const EdgeEnds& ends : deferred)
        gains.add(edge_gain(band->part.mesh, *band_field, band->part.mesh.find_edge(local.at(ends[0]), local.at(ends[1]))).value);
    }
    GainTally all;
    for (const GainTally& each : all_gather_value(gains)) {
      if (each.count == 0) continue;
      all.largest = all.count == 0 ? each.largest : std::max(all.largest, each.largest);
      all.sum += each.sum, all.count += each.count;
    }
    const MeshJacobianSummary jacobians = merged_over_processes(summarize_jacobian_quality(measures.elements));
    out.report.normalized_jacobian = jacobians.min_normalized_jacobian;
    out.report.scaled_jacobian = jacobians.scaled_jacobian;
    out.report.average_gain = all.count > 0 ? all.sum / static_cast<double>(all.count) : 0;
    out.report.max_gain = all.count > 0 ? std::max(0.0, all.largest) : 0;
  }

  // The curved lengths and qualities (CurvedMeasures), every edge once.
  void measure_curved_output(const std::vector<EdgeEnds>& held_below) {
    std::unordered_set<std::uint64_t> skipped_keys;
    for (const EdgeEnds& ends : held_below) skipped_keys.insert(global_edge_key(ends));
    std::vector<char> skipped(static_cast<std::size_t>(part.mesh.edge_count()), 0);
    for (Index e = 0; e < part.mesh.edge_count(); ++e) {
      const auto& ends = part.mesh.edge_vertices(e);
      skipped[e] = ends[0] != kNoIndex && skipped_keys.contains(global_edge_key({part.global_ids[ends[0]], part.global_ids[ends[1]]}));
    }
    CurvedMeasures own;
    if (part.mesh.element_count() > 0) {
      own = measure_curved(part.mesh, *field, options.threads, skipped);
    } else {
      own.length_min = own.quality_min = INFINITY;
    }
    CurvedMeasures all;
    bool first = true;
    for (const CurvedMeasures& each : all_gather_value(own)) {
      all = first ? each : merge_curved_measures(all, each);
      first = false;
    }
    out.curved = all;
  }

  // The log-metric of each of the part's vertices, from the field on the part.
  std::vector<SymMat<D>> vertex_log_metrics() const {
    std::vector<SymMat<D>> log_metrics;
    for (Index v = 0; v < part.mesh.vertex_count(); ++v) log_metrics.push_back(field->vertex_log_metric(v));
    return log_metrics;
  }

  // The field the figures are measured in: the part's with a ring of its neighbours' elements, so
  // that what lies just past the part's border is sampled as in the whole mesh's field (its bytes
  // counted in the band's round).
  void widen_field_to_neighbours() {
    long long bytes = 0;
    field.emplace(field_with_neighbours(part, vertex_log_metrics(), bytes));
    out.rounds[1].bytes_sent += sum_over_processes(bytes);
  }

  // The curved passes on the curved parts, which they change and move: the band's elements are no
  // longer the part's, and the field is remade on the part they leave. (The band and the curving's
  // field are let go first: the passes hold copies of the part.)
  void adapt_curved_parts(const CurvedPassesSettings& settings) {
    std::vector<SymMat<D>> log_metrics = vertex_log_metrics();
    band_elements.clear();
    band.reset();
    band_field.reset();
    field.reset();
    out.passes = adapt_curved_in_parts(part, log_metrics, geometry, cavity_options(options), settings, options.threads);
    field.emplace(MetricField<D>::from_log_metrics(part.mesh, std::move(log_metrics)));
  }
};

}  // namespace

template <int D>
CurvingInParts curve_in_parts(MeshPart<D>& part, std::vector<SymMat<D>> metrics, const PartsGeometryMaker<D>& make_geometry,
                              const CurvingOptions& options, bool measure_curved, const CurvedPassesSettings& passes) {
  long long boundary_bytes = 0;
  const MeshPart<D> boundary = boundary_of_parts(part, &boundary_bytes);
  const std::shared_ptr<const BoundaryGeometry<D>> geometry = make_geometry ? make_geometry(boundary.mesh) : nullptr;
  if (!part.mesh.has_topology()) part.mesh.build_topology();
  if (!part.mesh.is_p2()) part.mesh.make_p2();                 // interface edges keep their straight nodes on both sides
  for (SymMat<D>& metric : metrics) metric = log_spd(metric);  // in place: no second copy
  PartsRun<D> run{part, MetricField<D>::from_log_metrics(part.mesh, std::move(metrics)), boundary, geometry.get(), options, {}, {}, {}, {}};
  PartCurving total;
  add_round(total, run.curve_parts());
  run.out.rounds[0].bytes_sent += sum_over_processes(boundary_bytes);
  add_round(total, run.curve_band());
  if (passes.max_passes > 0) run.adapt_curved_parts(passes);
  check_curved_consistency(part.mesh);
  const std::vector<EdgeEnds> held_below = interface_edges_held_below(part);
  ReinsertionResult result;
  result.counters = total.counters;
  result.seconds = total.seconds;
  result.vertices_reinserted = static_cast<Index>(total.counters.cavities);
  double anisotropy = 0;
  for (Index v = 0; v < part.mesh.vertex_count(); ++v) anisotropy = std::max(anisotropy, anisotropy_of(run.field->vertex_log_metric(v)));
  run.out.report = curving_run_report<D>(max_over_processes(anisotropy), 0, result, static_cast<Index>(total.proposals_left));
  run.out.report.boundary_completion = total.completion;
  run.out.report.threads = options.threads;
  run.widen_field_to_neighbours();
  run.measure(held_below);
  if (measure_curved) run.measure_curved_output(held_below);
  return std::move(run.out);
}

void count_curved_output(CurvingReport& report, const MeshFileCounts& counts) {
  report.elements = counts.elements;
  report.points_before = counts.vertices;
  report.points_after = counts.vertices + counts.nodes;
}

template CurvingInParts curve_in_parts(MeshPart<2>&, std::vector<SymMat<2>>, const PartsGeometryMaker<2>&, const CurvingOptions&, bool,
                                       const CurvedPassesSettings&);
template CurvingInParts curve_in_parts(MeshPart<3>&, std::vector<SymMat<3>>, const PartsGeometryMaker<3>&, const CurvingOptions&, bool,
                                       const CurvedPassesSettings&);

}  // namespace hocav
