#include "parallel/field_with_neighbours.hpp"

#include <memory>
#include <unordered_map>

#include "parallel/byte_stream.hpp"
#include "parallel/communicator.hpp"
#include "parallel/face_key.hpp"

namespace hocav {
namespace {

struct Holder {
  Index id;  // a vertex's global id
  int process;
};

// Collective: per vertex of the part on one of its interfaces, the other processes that hold it:
// the holders tell its global id where it hashes to, and hear there of each other.
template <int D>
std::unordered_map<Index, std::vector<int>> other_holders(const MeshPart<D>& part) {
  const auto count = static_cast<std::size_t>(process_count());
  const std::vector<char> on_interface = interface_vertex_flags(part.mesh);
  std::vector<std::vector<Index>> told(count);
  for (Index v = 0; v < part.mesh.vertex_count(); ++v)
    if (on_interface[v])
      told[static_cast<std::size_t>(vertex_meeting_process(part.global_ids[v], process_count()))].push_back(part.global_ids[v]);
  const std::vector<std::vector<Index>> arrived = exchange_values(told);
  std::unordered_map<Index, std::vector<int>> holders;
  for (std::size_t r = 0; r < count; ++r)
    for (Index id : arrived[r]) holders[id].push_back(static_cast<int>(r));
  std::vector<std::vector<Holder>> answers(count);
  for (std::size_t r = 0; r < count; ++r)
    for (Index id : arrived[r])
      for (int other : holders.at(id))
        if (other != static_cast<int>(r)) answers[r].push_back({id, other});
  const std::unordered_map<Index, Index> local = local_ids_of(part);
  std::unordered_map<Index, std::vector<int>> others;
  for (const Holder& holder : exchange_values_joined(answers)) others[local.at(holder.id)].push_back(holder.process);
  return others;
}

// Per process, the part's elements with a vertex it holds too, each once.
template <int D>
std::vector<std::vector<Index>> elements_by_neighbour(const MeshPart<D>& part) {
  const std::unordered_map<Index, std::vector<int>> others = other_holders(part);
  std::vector<std::vector<Index>> elements(static_cast<std::size_t>(process_count()));
  for (Index k = 0; k < part.mesh.element_count(); ++k)
    for (Index v : part.mesh.element(k))
      if (const auto found = others.find(v); found != others.end())
        for (int p : found->second)
          if (elements[static_cast<std::size_t>(p)].empty() || elements[static_cast<std::size_t>(p)].back() != k)
            elements[static_cast<std::size_t>(p)].push_back(k);
  return elements;
}

// A process's message: its `elements` by their vertices' global ids, then those vertices' global
// ids, points and log-metrics.
template <int D>
std::vector<std::byte> ring_message(const MeshPart<D>& part, const std::vector<SymMat<D>>& log_metrics,
                                    const std::vector<Index>& elements) {
  std::vector<Index> corners, ids;
  std::vector<Vec<D>> points;
  std::vector<SymMat<D>> logs;
  std::unordered_map<Index, char> sent;
  for (Index k : elements)
    for (Index v : part.mesh.element(k)) {
      corners.push_back(part.global_ids[v]);
      if (!sent.emplace(v, 1).second) continue;
      ids.push_back(part.global_ids[v]);
      points.push_back(part.mesh.vertex(v));
      logs.push_back(log_metrics[static_cast<std::size_t>(v)]);
    }
  ByteWriter out;
  out.put(corners), out.put(ids), out.put(points), out.put(logs);
  return std::move(out.bytes);
}

}  // namespace

template <int D>
MetricField<D> field_with_neighbours(const MeshPart<D>& part, const std::vector<SymMat<D>>& log_metrics, long long& bytes_sent) {
  const std::vector<std::vector<Index>> elements = elements_by_neighbour(part);
  std::vector<std::vector<std::byte>> outgoing(elements.size());
  for (std::size_t p = 0; p < elements.size(); ++p) {
    if (elements[p].empty()) continue;
    outgoing[p] = ring_message(part, log_metrics, elements[p]);
    bytes_sent += static_cast<long long>(outgoing[p].size());
  }
  auto back = std::make_shared<Mesh<D>>();
  std::vector<SymMat<D>> logs = log_metrics;
  std::unordered_map<Index, Index> local = local_ids_of(part);
  for (Index v = 0; v < part.mesh.vertex_count(); ++v) back->add_vertex(part.mesh.vertex(v));
  for (Index k = 0; k < part.mesh.element_count(); ++k) back->add_element(part.mesh.element(k));
  for (const std::vector<std::byte>& message : exchange_bytes(outgoing)) {
    if (message.empty()) continue;  // (from a process with no element here)
    ByteReader in(message);
    const std::vector<Index> corners = in.take<Index>(), ids = in.take<Index>();
    const std::vector<Vec<D>> points = in.take<Vec<D>>();
    const std::vector<SymMat<D>> vertex_logs = in.take<SymMat<D>>();
    for (std::size_t i = 0; i < ids.size(); ++i)
      if (local.emplace(ids[i], back->vertex_count()).second) {
        back->add_vertex(points.at(i));
        logs.push_back(vertex_logs.at(i));
      }
    for (std::size_t c = 0; c + D < corners.size(); c += D + 1) {
      typename Mesh<D>::Element element;
      for (int i = 0; i <= D; ++i) element[i] = local.at(corners[c + static_cast<std::size_t>(i)]);
      back->add_element(element);
    }
  }
  back->build_topology();
  return MetricField<D>::on_back_mesh(std::move(back), std::move(logs));
}

template MetricField<2> field_with_neighbours(const MeshPart<2>&, const std::vector<SymMat<2>>&, long long&);
template MetricField<3> field_with_neighbours(const MeshPart<3>&, const std::vector<SymMat<3>>&, long long&);

}  // namespace hocav
