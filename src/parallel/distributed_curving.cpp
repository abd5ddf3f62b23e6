#include "parallel/distributed_curving.hpp"

#include <algorithm>
#include <chrono>
#include <string>

#include "base/error.hpp"
#include "base/stopwatch.hpp"
#include "mesh/boundary_vertices.hpp"
#include "parallel/communicator.hpp"
#include "parallel/element_partition.hpp"
#include "parallel/part_curving.hpp"
#include "parallel/part_measures.hpp"
#include "parallel/part_message.hpp"
#include "parallel/root_mesh_partition.hpp"

namespace hocav {
namespace {

// One round on rank 0: partition, send, curve part 0, receive, write the parts' nodes back (a
// curving changes no element: write_back_nodes).
template <int D>
struct RootRound {
  Mesh<D>& mesh;
  const MetricField<D>& field;
  const BoundaryGeometry<D>* geometry;
  const CurvingOptions& options;
  // The first round's parts, per element: equal element counts (curving costs about the same per
  // element), cut without the whole mesh's graph on rank 0 (partition_from_root).
  std::vector<int> first_partition;
  // Per vertex of `mesh`: not reinserted yet, frozen on the interfaces of every round so far (empty
  // before the first). Boundary vertices too: none is reinserted, but the band around them brings
  // their boundary edges on the old interfaces, which got no proposal, into a part that curves them
  // (without them the cubed shell on 2 processes left 56 boundary edges straight, the serial run 0).
  std::vector<char> pending;
  DistributedCurvingRound figures;
  // What the first round leaves for the measures: rank 0's own part, curved, with its log-metrics;
  // every part's outline (part_measures.hpp); per mesh edge whether a later round wrote its node.
  MeshPart<D> first_own;
  std::vector<SymMat<D>> first_log_metrics;
  std::vector<PartOutline> first_outlines;
  std::vector<char> written_later;
  std::vector<char> on_interface;  // per vertex of `mesh`: on an interface of the round's parts

  // A round whose curved elements are cut into `band_parts` parts (the first round: every element).
  // The parts come back as their edges' nodes, written back as they come.
  PartCurving run(int band_parts) {
    const auto start = std::chrono::steady_clock::now();
    const int count = process_count();
    const bool first = pending.empty();
    std::vector<Index> elements_sent(static_cast<std::size_t>(count));
    MeshPart<D> own = send_parts(band_parts, elements_sent);
    PartCurving round = curve_part(own, field_of(own), region_of(own), own.global_ids, geometry, options);
    write_back(edge_node_records(own), {own.mesh.element_count()}, 0, elements_sent[0]);
    if (first) {
      first_log_metrics = log_metrics_of(own);
      first_own = std::move(own);
    }
    for (int p = 1; p < count; ++p) {
      const auto nodes = values_of_bytes<EdgeNodeRecord<D>>(receive(p));
      write_back(nodes, values_of_bytes<Index>(receive(p)), p, elements_sent[p]);
      add_part(round, values_of_bytes<PartCurving>(receive(p)).at(0));
    }
    update_pending();
    if (first) written_later.assign(static_cast<std::size_t>(mesh.edge_count()), 0);
    figures.cavities = round.counters.cavities;
    figures.seconds += seconds_since(start);
    return round;
  }

  // Makes the round's parts one at a time, and sends each other process its part as soon as it is
  // made: rank 0 holds one part besides the mesh. Returns rank 0's own, made last; each part's
  // element count in `elements_sent`, the vertices of the interfaces in `on_interface`, the first
  // round's outlines.
  MeshPart<D> send_parts(int band_parts, std::vector<Index>& elements_sent) {
    const bool first = pending.empty();
    const int count = process_count();
    MeshPart<D> own;
    Index interface_facets = 0;
    on_interface.assign(static_cast<std::size_t>(mesh.vertex_count()), 0);
    if (first) first_outlines.resize(static_cast<std::size_t>(count));
    split_mesh_part_by_part<D>(mesh, part_of_elements(band_parts), own_part_last(count), [&](int p, MeshPart<D> part) {
      elements_sent[p] = part.mesh.element_count();
      interface_facets += interface_facet_count(part.mesh);
      mark_interface_vertices(part);
      if (first) first_outlines[p] = outline_of(part);
      if (p == 0) {
        own = std::move(part);
        return;
      }
      send(p, pack_part(part.mesh, std::span<const Index>(part.global_ids)));
      send(p, bytes_of_values(log_metrics_of(part)));
      send(p, bytes_of_values(region_of(part)));
    });
    figures.interface_faces = interface_facets / 2;
    return own;
  }

  // The first round: `first_partition`. Later rounds: the elements near the pending vertices in
  // `band_parts` parts of equal element counts (curving costs about the same per element), the
  // others in none (-1).
  std::vector<int> part_of_elements(int band_parts) const {
    if (pending.empty()) return first_partition;
    std::vector<int> part_of(static_cast<std::size_t>(mesh.element_count()), -1);
    std::vector<Index> band;
    const WeightedGraph graph = member_graph(mesh, elements_near(mesh, pending, kBandRings), {}, band);
    if (band.empty()) return part_of;
    const std::vector<int> part_of_band = band_parts > 1 ? partition_graph(graph, band_parts) : std::vector<int>(band.size(), 0);
    for (std::size_t i = 0; i < band.size(); ++i) part_of[band[i]] = part_of_band[i];
    return part_of;
  }

  MetricField<D> field_of(const MeshPart<D>& part) const { return MetricField<D>::from_log_metrics(part.mesh, log_metrics_of(part)); }

  std::vector<SymMat<D>> log_metrics_of(const MeshPart<D>& part) const {
    std::vector<SymMat<D>> out;
    for (Index g : part.global_ids) out.push_back(field.vertex_log_metric(g));
    return out;
  }

  // The pending vertices; in the first round empty (all).
  std::vector<char> region_of(const MeshPart<D>& part) const {
    std::vector<char> out;
    if (!pending.empty())
      for (Index g : part.global_ids) out.push_back(pending[g]);
    return out;
  }

  // The vertices on the interfaces of a part of this round into `on_interface`.
  void mark_interface_vertices(const MeshPart<D>& part) {
    const std::vector<char> on_its_interfaces = interface_vertex_flags(part.mesh);
    for (Index v = 0; v < part.mesh.vertex_count(); ++v)
      if (on_its_interfaces[v]) on_interface[part.global_ids[v]] = 1;
  }

  // Part p's curved nodes into the mesh; it must come back with the `sent` elements (`elements`, one value).
  void write_back(std::span<const EdgeNodeRecord<D>> nodes, const std::vector<Index>& elements, int p, Index sent) {
    if (elements.size() != 1 || elements[0] != sent)
      throw Error("distributed curving: part " + std::to_string(p) + " came back with another element count");
    write_back_nodes<D>(mesh, nodes, pending.empty() ? nullptr : &written_later);
  }

  // The vertices on this round's interfaces leave the pending ones (the first round's are the first pending).
  void update_pending() {
    figures.interface_vertices = static_cast<Index>(std::count(on_interface.begin(), on_interface.end(), 1));
    if (pending.empty()) {
      pending = on_interface;
      return;
    }
    for (std::size_t v = 0; v < pending.size(); ++v) {
      pending[v] = pending[v] && on_interface[v];
      figures.old_interface_vertices_frozen_again += pending[v];
    }
  }

  // The output's Jacobians and gains, measured by the first round's parts, in part order.
  PartMeasures measure_output() {
    std::vector<Index> written;
    for (Index e = 0; e < mesh.edge_count(); ++e)
      if (written_later[e]) written.push_back(e);
    const std::vector<bool> on_boundary = boundary_vertex_flags(mesh);
    const auto before = interface_edges_measured_before(first_outlines);
    auto updates = node_updates_by_part(mesh, written, first_outlines);
    const auto boundary_of = [&](const PartOutline& part) {
      std::vector<char> out;
      for (Index g : part.global_ids) out.push_back(on_boundary[g]);
      return out;
    };
    for (int p = 1; p < process_count(); ++p) {
      send_values(p, updates[p]);
      send_values(p, boundary_of(first_outlines[p]));
      send_values(p, before[p]);
    }
    PartMeasures all = measure_part<D>(first_own, MetricField<D>::from_log_metrics(first_own.mesh, std::move(first_log_metrics)),
                                       updates[0], boundary_of(first_outlines[0]), before[0], options.threads);
    for (int p = 1; p < process_count(); ++p) {
      const auto elements = receive_values<JacobianQuality>(p);
      const auto gains = receive_values<double>(p);
      const auto deferred = receive_values<std::array<Index, 2>>(p);
      all.elements.insert(all.elements.end(), elements.begin(), elements.end());
      all.gains.insert(all.gains.end(), gains.begin(), gains.end());
      all.deferred.insert(all.deferred.end(), deferred.begin(), deferred.end());
    }
    for (const auto& [a, b] : all.deferred) all.gains.push_back(edge_gain(mesh, field, mesh.find_edge(a, b)).value);
    return all;
  }

  void send(int to, const std::vector<std::byte>& bytes) { send_bytes(to, bytes, figures.bytes_sent); }
  std::vector<std::byte> receive(int from) { return receive_bytes(from, figures.bytes_sent); }
};

// A worker's end of RootRound::measure_output: its first-round part measured.
template <int D>
void measure_first_part(MeshPart<D>& part, std::vector<SymMat<D>> log_metrics, int threads) {
  const auto updates = receive_values<NodeUpdate<D>>(0);
  const auto on_boundary = receive_values<char>(0);
  const auto before = receive_values<std::array<Index, 2>>(0);
  const PartMeasures measures = measure_part<D>(part, MetricField<D>::from_log_metrics(part.mesh, std::move(log_metrics)), updates,
                                                on_boundary, before, threads);
  send_values(0, measures.elements);
  send_values(0, measures.gains);
  send_values(0, measures.deferred);
}

}  // namespace

template <int D>
CurvingReport curve_distributed(Mesh<D>& mesh, const MetricField<D>& field, const BoundaryGeometry<D>* geometry,
                                const CurvingOptions& options, const std::function<void(const DistributedCurvingRound&)>& on_round) {
  if (field.back_mesh().vertex_count() != mesh.vertex_count())
    throw Error("curving: the metric's back mesh has " + std::to_string(field.back_mesh().vertex_count()) + " vertices, the mesh " +
                std::to_string(mesh.vertex_count()));
  if (!mesh.has_topology()) mesh.build_topology();
  const auto start = std::chrono::steady_clock::now();
  long long partition_bytes = 0;
  std::vector<int> first_partition = partition_from_root(mesh, kCurvingPartitionSeed, &partition_bytes);  // before the nodes: P1 pieces
  const double partition_seconds = seconds_since(start);
  if (!mesh.is_p2()) mesh.make_p2();  // the parts are P2: their interface edges keep their nodes
  const Index points_before = mesh.vertex_count();
  CurvingOptions part_options = options;
  part_options.progress = {};  // rank 0's part is not the whole
  RootRound<D> root{mesh, field, geometry, part_options, std::move(first_partition), {}, {}, {}, {}, {}, {}, {}};
  PartCurving total;
  for (int round = 1; round <= kDistributedCurvingRounds; ++round) {
    if (round > 1 && std::find(root.pending.begin(), root.pending.end(), 1) == root.pending.end()) break;
    root.figures = {};
    root.figures.round = round;
    if (round == 1) {
      root.figures.bytes_sent = partition_bytes;
      root.figures.seconds = partition_seconds;
    }
    add_round(total, root.run(round < kDistributedCurvingRounds ? process_count() : 1));
    if (on_round) on_round(root.figures);
  }
  for (int p = 1; p < process_count(); ++p) send_bytes(p, {});  // the rounds are over
  check_curved_consistency(mesh);
  const PartMeasures measures = root.measure_output();
  ReinsertionResult result;
  result.counters = total.counters;
  result.seconds = total.seconds;
  result.vertices_reinserted = static_cast<Index>(total.counters.cavities);
  CurvingReport report = curving_run_report(field, points_before, result, static_cast<Index>(total.proposals_left));
  summarize_curved_output(report, mesh, measures.elements, measures.gains);
  report.boundary_completion = total.completion;
  report.threads = options.threads;
  return report;
}

template <int D>
void serve_distributed_curving(const BoundaryGeometry<D>* geometry, const CurvingOptions& options) {
  partition_from_root(Mesh<D>{}, kCurvingPartitionSeed);
  MeshPart<D> first;  // the first round's part, kept to measure the output at the end
  std::vector<SymMat<D>> first_log_metrics;
  for (bool first_round = true;; first_round = false) {
    const std::vector<std::byte> bytes = receive_bytes(0);
    if (bytes.empty()) break;
    MeshPart<D> part = unpack_part<D>(bytes);
    std::vector<SymMat<D>> log_metrics = receive_values<SymMat<D>>(0);
    const std::vector<char> region = receive_values<char>(0);
    const MetricField<D> field = MetricField<D>::from_log_metrics(part.mesh, first_round ? log_metrics : std::move(log_metrics));
    const PartCurving result = curve_part(part, field, region, part.global_ids, geometry, options);
    send_values(0, edge_node_records(part));
    send_values(0, std::vector<Index>{part.mesh.element_count()});
    send_values(0, std::vector<PartCurving>{result});
    if (first_round) {
      first = std::move(part);
      first_log_metrics = std::move(log_metrics);
    }
  }
  measure_first_part(first, std::move(first_log_metrics), options.threads);
}

template CurvingReport curve_distributed(Mesh<2>&, const MetricField<2>&, const BoundaryGeometry<2>*, const CurvingOptions&,
                                         const std::function<void(const DistributedCurvingRound&)>&);
template CurvingReport curve_distributed(Mesh<3>&, const MetricField<3>&, const BoundaryGeometry<3>*, const CurvingOptions&,
                                         const std::function<void(const DistributedCurvingRound&)>&);
template void serve_distributed_curving(const BoundaryGeometry<2>*, const CurvingOptions&);
template void serve_distributed_curving(const BoundaryGeometry<3>*, const CurvingOptions&);

}  // namespace hocav
