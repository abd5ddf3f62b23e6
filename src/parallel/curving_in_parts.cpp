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
#include "parallel/distinct_ids.hpp"
#include "parallel/element_partition.hpp"
#include "parallel/face_key.hpp"
#include "parallel/field_with_neighbours.hpp"
#include "parallel/last_run_region.hpp"
#include "parallel/part_curving.hpp"
#include "parallel/part_measures.hpp"
#include "parallel/part_shipment.hpp"
#include "report/curving_report.hpp"

namespace hocav {
namespace {

using EdgeEnds = std::array<Index, 2>;

constexpr int kNoTaker = -1;

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

// The elements near some interfaces, copied onto the process that takes them from every part that
// holds them, with per vertex its log-metric (until the band's field takes them) and whether it lies
// on a first-round interface (pending: to reinsert), and per element the process it came from.
template <int D>
struct Band {
  MeshPart<D> part;
  std::vector<SymMat<D>> log_metrics;
  std::vector<char> pending;
  std::vector<int> source;
};

// A process's message to a band's taker: the shipment of its `elements`, then its vertices'
// log-metrics (in `field`, on the part's mesh) and pending flags in the shipment's order.
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

// The band of the messages that came, by process (an empty message: none from that process).
template <int D>
Band<D> band_of_messages(const std::vector<std::vector<std::byte>>& messages) {
  std::vector<Shipment<D>> arrived;
  std::vector<std::vector<SymMat<D>>> logs;
  std::vector<std::vector<char>> flags;
  std::vector<int> source;
  for (std::size_t from = 0; from < messages.size(); ++from) {
    if (messages[from].empty()) continue;
    ByteReader in(messages[from]);
    arrived.push_back(Shipment<D>::read(in.take<std::byte>()));
    logs.push_back(in.take<SymMat<D>>());
    flags.push_back(in.take<char>());
    source.insert(source.end(), arrived.back().elements.size(), static_cast<int>(from));
  }
  Band<D> band{part_of_shipments(arrived), {}, {}, std::move(source)};
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

// A band's border (the faces towards the elements left behind) and its pending vertices.
struct BandBorder {
  Index faces = 0;
  std::vector<Index> vertex_ids;   // on the border, by global id
  std::vector<Index> pending_ids;  // pending, on the border or not
  Index pending_inside = 0;        // pending, off the border: reinserted here
};

template <int D>
BandBorder border_of(const Band<D>& band) {
  BandBorder out;
  const std::vector<char> border = interface_vertex_flags(band.part.mesh);
  out.faces = interface_facet_count(band.part.mesh);
  out.vertex_ids = global_ids_of(band.part, border);
  out.pending_ids = global_ids_of(band.part, band.pending);
  for (std::size_t v = 0; v < border.size(); ++v) out.pending_inside += band.pending[v] && !border[v];
  return out;
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

// The run on every process: its part, its vertices' metric field, and the second round's band it took, if any.
template <int D>
struct PartsRun {
  MeshPart<D>& part;
  std::optional<MetricField<D>> field;  // on the part's mesh (the curving keeps its vertices and elements; the curved passes do not)
  const MeshPart<D>& boundary;
  const BoundaryGeometry<D>* geometry;
  const CurvingOptions& options;
  CurvingInParts out;
  std::vector<int> band_taker;  // per element of the part: the process whose second-round band holds a copy (kNoTaker: none)
  std::optional<Band<D>> band;  // the second round's band this process took, if any
  std::optional<MetricField<D>> band_field;

  // Round 1: every part with its interfaces frozen.
  PartCurving curve_parts() {
    const auto start = std::chrono::steady_clock::now();
    const std::vector<Index> geometry_ids = boundary_indices(part, boundary.global_ids);
    const PartCurving own = curve_part(part, *field, {}, geometry_ids, geometry, options);
    PartCurving round;
    for (const PartCurving& each : all_gather_value(own)) add_part(round, each);
    DistributedCurvingRound& figures = out.rounds[0];
    figures.interface_faces = sum_over_processes(interface_facet_count(part.mesh)) / 2;
    figures.cavities = round.counters.cavities;
    figures.seconds = max_over_processes(seconds_since(start));
    return round;
  }

  // Rounds 2 and 3: each interface's band (the elements within kBandRings rings of its vertices)
  // copied onto one of its two processes, which reinserts the pending vertices there; then the
  // bands' seams (where three or more parts met, none with two processes) on rank 0.
  PartCurving curve_bands() {
    const std::vector<char> pending = interface_vertex_flags(part.mesh);
    out.rounds[0].interface_vertices = distinct_count(global_ids_of(part, pending));
    // (Each band to the lighter of its two processes, as the curved passes' regions.)
    const RegionCut cut = cut_last_run_region(part, kBandRings, all_gather_value(part.mesh.element_count()));
    band_taker.assign(cut.destination.size(), kNoTaker);
    for (std::size_t k = 0; k < band_taker.size(); ++k)
      if (cut.in_region[k]) band_taker[k] = cut.destination[k];
    std::vector<char> left = flags_of_global_ids(part, all_gather_values_joined(cut.seams));
    for (std::size_t v = 0; v < left.size(); ++v)
      left[v] = static_cast<char>(left[v] && pending[v]);  // on the border of every band holding it
    const int rounds = sum_over_processes(static_cast<Index>(std::count(left.begin(), left.end(), 1))) > 0 ? 3 : 2;
    for (int r = 0; r < rounds; ++r)
      out.rounds[static_cast<std::size_t>(r)].round = r + 1, out.rounds[static_cast<std::size_t>(r)].rounds = rounds;
    PartCurving bands = curve_band_round(band_taker, pending, out.rounds[1], true);
    if (rounds == 3) {
      std::vector<int> to_root;
      for (char near : elements_near(part.mesh, left, kBandRings)) to_root.push_back(near ? 0 : kNoTaker);
      add_round(bands, curve_band_round(to_root, left, out.rounds[2], false));
    }
    return bands;
  }

  // Per process, the message of the part's elements that `taker` sends it (none for no element),
  // and the bytes of those to other processes added to `bytes`.
  std::vector<std::vector<std::byte>> band_messages(const std::vector<int>& taker, const std::vector<char>& pending,
                                                    long long& bytes) const {
    std::vector<std::vector<Index>> elements_to(static_cast<std::size_t>(process_count()));
    for (Index k = 0; k < part.mesh.element_count(); ++k)
      if (taker[k] != kNoTaker) elements_to[static_cast<std::size_t>(taker[k])].push_back(k);
    std::vector<std::vector<std::byte>> outgoing(elements_to.size());
    for (std::size_t to = 0; to < outgoing.size(); ++to) {
      if (elements_to[to].empty()) continue;
      outgoing[to] = band_message(part, elements_to[to], *field, pending);
      if (static_cast<int>(to) != process_rank()) bytes += static_cast<long long>(outgoing[to].size());
    }
    return outgoing;
  }

  // One round of bands: element k of the part copied onto process taker[k] (none for kNoTaker); each
  // process that takes a band reinserts its `pending` vertices but those on its border, and sends the
  // nodes it wrote to the parts whose elements hold their edges. With `keep`, this process's band
  // stays for the figures' measures.
  PartCurving curve_band_round(const std::vector<int>& taker, const std::vector<char>& pending, DistributedCurvingRound& figures,
                               bool keep) {
    const auto start = std::chrono::steady_clock::now();
    long long bytes = 0;
    const std::vector<std::vector<std::byte>> arrived = exchange_bytes(band_messages(taker, pending, bytes));
    PartCurving own;
    BandBorder border;
    std::vector<std::vector<NodeUpdate<D>>> updates(arrived.size());
    std::optional<Band<D>> taken;
    std::optional<MetricField<D>> taken_field;
    if (std::any_of(arrived.begin(), arrived.end(), [](const std::vector<std::byte>& message) { return !message.empty(); })) {
      taken = band_of_messages<D>(arrived);
      border = border_of(*taken);
      taken_field.emplace(MetricField<D>::from_log_metrics(taken->part.mesh, std::move(taken->log_metrics)));
      own = curve_part(taken->part, *taken_field, taken->pending, boundary_indices(taken->part, boundary.global_ids), geometry, options);
      updates = node_updates_by_source(taken->part, taken->source, process_count());
    }
    for (std::size_t to = 0; to < updates.size(); ++to)
      if (static_cast<int>(to) != process_rank()) bytes += static_cast<long long>(updates[to].size() * sizeof(NodeUpdate<D>));
    for (const std::vector<NodeUpdate<D>>& each : exchange_values(updates)) apply_node_updates<D>(part, each);
    PartCurving round;
    for (const PartCurving& each : all_gather_value(own)) add_part(round, each);
    figures.interface_faces = sum_over_processes(border.faces);
    figures.interface_vertices = distinct_count(border.vertex_ids);
    // (A pending vertex on one band's border may lie inside another's: reinserted there, once.)
    figures.old_interface_vertices_frozen_again = distinct_count(border.pending_ids) - sum_over_processes(border.pending_inside);
    figures.cavities = round.counters.cavities;
    figures.bytes_sent = sum_over_processes(bytes);
    figures.seconds = max_over_processes(seconds_since(start));
    if (keep) band = std::move(taken), band_field = std::move(taken_field);
    return round;
  }

  // The output's Jacobians and gains: each part measures its own elements and its volume edges
  // (an interface edge once, by the lowest rank holding it); an edge whose samples fall outside its
  // part is measured by the process whose band holds it when one does, else in the part's field.
  void measure(const std::vector<EdgeEnds>& held_below) {
    const std::vector<bool> on_boundary_mesh = boundary_vertex_flags(boundary.mesh);
    std::vector<char> on_boundary;
    for (Index id : boundary_indices(part, boundary.global_ids)) on_boundary.push_back(id != kNoIndex && on_boundary_mesh[id]);
    const PartMeasures measures = measure_part(part, *field, on_boundary, held_below, options.threads);
    GainTally gains;
    for (double gain : measures.gains) gains.add(gain);
    std::unordered_map<std::uint64_t, int> band_edges;  // the part's edges in a second-round band, with its taker
    for (Index k = 0; k < part.mesh.element_count(); ++k) {
      if (band_taker.empty() || band_taker[k] == kNoTaker) continue;
      for (int e = 0; e < Simplex<D>::kEdges; ++e) {
        const auto& ends = part.mesh.edge_vertices(part.mesh.element_edge(k, e));
        band_edges.emplace(global_edge_key({part.global_ids[ends[0]], part.global_ids[ends[1]]}), band_taker[k]);
      }
    }
    std::vector<std::vector<EdgeEnds>> to_band(static_cast<std::size_t>(process_count()));
    Index in_part = 0;
    for (std::size_t i = 0; i < measures.deferred.size(); ++i) {
      const auto at = band_edges.find(global_edge_key(measures.deferred[i]));
      if (at != band_edges.end())
        to_band[static_cast<std::size_t>(at->second)].push_back(measures.deferred[i]);
      else
        gains.add(measures.deferred_in_part[i]), ++in_part;
    }
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
    band_taker.clear();
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
  add_round(total, run.curve_bands());
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
