#include "parallel/hessian_metric_runs.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <unordered_set>

#include "base/error.hpp"
#include "io/node_metrics.hpp"
#include "io/record_run.hpp"
#include "mesh/measure.hpp"
#include "mesh/vertex_graph.hpp"
#include "metric/hessian_recovery.hpp"
#include "parallel/communicator.hpp"
#include "parallel/metrics_by_global_id.hpp"

namespace hocav {
namespace {

// What a piece tells a vertex's process: its point and the summed measure of its elements there.
template <int D>
struct PieceVertex {
  Index id;
  Vec<D> point;
  double measure;
};

// A vertex's point and field value, as a stencil reads them.
template <int D>
struct Sample {
  Vec<D> point;
  double value;
};

// Neighbour lists as compressed rows, of a run of consecutive ids or of listed ids.
struct Lists {
  std::vector<Index> offsets{0}, entries;

  std::span<const Index> of(std::size_t i) const {
    return std::span<const Index>(entries).subspan(static_cast<std::size_t>(offsets[i]),
                                                   static_cast<std::size_t>(offsets[i + 1] - offsets[i]));
  }
  void add(std::span<const Index> list) {
    entries.insert(entries.end(), list.begin(), list.end());
    offsets.push_back(static_cast<Index>(entries.size()));
  }
};

// This process's run of the file's vertices, with what the pieces told it.
template <int D>
struct RunGraph {
  Index first = 0;
  std::vector<Vec<D>> points;
  std::vector<double> measures;
  std::vector<char> used;  // by an element
  Lists neighbours;        // ascending global ids, as vertex_graph's rows
};

int holder_of(Index id, Index vertex_count) { return slice_holding(id, vertex_count, process_count()); }

// Per process, the piece's vertex graph's rows (id, count, neighbours' ids) of the vertices of that
// process's run.
template <int D>
std::vector<std::vector<Index>> piece_rows(const MeshPart<D>& piece, Index vertex_count) {
  std::vector<std::vector<Index>> rows(static_cast<std::size_t>(process_count()));
  const VertexGraph graph = vertex_graph(piece.mesh);
  for (Index v = 0; v < piece.mesh.vertex_count(); ++v) {
    const Index id = piece.global_ids[static_cast<std::size_t>(v)];
    std::vector<Index>& row = rows[static_cast<std::size_t>(holder_of(id, vertex_count))];
    row.push_back(id);
    row.push_back(static_cast<Index>(graph.neighbors_of(v).size()));
    for (Index u : graph.neighbors_of(v)) row.push_back(piece.global_ids[static_cast<std::size_t>(u)]);
  }
  return rows;
}

// The rows (id, count, ids) that arrived for the run of vertices from `first`, joined per vertex.
Lists joined_rows(const std::vector<Index>& arrived, Index first, std::size_t size) {
  Lists lists;
  lists.offsets.assign(size + 1, 0);
  for (std::size_t at = 0; at < arrived.size(); at += static_cast<std::size_t>(arrived[at + 1]) + 2)
    lists.offsets[static_cast<std::size_t>(arrived[at] - first) + 1] += arrived[at + 1];
  for (std::size_t i = 0; i < size; ++i) lists.offsets[i + 1] += lists.offsets[i];
  lists.entries.resize(static_cast<std::size_t>(lists.offsets[size]));
  std::vector<Index> filled(lists.offsets.begin(), lists.offsets.end() - 1);
  for (std::size_t at = 0; at < arrived.size(); at += static_cast<std::size_t>(arrived[at + 1]) + 2) {
    const auto vertex = static_cast<std::size_t>(arrived[at] - first);
    for (Index k = 0; k < arrived[at + 1]; ++k)
      lists.entries[static_cast<std::size_t>(filled[vertex]++)] = arrived[at + 2 + static_cast<std::size_t>(k)];
  }
  return lists;
}

// Each list sorted and its repeats dropped, in place.
void sort_unique_in_place(Lists& lists) {
  const std::size_t size = lists.offsets.size() - 1;
  Index kept = 0;
  for (std::size_t i = 0; i < size; ++i) {
    Index* begin = lists.entries.data() + lists.offsets[i];
    Index* end = lists.entries.data() + lists.offsets[i + 1];
    std::sort(begin, end);
    end = std::unique(begin, end);
    lists.offsets[i] = kept;  // (offsets[i + 1] is read before it is overwritten)
    kept = static_cast<Index>(std::copy(begin, end, lists.entries.data() + kept) - lists.entries.data());
  }
  lists.offsets[size] = kept;
  lists.entries.resize(static_cast<std::size_t>(kept));
}

// Collective: the run's rows of the whole mesh's vertex graph: the pieces' rows of each vertex
// merged, ascending, each neighbour once.
template <int D>
Lists run_neighbours(const MeshPart<D>& piece, Index vertex_count, Index first, std::size_t size) {
  Lists lists = joined_rows(exchange_values_joined(piece_rows(piece, vertex_count)), first, size);
  sort_unique_in_place(lists);
  return lists;
}

// Collective: the run's points, measures and neighbours from every piece.
template <int D>
RunGraph<D> run_graph(const MeshPart<D>& piece, Index vertex_count) {
  const std::vector<double> measure = vertex_element_measures(piece.mesh);
  std::vector<std::vector<PieceVertex<D>>> vertices(static_cast<std::size_t>(process_count()));
  for (Index v = 0; v < piece.mesh.vertex_count(); ++v) {
    const Index id = piece.global_ids[static_cast<std::size_t>(v)];
    vertices[static_cast<std::size_t>(holder_of(id, vertex_count))].push_back(
        {id, piece.mesh.vertex(v), measure[static_cast<std::size_t>(v)]});
  }
  RunGraph<D> run;
  run.first = slice_start(vertex_count, process_rank(), process_count());
  const auto size = static_cast<std::size_t>(slice_start(vertex_count, process_rank() + 1, process_count()) - run.first);
  run.points.resize(size);
  run.measures.assign(size, 0.0);
  run.used.assign(size, 0);
  for (const PieceVertex<D>& vertex : exchange_values_joined(vertices)) {
    const auto i = static_cast<std::size_t>(vertex.id - run.first);
    run.points[i] = vertex.point;
    run.measures[i] += vertex.measure;
    run.used[i] = 1;
  }
  run.neighbours = run_neighbours(piece, vertex_count, run.first, size);
  return run;
}

// Collective: the neighbour lists of `ids` (ascending, unique), each asked of its run's process.
template <int D>
Lists lists_of(const std::vector<Index>& ids, const RunGraph<D>& run, Index vertex_count) {
  std::vector<std::vector<Index>> asked(static_cast<std::size_t>(process_count()));
  for (Index id : ids) asked[static_cast<std::size_t>(holder_of(id, vertex_count))].push_back(id);
  std::vector<std::vector<Index>> answers;
  for (const std::vector<Index>& wanted : exchange_values(asked)) {
    answers.emplace_back();
    for (Index id : wanted) {
      const std::span<const Index> list = run.neighbours.of(static_cast<std::size_t>(id - run.first));
      answers.back().push_back(static_cast<Index>(list.size()));
      answers.back().insert(answers.back().end(), list.begin(), list.end());
    }
  }
  const std::vector<std::vector<Index>> replies = exchange_values(answers);
  std::vector<std::size_t> next(replies.size(), 0);
  Lists lists;
  for (Index id : ids) {
    const auto p = static_cast<std::size_t>(holder_of(id, vertex_count));
    const auto length = static_cast<std::size_t>(replies[p][next[p]]);
    lists.add(std::span<const Index>(replies[p]).subspan(next[p] + 1, length));
    next[p] += length + 1;
  }
  return lists;
}

// A vertex not fitted yet, its stencil grown ring by ring as collect_rings grows it.
struct Stencil {
  std::size_t vertex;  // in the run
  std::vector<Index> ids;
  std::size_t ring_begin = 0;  // the last ring's first entry
};

std::vector<Index> ascending_unique(std::vector<Index> ids) {
  std::sort(ids.begin(), ids.end());
  ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
  return ids;
}

// Collective: every stencil grown by one ring, from its last ring's neighbour lists.
template <int D>
void grow_rings(std::vector<Stencil>& stencils, const RunGraph<D>& run, Index vertex_count) {
  std::vector<Index> frontier;
  for (const Stencil& s : stencils) frontier.insert(frontier.end(), s.ids.begin() + static_cast<std::ptrdiff_t>(s.ring_begin), s.ids.end());
  const std::vector<Index> ids = ascending_unique(std::move(frontier));
  const Lists lists = lists_of(ids, run, vertex_count);
  for (Stencil& s : stencils) {
    std::unordered_set<Index> seen(s.ids.begin(), s.ids.end());
    seen.insert(run.first + static_cast<Index>(s.vertex));
    const std::size_t ring_end = s.ids.size();
    for (std::size_t i = s.ring_begin; i < ring_end; ++i) {
      const auto place = static_cast<std::size_t>(std::lower_bound(ids.begin(), ids.end(), s.ids[i]) - ids.begin());
      for (Index w : lists.of(place))
        if (seen.insert(w).second) s.ids.push_back(w);
    }
    s.ring_begin = ring_end;
  }
}

// Collective: the samples of the `wanted` ids, each asked of its run's process, looked up by id.
template <int D>
class SampleTable {
 public:
  SampleTable(std::vector<Index> wanted, const std::vector<Sample<D>>& held, Index first) : ids_(ascending_unique(std::move(wanted))) {
    long long bytes_sent = 0;
    samples_ = values_by_global_id<Sample<D>>(ids_, first, held, bytes_sent);
  }

  // The fit at `at` on the stencil `ids` (fit_hessian).
  std::optional<SymMat<D>> fit(const Sample<D>& at, std::span<const Index> ids) {
    points_.clear();
    values_.clear();
    for (Index id : ids) {
      const Sample<D>& sample = samples_[static_cast<std::size_t>(std::lower_bound(ids_.begin(), ids_.end(), id) - ids_.begin())];
      points_.push_back(sample.point);
      values_.push_back(sample.value);
    }
    return fit_hessian<D>(at.point, at.value, points_, values_);
  }

 private:
  std::vector<Index> ids_;
  std::vector<Sample<D>> samples_;
  std::vector<Vec<D>> points_;  // a stencil's, reused
  std::vector<double> values_;
};

// Collective: recover_hessians' Hessians at the run's vertices, from the field's `values` there:
// the 1-ring's fit of every vertex, then the 2- and 3-ring's of the vertices left.
template <int D>
std::vector<SymMat<D>> recovered_hessians(const RunGraph<D>& run, const std::vector<double>& values, Index vertex_count,
                                          const std::string& path) {
  std::vector<Sample<D>> held;
  for (std::size_t i = 0; i < values.size(); ++i) held.push_back({run.points[i], values[i]});
  std::vector<SymMat<D>> hessians(values.size());
  std::vector<Stencil> left;
  SampleTable<D> ring_one(run.neighbours.entries, held, run.first);
  for (std::size_t i = 0; i < values.size(); ++i) {
    const std::optional<SymMat<D>> fitted = ring_one.fit(held[i], run.neighbours.of(i));
    if (fitted)
      hessians[i] = *fitted;
    else
      left.push_back({i, std::vector<Index>(run.neighbours.of(i).begin(), run.neighbours.of(i).end())});
  }
  for (int rings = 2; rings <= kHessianMaxRings && max_over_processes(static_cast<Index>(left.size())) > 0; ++rings) {
    grow_rings(left, run, vertex_count);
    std::vector<Index> wanted;
    for (const Stencil& s : left) wanted.insert(wanted.end(), s.ids.begin(), s.ids.end());
    SampleTable<D> table(std::move(wanted), held, run.first);
    std::erase_if(left, [&](const Stencil& s) {
      const std::optional<SymMat<D>> fitted = table.fit(held[s.vertex], s.ids);
      if (fitted) hessians[s.vertex] = *fitted;
      return fitted.has_value();
    });
  }
  if (!left.empty())
    throw Error(path + ": hessian recovery: the neighbours of vertex " +
                std::to_string(run.first + static_cast<Index>(left[0].vertex) + 1) + " within " + std::to_string(kHessianMaxRings) +
                " edges do not determine a quadratic");
  return hessians;
}

// Collective: the source's Hessians at the run's vertices: exact for an analytic field, else
// recovered from the field file's run.
template <int D>
std::vector<SymMat<D>> run_hessians(const RunGraph<D>& run, const HessianSource& source, Index vertex_count, const std::string& path) {
  if (is_analytic_field(source.field)) {
    const AnalyticFieldSpec shape = analytic_field_of(source);
    std::vector<SymMat<D>> hessians;
    for (const Vec<D>& x : run.points) hessians.push_back(analytic_field_hessian<D>(shape, x));
    return hessians;
  }
  const std::vector<double> values = read_scalar_run(source.field, D, vertex_count, RecordRun{process_rank(), process_count()});
  return recovered_hessians(run, values, vertex_count, path);
}

}  // namespace

template <int D>
VertexRunMetrics<D> hessian_metric_by_runs(const MeshPart<D>& piece, Index vertex_count, const HessianSource& source, double diagonal,
                                           const std::string& path) {
  const LpMetricOptions options = lp_options_of(source, diagonal);
  check_lp_options(options);
  const RunGraph<D> run = run_graph(piece, vertex_count);
  for (std::size_t i = 0; i < run.used.size(); ++i)
    if (!run.used[i])
      throw Error(path + ": hessian metric: vertex " + std::to_string(run.first + static_cast<Index>(i) + 1) +
                  " belongs to no element, so it has no metric");
  const std::vector<SymMat<D>> hessians = run_hessians(run, source, vertex_count, path);
  VertexRunMetrics<D> out{run.first, {}, run.measures};
  double integral = 0;  // of the density, this run's share (vertex_volumes' weights)
  for (std::size_t i = 0; i < hessians.size(); ++i) {
    const LpVertex<D> vertex = lp_vertex(hessians[i], options, run.first + static_cast<Index>(i) + 1);
    out.metrics.push_back(vertex.metric);
    integral += run.measures[i] / (D + 1) * vertex.density;
  }
  const double scale = lp_scale<D>(options, sum_over_processes(integral));
  for (SymMat<D>& metric : out.metrics) metric *= scale;
  return out;
}

template VertexRunMetrics<2> hessian_metric_by_runs(const MeshPart<2>&, Index, const HessianSource&, double, const std::string&);
template VertexRunMetrics<3> hessian_metric_by_runs(const MeshPart<3>&, Index, const HessianSource&, double, const std::string&);

}  // namespace hocav
