#include "parallel/implied_metric_runs.hpp"

#include <algorithm>
#include <string>

#include "base/error.hpp"
#include "io/gamma_mesh.hpp"
#include "io/record_run.hpp"
#include "metric/implied_metric.hpp"
#include "parallel/communicator.hpp"

namespace hocav {
namespace {

// A piece's sum of a vertex's element shares, sent to the vertex's process.
template <int D>
struct VertexSum {
  Index vertex;         // its global id
  std::int32_t shares;  // how many elements gave one
  ImpliedShare<D> sum;
};

// One element's share of a vertex's metric, for a vertex whose elements lie in several pieces.
template <int D>
struct ElementShare {
  Index vertex, element;  // global id, file id
  ImpliedShare<D> share;
};

// The piece's elements' global numbers start here: the runs of elements are in rank order.
template <int D>
Index first_element_of(const MeshPart<D>& piece) {
  Index first = 0;
  const std::vector<Index> counts = all_gather_value(piece.mesh.element_count());
  for (int r = 0; r < process_rank(); ++r) first += counts[r];
  return first;
}

template <int D>
ImpliedShare<D> share_of(const MeshPart<D>& piece, Index k, Index first_element, const std::string& path) {
  try {
    return implied_share(piece.mesh, k, first_element + k + 1);
  } catch (const Error& error) {
    throw Error(path + ": " + error.what());
  }
}

// Per process, the piece's sums of the vertices that process's run holds.
template <int D>
std::vector<std::vector<VertexSum<D>>> piece_sums(const MeshPart<D>& piece, Index vertex_count, Index first_element,
                                                  const std::string& path) {
  std::vector<VertexSum<D>> sums(piece.global_ids.size());
  for (std::size_t v = 0; v < sums.size(); ++v) sums[v] = {piece.global_ids[v], 0, {}};
  for (Index k = 0; k < piece.mesh.element_count(); ++k) {
    const ImpliedShare<D> share = share_of(piece, k, first_element, path);
    for (Index v : piece.mesh.element(k)) {
      sums[v].sum += share;
      ++sums[v].shares;
    }
  }
  std::vector<std::vector<VertexSum<D>>> outgoing(static_cast<std::size_t>(process_count()));
  for (const VertexSum<D>& sum : sums) outgoing[slice_holding(sum.vertex, vertex_count, process_count())].push_back(sum);
  return outgoing;
}

// Every process at once: the element shares of the vertices in `asked` (per process, the global ids
// it asks this piece for), sent to the processes that asked.
template <int D>
std::vector<ElementShare<D>> element_shares(const MeshPart<D>& piece, const std::vector<std::vector<Index>>& asked, Index vertex_count,
                                            Index first_element, const std::string& path) {
  std::vector<char> wanted(piece.global_ids.size(), 0);
  for (const std::vector<Index>& ids : asked)
    for (Index id : ids)
      wanted[static_cast<std::size_t>(std::lower_bound(piece.global_ids.begin(), piece.global_ids.end(), id) - piece.global_ids.begin())] =
          1;
  std::vector<std::vector<ElementShare<D>>> outgoing(asked.size());
  for (Index k = 0; k < piece.mesh.element_count(); ++k) {
    const auto& element = piece.mesh.element(k);
    if (std::none_of(element.begin(), element.end(), [&](Index v) { return wanted[v] != 0; })) continue;
    const ImpliedShare<D> share = share_of(piece, k, first_element, path);
    for (Index v : element)
      if (wanted[v]) {
        const Index id = piece.global_ids[v];
        outgoing[slice_holding(id, vertex_count, process_count())].push_back({id, first_element + k, share});
      }
  }
  return exchange_values_joined(outgoing);
}

// What this process's run of vertices got from the pieces: per vertex the sum of its shares and the
// number of pieces that gave one, and per piece the vertices it gave sums for.
template <int D>
struct RunSums {
  std::vector<ImpliedShare<D>> sums;
  std::vector<int> pieces;
  std::vector<std::vector<Index>> given;  // per process
};

template <int D>
RunSums<D> run_sums(const MeshPart<D>& piece, Index first, std::size_t size, Index vertex_count, Index first_element,
                    const std::string& path) {
  RunSums<D> run{std::vector<ImpliedShare<D>>(size), std::vector<int>(size, 0), {}};
  for (const std::vector<VertexSum<D>>& given : exchange_values(piece_sums(piece, vertex_count, first_element, path))) {
    run.given.emplace_back();
    for (const VertexSum<D>& sum : given) {
      run.sums[sum.vertex - first] = sum.sum;
      ++run.pieces[sum.vertex - first];
      run.given.back().push_back(sum.vertex);
    }
  }
  return run;
}

// Every process at once: the sums of the run's vertices of several pieces made again from their
// shares element by element, in the file's order, as the serial sum runs.
template <int D>
void sum_in_file_order(RunSums<D>& run, const MeshPart<D>& piece, Index first, Index vertex_count, Index first_element,
                       const std::string& path) {
  std::vector<std::vector<Index>> ask(run.given.size());
  for (std::size_t p = 0; p < run.given.size(); ++p)
    for (Index vertex : run.given[p])
      if (run.pieces[vertex - first] > 1) ask[p].push_back(vertex);
  std::vector<ElementShare<D>> shares = element_shares(piece, exchange_values(ask), vertex_count, first_element, path);
  std::sort(shares.begin(), shares.end(), [](const ElementShare<D>& a, const ElementShare<D>& b) {
    return a.vertex != b.vertex ? a.vertex < b.vertex : a.element < b.element;
  });
  for (const ElementShare<D>& share : shares) run.sums[share.vertex - first] = {};
  for (const ElementShare<D>& share : shares) run.sums[share.vertex - first] += share.share;
}

}  // namespace

template <int D>
VertexRunMetrics<D> implied_metric_by_runs(const MeshPart<D>& piece, Index vertex_count, const std::string& path) {
  const Index first_element = first_element_of(piece);
  VertexRunMetrics<D> out;
  out.first = slice_start(vertex_count, process_rank(), process_count());
  const auto size = static_cast<std::size_t>(slice_start(vertex_count, process_rank() + 1, process_count()) - out.first);
  RunSums<D> run = run_sums(piece, out.first, size, vertex_count, first_element, path);
  sum_in_file_order(run, piece, out.first, vertex_count, first_element, path);
  for (std::size_t i = 0; i < size; ++i) {
    if (run.pieces[i] == 0)
      throw Error(path + ": implied metric: vertex " + std::to_string(out.first + static_cast<Index>(i) + 1) +
                  " belongs to no element, so it has no metric");
    out.metrics.push_back(implied_vertex_metric(run.sums[i]));
    out.measures.push_back(run.sums[i].weight);
  }
  return out;
}

template VertexRunMetrics<2> implied_metric_by_runs(const MeshPart<2>&, Index, const std::string&);
template VertexRunMetrics<3> implied_metric_by_runs(const MeshPart<3>&, Index, const std::string&);

}  // namespace hocav
