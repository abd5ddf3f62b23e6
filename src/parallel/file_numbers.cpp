#include "parallel/file_numbers.hpp"

#include <algorithm>
#include <cstdint>

#include "base/error.hpp"
#include "base/index.hpp"
#include "io/record_run.hpp"
#include "parallel/communicator.hpp"
#include "parallel/entity_tags.hpp"

namespace hocav {
namespace {

// What the process of a vertex's run answers: the vertex's file number, and whether another part
// holds it.
struct VertexNumber {
  Index number;
  std::int32_t shared;
};

// An edge (P2 node) or a feature line that several parts may hold, on its way to the process its
// ends' global ids hash to.
template <int D>
struct SharedEdge {
  FaceKey<2> key;  // the sorted global ids of its ends
  Vec<D> node;     // an edge's P2 node
  LineRow line;    // a line's row
};

// Where an arrived record lies: its sender and its place in the sender's message.
struct Arrival {
  int from;
  std::size_t at;
};

// The records that arrived, grouped by key: `order` sorted by key, rank order within a key, and
// group g is order[starts[g], starts[g + 1]).
struct ArrivalGroups {
  std::vector<Arrival> order;
  std::vector<std::size_t> starts;
  std::size_t count() const { return starts.size() - 1; }
};

template <class Record, class KeyOf>
ArrivalGroups grouped(const std::vector<std::vector<Record>>& arrived, KeyOf key_of) {
  ArrivalGroups groups;
  for (std::size_t from = 0; from < arrived.size(); ++from)
    for (std::size_t at = 0; at < arrived[from].size(); ++at) groups.order.push_back({static_cast<int>(from), at});
  const auto key = [&](const Arrival& a) { return key_of(arrived[static_cast<std::size_t>(a.from)][a.at]); };
  std::stable_sort(groups.order.begin(), groups.order.end(), [&](const Arrival& a, const Arrival& b) { return key(a) < key(b); });
  for (std::size_t i = 0; i < groups.order.size(); ++i)
    if (i == 0 || key(groups.order[i - 1]) < key(groups.order[i])) groups.starts.push_back(i);
  groups.starts.push_back(groups.order.size());
  return groups;
}

// Empty answers shaped as the messages that arrived, one per record.
template <class Answer, class Record>
std::vector<std::vector<Answer>> answers_for(const std::vector<std::vector<Record>>& arrived) {
  std::vector<std::vector<Answer>> answers(arrived.size());
  for (std::size_t from = 0; from < arrived.size(); ++from) answers[from].resize(arrived[from].size());
  return answers;
}

}  // namespace

template <int D>
FileNumbers<D>::FileNumbers(const std::string& path, const MeshPart<D>& part) : path_(path), part_(part) {
  if (part.global_ids.size() != static_cast<std::size_t>(part.mesh.vertex_count()) ||
      part.pinned.size() != static_cast<std::size_t>(part.mesh.vertex_count()) || !part.mesh.is_compact())
    throw std::logic_error("FileNumbers: a part without global ids or pinned flags, or not compact");
  number_vertices();
  p2_ = sum_over_processes(static_cast<int>(part.mesh.is_p2())) > 0;
  if (p2_) number_nodes();
}

// Every vertex to the process of its run of global ids, which numbers the vertices it gets in id
// order (after the runs before it) and answers each part its numbers.
template <int D>
void FileNumbers<D>::number_vertices() {
  const Mesh<D>& mesh = part_.mesh;
  const Index id_space = max_over_processes(
      part_.global_ids.empty() ? Index{0} : *std::max_element(part_.global_ids.begin(), part_.global_ids.end()) + 1);
  const EntityTags<D> tags(mesh);
  std::vector<std::vector<VertexToRun<D>>> outgoing(static_cast<std::size_t>(process_count()));
  std::vector<std::vector<Index>> sent(outgoing.size());  // the part's vertices, as sent to each process
  for (Index v = 0; v < mesh.vertex_count(); ++v) {
    const auto run = static_cast<std::size_t>(slice_holding(part_.global_ids[v], id_space, process_count()));
    const char flags = static_cast<char>((tags.corner[v] ? kCornerFlag : 0) | ((part_.pinned[v] & kPinnedByMesh) ? kRequiredFlag : 0));
    outgoing[run].push_back({part_.global_ids[v], mesh.vertex(v), mesh.vertex_ref(v), flags});
    sent[run].push_back(v);
  }
  const std::vector<std::vector<VertexToRun<D>>> arrived = exchange_values(outgoing);
  const ArrivalGroups groups = grouped(arrived, [](const VertexToRun<D>& r) { return r.id; });
  const CountOffset offset = offset_over_processes(static_cast<Index>(groups.count()));
  vertex_count_ = offset.total;
  first_vertex_ = offset.before;
  std::vector<std::vector<VertexNumber>> answers = answers_for<VertexNumber>(arrived);
  for (std::size_t g = 0; g < groups.count(); ++g) {
    const Arrival first = groups.order[groups.starts[g]];
    VertexToRun<D> row = arrived[static_cast<std::size_t>(first.from)][first.at];
    for (std::size_t i = groups.starts[g]; i < groups.starts[g + 1]; ++i) {
      const VertexToRun<D>& other = arrived[static_cast<std::size_t>(groups.order[i].from)][groups.order[i].at];
      if (!(other.point == row.point))
        throw Error(path_ + ": vertex " + one_based(row.id) + " has different points in two parts of the distributed mesh");
      row.flags = static_cast<char>(row.flags | other.flags);
      answers[static_cast<std::size_t>(groups.order[i].from)][groups.order[i].at] = {offset.before + static_cast<Index>(g),
                                                                                     groups.starts[g + 1] - groups.starts[g] > 1};
    }
    vertex_rows_.push_back(row);
  }
  number_.assign(static_cast<std::size_t>(mesh.vertex_count()), kNoIndex);
  shared_.assign(number_.size(), 0);
  const std::vector<std::vector<VertexNumber>> numbers = exchange_values(answers);
  for (std::size_t run = 0; run < sent.size(); ++run)
    for (std::size_t i = 0; i < sent[run].size(); ++i) {
      number_[sent[run][i]] = numbers[run].at(i).number;
      shared_[sent[run][i]] = static_cast<char>(numbers[run].at(i).shared);
    }
}

// A P2 mesh's nodes: an edge with both ends shared may lie in several parts, and goes to the
// process its ends hash to, which numbers it once (after that process's other edges); every other
// edge is its part's own.
template <int D>
void FileNumbers<D>::number_nodes() {
  const Mesh<D>& mesh = part_.mesh;
  std::vector<std::vector<SharedEdge<D>>> outgoing(static_cast<std::size_t>(process_count()));
  std::vector<std::vector<Index>> sent(outgoing.size());
  for (Index e = 0; e < mesh.edge_count(); ++e) {
    const auto [a, b] = mesh.edge_vertices(e);
    if (!shared_edge(a, b)) {
      written_nodes_.push_back(mesh.edge_node(e));
      continue;
    }
    const FaceKey<2> key = edge_key(a, b);
    const auto to = static_cast<std::size_t>(meeting_process<2>(key, process_count()));
    outgoing[to].push_back({key, mesh.edge_node(e), {}});
    sent[to].push_back(e);
  }
  const Index own = static_cast<Index>(written_nodes_.size());
  const std::vector<std::vector<SharedEdge<D>>> arrived = exchange_values(outgoing);
  const ArrivalGroups groups = grouped(arrived, [](const SharedEdge<D>& r) { return r.key; });
  const CountOffset offset = offset_over_processes(own + static_cast<Index>(groups.count()));
  node_count_ = offset.total;
  first_node_ = vertex_count_ + offset.before;
  node_number_.assign(static_cast<std::size_t>(mesh.edge_count()), kNoIndex);
  Index next = first_node_;
  for (Index e = 0; e < mesh.edge_count(); ++e)
    if (const auto [a, b] = mesh.edge_vertices(e); !shared_edge(a, b)) node_number_[e] = next++;
  std::vector<std::vector<Index>> answers = answers_for<Index>(arrived);
  for (std::size_t g = 0; g < groups.count(); ++g) {
    const Arrival head = groups.order[groups.starts[g]];
    const SharedEdge<D>& edge = arrived[static_cast<std::size_t>(head.from)][head.at];
    for (std::size_t i = groups.starts[g]; i < groups.starts[g + 1]; ++i) {
      const SharedEdge<D>& other = arrived[static_cast<std::size_t>(groups.order[i].from)][groups.order[i].at];
      if (!(other.node == edge.node))
        throw Error(path_ + ": edge (" + one_based(edge.key[0]) + ", " + one_based(edge.key[1]) +
                    ") has different P2 nodes in two parts of the distributed mesh");
      answers[static_cast<std::size_t>(groups.order[i].from)][groups.order[i].at] = next;
    }
    written_nodes_.push_back(edge.node);
    ++next;
  }
  const std::vector<std::vector<Index>> numbers = exchange_values(answers);
  for (std::size_t to = 0; to < sent.size(); ++to)
    for (std::size_t i = 0; i < sent[to].size(); ++i) node_number_[sent[to][i]] = numbers[to].at(i);
}

template <int D>
std::vector<LineRow> FileNumbers<D>::lines_once(std::span<const Index> line_order) const {
  if constexpr (D == 2) return {};  // a 2D mesh's feature lines are its facets
  const Mesh<D>& mesh = part_.mesh;
  const EntityTags<D> tags(mesh);
  std::vector<LineRow> rows;
  std::vector<std::vector<SharedEdge<D>>> outgoing(static_cast<std::size_t>(process_count()));
  for (Index l = 0; l < mesh.line_count(); ++l) {
    const auto [a, b] = mesh.line(l);
    const char flags = static_cast<char>((tags.ridge_line[l] ? kRidgeFlag : 0) | (tags.required_line[l] ? kRequiredFlag : 0));
    const LineRow row{line_order.empty() ? kNoIndex : line_order[static_cast<std::size_t>(l)], mesh.line_ref(l), flags,
                      simplex(mesh.line(l))};
    if (!shared_edge(a, b)) {
      rows.push_back(row);
      continue;
    }
    const FaceKey<2> key = edge_key(a, b);
    outgoing[static_cast<std::size_t>(meeting_process<2>(key, process_count()))].push_back({key, {}, row});
  }
  const std::vector<std::vector<SharedEdge<D>>> arrived = exchange_values(outgoing);
  const ArrivalGroups groups = grouped(arrived, [](const SharedEdge<D>& r) { return r.key; });
  for (std::size_t g = 0; g < groups.count(); ++g) {
    const Arrival head = groups.order[groups.starts[g]];
    rows.push_back(arrived[static_cast<std::size_t>(head.from)][head.at].line);
  }
  return rows;
}

template class FileNumbers<2>;
template class FileNumbers<3>;

}  // namespace hocav
