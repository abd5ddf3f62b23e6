#include "parallel/part_adaptation.hpp"

#include <algorithm>
#include <chrono>
#include <cstring>
#include <type_traits>
#include <unordered_set>

#include "base/memory_budget.hpp"
#include "base/stopwatch.hpp"

namespace hocav {
namespace {

// Every iteration's parts stop this many passes after their loop's window closes: what a part would
// do next to its frozen interface a later iteration (with that interface inside a part), or the last
// serial runs do better (docs/distributed.md).
constexpr int kEarlyPassesAfterWindowCloses = 2;

// Attribute columns of a part's vertices through a change: 0 for a new vertex, else the global id + 1
// and the pinned flags.
constexpr int kGlobalIdColumn = 0, kPinnedColumn = 1;

// What the part's vertices and interface edges were before its loop, by global ids: its corners and
// the feature lines on its interface edges (the whole mesh's; the loop's classification adds more).
struct TagsBefore {
  std::unordered_set<Index> corners;
  std::unordered_set<std::uint64_t> interface_lines;
};

template <int D>
std::uint64_t global_edge_key(const MeshPart<D>& part, const typename Mesh<D>::Line& line) {
  return Mesh<D>::edge_key(part.global_ids[line[0]], part.global_ids[line[1]]);
}

template <int D>
TagsBefore tags_before(const MeshPart<D>& part) {
  TagsBefore before;
  for (Index v : part.mesh.corners()) before.corners.insert(part.global_ids[v]);
  const std::unordered_set<std::uint64_t> edges = interface_edge_keys(part.mesh);
  for (Index l = 0; l < part.mesh.line_count(); ++l)
    if (edges.contains(Mesh<D>::edge_key(part.mesh.line(l)[0], part.mesh.line(l)[1])))
      before.interface_lines.insert(global_edge_key(part, part.mesh.line(l)));
  return before;
}

// Drops the corners of old vertices and the lines on interface edges that were not there before.
template <int D>
void drop_interface_tags(MeshPart<D>& part, const TagsBefore& before) {
  std::erase_if(part.mesh.corners(),
                [&](Index v) { return part.global_ids[v] != kNoIndex && !before.corners.contains(part.global_ids[v]); });
  const std::unordered_set<std::uint64_t> edges = interface_edge_keys(part.mesh);
  bool dropped = false;
  for (Index l = 0; l < part.mesh.line_count(); ++l) {
    const auto& line = part.mesh.line(l);
    if (edges.contains(Mesh<D>::edge_key(line[0], line[1])) && !before.interface_lines.contains(global_edge_key(part, line))) {
      part.mesh.remove_line(l);
      dropped = true;
    }
  }
  if (dropped) part.mesh.compact();  // no vertex is removed: the vertex ids stay
}

// Adapts one part with its interfaces frozen (required facets and vertices); its global ids and
// pinned flags follow the vertices through the loop.
template <int D>
AdaptationRun adapt_part(MeshPart<D>& part, const AdaptationMetric<D>& metric, const BoundaryGeometry<D>* geometry,
                         const AdaptationSettings& settings) {
  if (part.mesh.element_count() == 0) return {};
  const TagsBefore before = tags_before(part);
  AdaptationRun run;
  change_keeping_global_ids<D>(part, [&](Mesh<D>& mesh) {
    if (!mesh.has_topology()) mesh.build_topology();  // a part from migrate_part has it
    run = adapt_to_metric(mesh, metric, geometry, settings);
  });
  drop_interface_tags(part, before);
  return run;
}

}  // namespace

template <int D>
void change_keeping_global_ids(MeshPart<D>& part, const std::function<void(Mesh<D>&)>& change) {
  const bool pinned = !part.pinned.empty();
  const int attribute = part.mesh.add_vertex_attribute(2);
  for (Index v = 0; v < part.mesh.vertex_count(); ++v) {
    part.mesh.vertex_attribute(attribute, v)[kGlobalIdColumn] = part.global_ids[v] + 1.0;
    part.mesh.vertex_attribute(attribute, v)[kPinnedColumn] = pinned ? part.pinned[v] : 0;
  }
  change(part.mesh);
  part.global_ids.resize(static_cast<std::size_t>(part.mesh.vertex_count()));
  part.pinned.resize(pinned ? part.global_ids.size() : 0);
  for (Index v = 0; v < part.mesh.vertex_count(); ++v) {
    part.global_ids[v] = static_cast<Index>(part.mesh.vertex_attribute(attribute, v)[kGlobalIdColumn]) - 1;
    if (pinned) part.pinned[v] = static_cast<char>(part.mesh.vertex_attribute(attribute, v)[kPinnedColumn]);
  }
}

AdaptationSettings part_settings(const AdaptationSettings& settings) {
  AdaptationSettings part = settings;
  part.passes_after_window_closes = kEarlyPassesAfterWindowCloses;
  part.splits_at_required_vertices = SplitsAtRequiredVertices::kNextToFineRequiredFacets;
  part.ridges_from_shape = false;
  return part;
}

template <int D>
std::pair<AdaptationRun, PartFigures> adapt_part_measured(MeshPart<D>& part, const AdaptationMetric<D>& metric,
                                                          const BoundaryGeometry<D>* geometry, const AdaptationSettings& settings) {
  const auto start = std::chrono::steady_clock::now();
  AdaptationRun run = adapt_part(part, metric, geometry, settings);
  return {std::move(run), PartFigures{seconds_since(start), peak_resident_bytes()}};
}

template <int D>
BoundarySettling settle_part_boundary(MeshPart<D>& part, std::span<const SymMat<D>> metrics, const BoundaryGeometry<D>& geometry,
                                      double feature_angle_degrees) {
  if (part.mesh.element_count() == 0) return {};
  const TagsBefore before = tags_before(part);
  const BoundarySettling settling = settle_boundary(part.mesh, metrics, geometry, feature_angle_degrees);
  drop_interface_tags(part, before);
  return settling;
}

static_assert(std::is_trivially_copyable_v<AdaptationPass>);

// The passes, the caps removed, then the two flags.
std::vector<std::byte> pack_run(const AdaptationRun& run) {
  const std::size_t passes = run.passes.size() * sizeof(AdaptationPass);
  std::vector<std::byte> bytes(passes + sizeof(Index) + 2);
  if (!run.passes.empty()) std::memcpy(bytes.data(), run.passes.data(), passes);
  std::memcpy(bytes.data() + passes, &run.caps_removed, sizeof(Index));
  bytes[bytes.size() - 2] = std::byte{run.converged};
  bytes[bytes.size() - 1] = std::byte{run.stopped_with_window_open};
  return bytes;
}

AdaptationRun unpack_run(const std::vector<std::byte>& bytes) {
  AdaptationRun run;
  run.passes.resize((bytes.size() - 2 - sizeof(Index)) / sizeof(AdaptationPass));
  const std::size_t passes = run.passes.size() * sizeof(AdaptationPass);
  if (!run.passes.empty()) std::memcpy(run.passes.data(), bytes.data(), passes);
  std::memcpy(&run.caps_removed, bytes.data() + passes, sizeof(Index));
  run.converged = bytes[bytes.size() - 2] != std::byte{0};
  run.stopped_with_window_open = bytes[bytes.size() - 1] != std::byte{0};
  return run;
}

AdaptationRun combined(const std::vector<AdaptationRun>& runs) {
  AdaptationRun out;
  out.converged = true;
  for (const AdaptationRun& run : runs) {
    if (run.passes.size() > out.passes.size()) out.passes.resize(run.passes.size());
    out.converged = out.converged && run.converged;
    out.stopped_with_window_open = out.stopped_with_window_open || run.stopped_with_window_open;
    out.caps_removed += run.caps_removed;
    for (std::size_t i = 0; i < run.passes.size(); ++i) {
      AdaptationPass& sum = out.passes[i];
      const AdaptationPass& pass = run.passes[i];
      sum.collapses += pass.collapses;
      sum.splits += pass.splits;
      sum.swaps += pass.swaps;
      sum.moves += pass.moves;
      sum.vertices += pass.vertices;
      sum.elements += pass.elements;
      sum.settled += pass.settled;
      sum.partly_settled += pass.partly_settled;
      sum.window_open = sum.window_open || pass.window_open;
      sum.collapse_length_bound = std::max(sum.collapse_length_bound, pass.collapse_length_bound);
      for (auto seconds :
           {&AdaptationPass::seconds, &AdaptationPass::seconds_collapse, &AdaptationPass::seconds_swap, &AdaptationPass::seconds_split,
            &AdaptationPass::seconds_smooth, &AdaptationPass::seconds_compact, &AdaptationPass::seconds_settle})
        sum.*seconds = std::max(sum.*seconds, pass.*seconds);
    }
  }
  return out;
}

template std::pair<AdaptationRun, PartFigures> adapt_part_measured(MeshPart<2>&, const AdaptationMetric<2>&, const BoundaryGeometry<2>*,
                                                                   const AdaptationSettings&);
template std::pair<AdaptationRun, PartFigures> adapt_part_measured(MeshPart<3>&, const AdaptationMetric<3>&, const BoundaryGeometry<3>*,
                                                                   const AdaptationSettings&);

template void change_keeping_global_ids(MeshPart<2>&, const std::function<void(Mesh<2>&)>&);
template void change_keeping_global_ids(MeshPart<3>&, const std::function<void(Mesh<3>&)>&);

template BoundarySettling settle_part_boundary(MeshPart<2>&, std::span<const SymMat<2>>, const BoundaryGeometry<2>&, double);
template BoundarySettling settle_part_boundary(MeshPart<3>&, std::span<const SymMat<3>>, const BoundaryGeometry<3>&, double);

}  // namespace hocav
