#include "parallel/distributed_gradation.hpp"

#include <unordered_map>

#include "adapt/hausdorff_metric.hpp"
#include "parallel/communicator.hpp"
#include "parallel/face_key.hpp"

namespace hocav {
namespace {

// A copy of an interface vertex's metric, by its global id.
template <int D>
struct VertexCopy {
  Index id;
  SymMat<D> metric;
};

// At a meeting process: per sender, the intersection of every copy of each vertex it sent, the
// copies taken in rank order.
template <int D>
std::vector<std::vector<SymMat<D>>> met_copies(const std::vector<std::vector<VertexCopy<D>>>& arrived) {
  std::unordered_map<Index, SymMat<D>> met;
  for (const std::vector<VertexCopy<D>>& copies : arrived)
    for (const VertexCopy<D>& copy : copies)
      if (const auto [at, added] = met.try_emplace(copy.id, copy.metric); !added) at->second = within_bound(at->second, copy.metric);
  std::vector<std::vector<SymMat<D>>> answers(arrived.size());
  for (std::size_t from = 0; from < arrived.size(); ++from)
    for (const VertexCopy<D>& copy : arrived[from]) answers[from].push_back(met.at(copy.id));
  return answers;
}

// One meeting of the interface vertices' copies (`shared`: their local ids): each takes the
// intersection of all. Returns whether any of this process's changed.
template <int D>
bool meet_interface_copies(const MeshPart<D>& piece, const std::vector<Index>& shared, std::vector<SymMat<D>>& metrics) {
  std::vector<std::vector<VertexCopy<D>>> outgoing(static_cast<std::size_t>(process_count()));
  for (Index v : shared) {
    const Index id = piece.global_ids[v];
    outgoing[static_cast<std::size_t>(vertex_meeting_process(id, process_count()))].push_back({id, metrics[v]});
  }
  const std::vector<std::vector<SymMat<D>>> answers = exchange_values(met_copies(exchange_values(outgoing)));
  std::vector<std::size_t> next(answers.size(), 0);
  bool changed = false;
  for (Index v : shared) {
    const auto meeting = static_cast<std::size_t>(vertex_meeting_process(piece.global_ids[v], process_count()));
    const SymMat<D>& met = answers[meeting][next[meeting]++];
    changed |= met != metrics[v];
    metrics[v] = met;
  }
  return changed;
}

}  // namespace

template <int D>
int grade_piece_metrics(const MeshPart<D>& piece, std::vector<SymMat<D>>& metrics, const GradationOptions& options) {
  const std::vector<char> on_interface = interface_vertex_flags(piece.mesh);
  std::vector<Index> shared;
  for (Index v = 0; v < piece.mesh.vertex_count(); ++v)
    if (on_interface[v]) shared.push_back(v);
  for (int round = 1;; ++round) {
    grade_metrics(piece.mesh, metrics, options);
    if (max_over_processes(static_cast<int>(meet_interface_copies(piece, shared, metrics))) == 0) return round;
  }
}

template int grade_piece_metrics(const MeshPart<2>&, std::vector<SymMat<2>>&, const GradationOptions&);
template int grade_piece_metrics(const MeshPart<3>&, std::vector<SymMat<3>>&, const GradationOptions&);

}  // namespace hocav
