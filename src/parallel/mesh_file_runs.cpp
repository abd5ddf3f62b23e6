#include "parallel/mesh_file_runs.hpp"

#include <algorithm>
#include <cstdint>
#include <fstream>
#include <numeric>

#include "base/error.hpp"
#include "io/gamma_keyword_writer.hpp"
#include "io/gamma_keywords.hpp"
#include "io/gamma_mesh.hpp"
#include "io/record_run.hpp"
#include "mesh/simplex.hpp"
#include "parallel/communicator.hpp"
#include "parallel/entity_tags.hpp"
#include "parallel/face_key.hpp"
#include "parallel/file_in_runs.hpp"

namespace hocav {
namespace {

constexpr char kCornerFlag = 1, kRequiredFlag = 2, kRidgeFlag = 4;
// The places of an element order sent at once (docs/distributed.md §Writing in runs).
constexpr Index kElementWindow = Index{1} << 16;

// A vertex on its way to the process of its run of global ids.
template <int D>
struct VertexToRun {
  Index id;
  Vec<D> point;
  int ref;
  char flags;  // kCornerFlag, kRequiredFlag
};

// What that process answers: the vertex's file number (from 0), and whether another part holds it.
struct VertexNumber {
  Index number;
  std::int32_t shared;
};

// An element, facet or line on its way to the process of its run of places in the file (an
// order's).
template <std::size_t M>
struct PlacedRow {
  Index place;
  int ref;
  char flags;                    // a facet's or line's kRidgeFlag, kRequiredFlag
  std::array<Index, M> numbers;  // its vertices' file numbers, then its nodes' (P2; kNoIndex for P1)
};

// A line's row: its ends' file numbers in its order, then its P2 node's.
using LineRow = PlacedRow<3>;

// An edge (P2 node) or a feature line that several parts may hold, on its way to the process its
// ends' global ids hash to.
template <int D>
struct SharedEdge {
  FaceKey<2> key;  // the sorted global ids of its ends
  Vec<D> node;     // an edge's P2 node
  LineRow line;    // a line's row (its place kNoIndex without a line order)
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

// One process's records of one keyword, encoded as the file's format writes them.
class ChunkRecords {
 public:
  ChunkRecords(const std::string& path, bool binary, int version) : binary_(binary), binary_records_(path, version) {}

  void write_integer(std::int64_t value) { binary_ ? binary_records_.write_integer(value) : text_records_.write_integer(value); }
  void write_real(double value) { binary_ ? binary_records_.write_real(value) : text_records_.write_real(value); }
  void end_record() {
    text_records_.end_record();
    ++records_;
  }
  std::int64_t records() const { return records_; }
  const std::string& bytes() const { return binary_ ? binary_records_.bytes : text_records_.bytes; }

 private:
  bool binary_;
  gamma::BinaryRecords binary_records_;
  gamma::TextRecords text_records_;
  std::int64_t records_ = 0;
};

// A keyword of the file: its records, rank after rank in each of its runs (the vertices' keyword
// has two: the vertices, then a P2 file's nodes).
struct Keyword {
  int code, integers, reals;
  std::vector<const ChunkRecords*> runs;
};

template <int D>
class RunsWriter {
 public:
  RunsWriter(const std::string& path, const MeshPart<D>& part, bool binary, const EntityOrders& orders)
      : path_(path),
        part_(part),
        mesh_(part.mesh),
        binary_(binary),
        element_order_(orders.elements),
        facet_order_(orders.facets),
        line_order_(orders.lines) {
    if (part.global_ids.size() != static_cast<std::size_t>(mesh_.vertex_count()) ||
        part.pinned.size() != static_cast<std::size_t>(mesh_.vertex_count()) || !mesh_.is_compact())
      throw std::logic_error("write_mesh_runs: a part without global ids or pinned flags, or not compact");
    if (!element_order_.empty() && element_order_.size() != static_cast<std::size_t>(mesh_.element_count()))
      throw std::logic_error("write_mesh_runs: an element order that is not one place per element");
  }

  MeshFileCounts write(int requested_version) {
    number_vertices();
    const bool p2 = sum_over_processes(static_cast<int>(mesh_.is_p2())) > 0;
    if (p2) number_nodes();
    version_ = gamma::resolve_version(path_, requested_version, std::int64_t{counts_.vertices} + counts_.nodes, binary_ ? 3 : 2);
    const int order = p2 ? 2 : 1;
    encode_vertices();
    if (p2) encode_nodes();
    if constexpr (D == 3) encode_lines();
    encode_facets();
    encode_elements();
    std::vector<Keyword> keywords{{gamma::kVertices, 1, D, {&vertices_, &nodes_}}};
    if constexpr (D == 3) keywords.push_back(simplex_keyword(1, order, lines_));
    keywords.push_back(simplex_keyword(D - 1, order, facets_));
    keywords.push_back(simplex_keyword(D, order, element_runs_.front()));
    for (std::size_t run = 1; run < element_runs_.size(); ++run) keywords.back().runs.push_back(&element_runs_[run]);
    for (const auto& [code, records] : {std::pair{gamma::kCorners, &corners_},
                                        {gamma::kRidges, &ridges_},
                                        {gamma::kRequiredVertices, &required_vertices_},
                                        {gamma::kRequiredEdges, &required_edges_},
                                        {gamma::kRequiredTriangles, &required_triangles_}})
      keywords.push_back({code, 1, 0, {records}});
    write_keywords(keywords);
    return counts_;
  }

 private:
  ChunkRecords records() const { return {path_, binary_, version_}; }

  static Keyword simplex_keyword(int simplex_dimension, int order, const ChunkRecords& records) {
    const gamma::SimplexKeyword& keyword = gamma::simplex_keyword(simplex_dimension, order);
    return {keyword.code, keyword.node_count + 1, 0, {&records}};
  }

  // Every vertex to the process of its run of global ids, which numbers the vertices it gets in id
  // order (after the runs before it) and answers each part its numbers.
  void number_vertices() {
    const Index id_space = max_over_processes(
        part_.global_ids.empty() ? Index{0} : *std::max_element(part_.global_ids.begin(), part_.global_ids.end()) + 1);
    const EntityTags<D> tags(mesh_);
    std::vector<std::vector<VertexToRun<D>>> outgoing(static_cast<std::size_t>(process_count()));
    std::vector<std::vector<Index>> sent(outgoing.size());  // the part's vertices, as sent to each process
    for (Index v = 0; v < mesh_.vertex_count(); ++v) {
      const auto run = static_cast<std::size_t>(slice_holding(part_.global_ids[v], id_space, process_count()));
      const char flags = static_cast<char>((tags.corner[v] ? kCornerFlag : 0) | ((part_.pinned[v] & kPinnedByMesh) ? kRequiredFlag : 0));
      outgoing[run].push_back({part_.global_ids[v], mesh_.vertex(v), mesh_.vertex_ref(v), flags});
      sent[run].push_back(v);
    }
    const std::vector<std::vector<VertexToRun<D>>> arrived = exchange_values(outgoing);
    const ArrivalGroups groups = grouped(arrived, [](const VertexToRun<D>& r) { return r.id; });
    const CountOffset offset = offset_over_processes(static_cast<Index>(groups.count()));
    counts_.vertices = offset.total;
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
    number_.assign(static_cast<std::size_t>(mesh_.vertex_count()), kNoIndex);
    shared_.assign(number_.size(), 0);
    const std::vector<std::vector<VertexNumber>> numbers = exchange_values(answers);
    for (std::size_t run = 0; run < sent.size(); ++run)
      for (std::size_t i = 0; i < sent[run].size(); ++i) {
        number_[sent[run][i]] = numbers[run].at(i).number;
        shared_[sent[run][i]] = static_cast<char>(numbers[run].at(i).shared);
      }
  }

  bool shared_edge(Index a, Index b) const { return shared_[a] && shared_[b]; }
  FaceKey<2> edge_key(Index a, Index b) const { return sorted_key<2>({part_.global_ids[a], part_.global_ids[b]}); }

  // A P2 mesh's nodes: an edge with both ends shared may lie in several parts, and goes to the
  // process its ends hash to, which numbers it once (after that process's other edges); every other
  // edge is its part's own.
  void number_nodes() {
    std::vector<std::vector<SharedEdge<D>>> outgoing(static_cast<std::size_t>(process_count()));
    std::vector<std::vector<Index>> sent(outgoing.size());
    Index own = 0;
    for (Index e = 0; e < mesh_.edge_count(); ++e) {
      const auto [a, b] = mesh_.edge_vertices(e);
      if (!shared_edge(a, b)) {
        ++own;
        continue;
      }
      const FaceKey<2> key = edge_key(a, b);
      const auto to = static_cast<std::size_t>(meeting_process<2>(key, process_count()));
      outgoing[to].push_back({key, mesh_.edge_node(e), {}});
      sent[to].push_back(e);
    }
    const std::vector<std::vector<SharedEdge<D>>> arrived = exchange_values(outgoing);
    const ArrivalGroups groups = grouped(arrived, [](const SharedEdge<D>& r) { return r.key; });
    const CountOffset offset = offset_over_processes(own + static_cast<Index>(groups.count()));
    counts_.nodes = offset.total;
    const Index first = counts_.vertices + offset.before;  // this process's first node
    node_number_.assign(static_cast<std::size_t>(mesh_.edge_count()), kNoIndex);
    Index next = first;
    for (Index e = 0; e < mesh_.edge_count(); ++e)
      if (const auto [a, b] = mesh_.edge_vertices(e); !shared_edge(a, b)) node_number_[e] = next++;
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
      shared_nodes_.push_back(edge.node);
      ++next;
    }
    const std::vector<std::vector<Index>> numbers = exchange_values(answers);
    for (std::size_t to = 0; to < sent.size(); ++to)
      for (std::size_t i = 0; i < sent[to].size(); ++i) node_number_[sent[to][i]] = numbers[to].at(i);
  }

  void write_point(ChunkRecords& out, const Vec<D>& point, int ref) const {
    for (int i = 0; i < D; ++i) out.write_real(point[i]);
    out.write_integer(ref);
    out.end_record();
  }

  void encode_vertices() {
    vertices_ = corners_ = required_vertices_ = records();
    for (const VertexToRun<D>& row : vertex_rows_) write_point(vertices_, row.point, row.ref);
    Index next = first_vertex_;
    for (const VertexToRun<D>& row : vertex_rows_) {
      if (row.flags & kCornerFlag) write_id(corners_, next);
      if (row.flags & kRequiredFlag) write_id(required_vertices_, next);
      ++next;
    }
  }

  void encode_nodes() {
    nodes_ = records();
    for (Index e = 0; e < mesh_.edge_count(); ++e)
      if (const auto [a, b] = mesh_.edge_vertices(e); !shared_edge(a, b)) write_point(nodes_, mesh_.edge_node(e), 0);
    for (const Vec<D>& node : shared_nodes_) write_point(nodes_, node, 0);
  }

  static void write_id(ChunkRecords& out, Index id) {
    out.write_integer(std::int64_t{id} + 1);
    out.end_record();
  }

  // An entity's file numbers (from 0): its vertices', then its edges' nodes' (P2, in the local edge
  // order of a simplex of its dimension; kNoIndex for P1).
  template <std::size_t N>
  std::array<Index, N + N*(N - 1) / 2> simplex_numbers(const std::array<Index, N>& vertices) const {
    std::array<Index, N + N*(N - 1) / 2> numbers;
    numbers.fill(kNoIndex);
    for (std::size_t i = 0; i < N; ++i) numbers[i] = number_[vertices[i]];
    if (mesh_.is_p2())
      for (std::size_t e = 0; e < N * (N - 1) / 2; ++e) {
        std::array<int, 2> ends{0, 1};
        if constexpr (N > 2) ends = edge_vertices<static_cast<int>(N) - 1>(static_cast<int>(e));
        numbers[N + e] = node_number_[mesh_.find_edge(vertices[ends[0]], vertices[ends[1]])];
      }
    return numbers;
  }

  // An entity's record: its file numbers (those of its nodes when P2) and its ref.
  template <std::size_t M>
  static void write_numbers(ChunkRecords& out, const std::array<Index, M>& numbers, int ref) {
    for (Index number : numbers)
      if (number != kNoIndex) out.write_integer(std::int64_t{number} + 1);
    out.write_integer(ref);
    out.end_record();
  }

  template <std::size_t N>
  void write_simplex(ChunkRecords& out, const std::array<Index, N>& vertices, int ref) const {
    write_numbers(out, simplex_numbers(vertices), ref);
  }

  // 3D feature lines: a line with both ends shared may lie in several parts and goes to the process
  // its ends hash to, which keeps it once (the first part's, in rank order); every other line is its
  // part's own. Without a line order each process writes its own lines, then those it kept; with
  // one (per line of the part, its place), each line goes on to the process of its run of places.
  // Their ridge and required tags go with them.
  void encode_lines() {
    const EntityTags<D> tags(mesh_);
    const bool ordered = sum_over_processes(static_cast<int>(!line_order_.empty())) > 0;
    if (ordered && line_order_.size() != static_cast<std::size_t>(mesh_.line_count()))
      throw std::logic_error("write_mesh_runs: a line order that is not one place per line");
    std::vector<LineRow> rows;  // the lines this process writes or places
    std::vector<std::vector<SharedEdge<D>>> outgoing(static_cast<std::size_t>(process_count()));
    for (Index l = 0; l < mesh_.line_count(); ++l) {
      const auto [a, b] = mesh_.line(l);
      const char flags = static_cast<char>((tags.ridge_line[l] ? kRidgeFlag : 0) | (tags.required_line[l] ? kRequiredFlag : 0));
      const LineRow row{ordered ? line_order_[static_cast<std::size_t>(l)] : kNoIndex, mesh_.line_ref(l), flags,
                        simplex_numbers(mesh_.line(l))};
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
    const CountOffset offset = offset_over_processes(static_cast<Index>(rows.size()));
    counts_.lines = offset.total;
    std::vector<char> flags;  // per line written here, in order
    if (ordered) {
      std::vector<Index> places;
      for (const LineRow& row : rows) places.push_back(row.place);
      lines_ = std::move(encode_in_order<3>(places, offset.total, std::max<Index>(offset.total, 1), flags, [&](std::size_t i) {
                           return rows[i];
                         }).front());
      write_tags(flags, {slice_start(offset.total, process_rank(), process_count()), offset.total}, ridges_, required_edges_);
      return;
    }
    lines_ = records();
    for (const LineRow& row : rows) {
      write_numbers(lines_, row.numbers, row.ref);
      flags.push_back(row.flags);
    }
    write_tags(flags, offset, ridges_, required_edges_);
  }

  // The ids of the entities written here (from offset.before on) that carry each flag.
  void write_tags(const std::vector<char>& flags, const CountOffset& offset, ChunkRecords& ridges, ChunkRecords& required) const {
    ridges = required = records();
    for (std::size_t i = 0; i < flags.size(); ++i) {
      if (flags[i] & kRidgeFlag) write_id(ridges, offset.before + static_cast<Index>(i));
      if (flags[i] & kRequiredFlag) write_id(required, offset.before + static_cast<Index>(i));
    }
  }

  char facet_flags(const EntityTags<D>& tags, Index f) const {
    return static_cast<char>((tags.ridge_facet[f] ? kRidgeFlag : 0) | (tags.required_facet[f] ? kRequiredFlag : 0));
  }

  // The facets part by part, or in facet_order_ (in one window: a process's run of places is then
  // contiguous, and so are the tags it writes).
  void encode_facets() {
    const EntityTags<D> tags(mesh_);
    std::vector<Index> written;  // the part's facets but the interfaces'
    for (Index f = 0; f < mesh_.facet_count(); ++f)
      if (mesh_.facet_ref(f) != kInterfaceRef) written.push_back(f);
    const CountOffset offset = offset_over_processes(static_cast<Index>(written.size()));
    counts_.facets = offset.total;
    std::vector<char> flags;
    const bool ordered = sum_over_processes(static_cast<int>(!facet_order_.empty())) > 0;
    if (ordered) {
      if (facet_order_.size() != written.size()) throw std::logic_error("write_mesh_runs: a facet order that is not one place per facet");
      facets_ = std::move(
          encode_in_order<D + D*(D - 1) / 2>(facet_order_, offset.total, std::max<Index>(offset.total, 1), flags, [&](std::size_t i) {
            const Index f = written[i];
            return PlacedRow<D + D*(D - 1) / 2>{0, mesh_.facet_ref(f), facet_flags(tags, f), simplex_numbers(mesh_.facet(f))};
          }).front());
    } else {
      facets_ = records();
      for (Index f : written) {
        write_simplex(facets_, mesh_.facet(f), mesh_.facet_ref(f));
        flags.push_back(facet_flags(tags, f));
      }
    }
    const CountOffset tagged = ordered ? CountOffset{slice_start(offset.total, process_rank(), process_count()), offset.total} : offset;
    if constexpr (D == 2) {
      write_tags(flags, tagged, ridges_, required_edges_);
    } else {
      ChunkRecords no_ridges = records();  // a 3D mesh's ridges are lines
      write_tags(flags, tagged, no_ridges, required_triangles_);
    }
  }

  // The elements part by part, or in element_order_, window after window of kElementWindow places.
  void encode_elements() {
    const CountOffset offset = offset_over_processes(mesh_.element_count());
    counts_.elements = offset.total;
    if (sum_over_processes(static_cast<int>(!element_order_.empty())) > 0) {
      std::vector<char> no_flags;
      element_runs_ = encode_in_order<D + 1 + Simplex<D>::kEdges>(
          element_order_, offset.total, kElementWindow, no_flags, [&](std::size_t k) {
            const auto element = static_cast<Index>(k);
            return PlacedRow<D + 1 + Simplex<D>::kEdges>{0, mesh_.element_ref(element), 0, simplex_numbers(mesh_.element(element))};
          });
      return;
    }
    element_runs_.assign(1, records());
    for (Index k = 0; k < mesh_.element_count(); ++k) write_simplex(element_runs_[0], mesh_.element(k), mesh_.element_ref(k));
  }

  // Entities in the order of their places among the file's `total` (`order`: per entity, together a
  // permutation of the places), window after window of `window` places so that the messages never
  // hold more than a window's rows: each entity's row (row_of(i), its place set here) goes to the
  // process of its run of the window's places, which sorts its run, refuses a place missing or
  // given twice, and encodes it. Returns the runs, one per window; appends the rows' flags, in the
  // order written, to `flags`.
  template <std::size_t M, typename RowOf>
  std::vector<ChunkRecords> encode_in_order(std::span<const Index> order, Index total, Index window, std::vector<char>& flags,
                                            RowOf row_of) const {
    const auto refused = [&] { return Error(path_ + ": the order of the entities written is no permutation of them"); };
    std::vector<std::size_t> by_place(order.size());
    std::iota(by_place.begin(), by_place.end(), std::size_t{0});
    std::sort(by_place.begin(), by_place.end(), [&](std::size_t a, std::size_t b) { return order[a] < order[b]; });
    if (!by_place.empty() && (order[by_place.front()] < 0 || order[by_place.back()] >= total)) throw refused();
    const int windows = static_cast<int>(std::max<Index>(1, (total + window - 1) / window));
    std::vector<ChunkRecords> runs(static_cast<std::size_t>(windows), records());
    std::size_t next = 0;
    for (int w = 0; w < windows; ++w) {
      const Index begin = slice_start(total, w, windows), size = slice_start(total, w + 1, windows) - begin;
      std::vector<std::vector<PlacedRow<M>>> outgoing(static_cast<std::size_t>(process_count()));
      for (; next < by_place.size() && order[by_place[next]] < begin + size; ++next) {
        PlacedRow<M> row = row_of(by_place[next]);
        row.place = order[by_place[next]] - begin;
        outgoing[static_cast<std::size_t>(slice_holding(row.place, size, process_count()))].push_back(row);
      }
      std::vector<PlacedRow<M>> rows = exchange_values_joined(outgoing);
      std::sort(rows.begin(), rows.end(), [](const PlacedRow<M>& a, const PlacedRow<M>& b) { return a.place < b.place; });
      const Index first = slice_start(size, process_rank(), process_count());
      if (static_cast<Index>(rows.size()) != slice_start(size, process_rank() + 1, process_count()) - first) throw refused();
      for (std::size_t i = 0; i < rows.size(); ++i) {
        if (rows[i].place != first + static_cast<Index>(i)) throw refused();
        write_numbers(runs[static_cast<std::size_t>(w)], rows[i].numbers, rows[i].ref);
        flags.push_back(rows[i].flags);
      }
    }
    return runs;
  }

  void write_keywords(const std::vector<Keyword>& keywords);

  const std::string& path_;
  const MeshPart<D>& part_;
  const Mesh<D>& mesh_;
  bool binary_;
  std::span<const Index> element_order_, facet_order_, line_order_;
  int version_ = 0;
  MeshFileCounts counts_;
  std::vector<Index> number_;                // per part vertex, its file number (from 0)
  std::vector<char> shared_;                 // per part vertex, whether another part holds it
  std::vector<Index> node_number_;           // per part edge (P2), its node's file number (from 0)
  std::vector<VertexToRun<D>> vertex_rows_;  // the vertices this process writes, in order
  Index first_vertex_ = 0;                   // the file number (from 0) of the first of them
  std::vector<Vec<D>> shared_nodes_;         // the nodes of shared edges this process writes
  ChunkRecords vertices_ = records(), nodes_ = records(), lines_ = records(), facets_ = records();
  std::vector<ChunkRecords> element_runs_;  // the elements' records: one run, or one per window of an element order
  ChunkRecords corners_ = records(), ridges_ = records(), required_vertices_ = records(), required_edges_ = records(),
               required_triangles_ = records();
};

}  // namespace

// Rank 0 writes the keywords with a hole of each one's records; every process then writes its runs
// of records at their places: run j of a keyword after every process's runs before j, and after
// the processes before it in run j.
template <int D>
void RunsWriter<D>::write_keywords(const std::vector<Keyword>& keywords) {
  std::vector<std::int64_t> sizes;  // records, bytes per run of each keyword
  for (const Keyword& keyword : keywords)
    for (const ChunkRecords* run : keyword.runs) {
      sizes.push_back(run->records());
      sizes.push_back(static_cast<std::int64_t>(run->bytes().size()));
    }
  std::vector<std::vector<std::int64_t>> all;  // per process
  for (const std::vector<std::byte>& bytes : all_gather_bytes(bytes_of_values(sizes))) all.push_back(values_of_bytes<std::int64_t>(bytes));
  std::vector<std::uint64_t> starts(keywords.size(), 0);  // where each keyword's records begin
  if (process_rank() == 0) {
    const auto skeleton = [&](auto&& out) {
      std::size_t slot = 0;
      for (std::size_t i = 0; i < keywords.size(); ++i) {
        std::int64_t records = 0, bytes = 0;
        for (std::size_t j = 0; j < keywords[i].runs.size(); ++j, slot += 2)
          for (const std::vector<std::int64_t>& process : all) records += process[slot], bytes += process[slot + 1];
        if (records == 0 && keywords[i].code != gamma::kVertices) continue;
        out.begin_keyword(keywords[i].code, records, keywords[i].integers, keywords[i].reals);
        starts[i] = out.position();
        out.leave_records(static_cast<std::uint64_t>(bytes));
      }
      out.finish();
    };
    if (binary_)
      skeleton(gamma::BinaryKeywordWriter(path_, version_, D));
    else
      skeleton(gamma::TextKeywordWriter(path_, version_, D));
  }
  broadcast_values(starts);
  std::fstream out(file_begun_on_rank_0(path_), std::ios::in | std::ios::out | std::ios::binary);
  std::size_t slot = 0;
  for (std::size_t i = 0; i < keywords.size(); ++i) {
    std::uint64_t at = starts[i];
    for (std::size_t j = 0; j < keywords[i].runs.size(); ++j, slot += 2) {
      for (int r = 0; r < process_rank(); ++r) at += static_cast<std::uint64_t>(all[static_cast<std::size_t>(r)][slot + 1]);
      const std::string& bytes = keywords[i].runs[j]->bytes();
      out.seekp(static_cast<std::streamoff>(at));
      out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
      for (int r = process_rank(); r < process_count(); ++r) at += static_cast<std::uint64_t>(all[static_cast<std::size_t>(r)][slot + 1]);
    }
  }
  out.close();
  if (!out) throw Error(path_ + ": cannot write the records of rank " + std::to_string(process_rank()));
  all_gather_value(0);  // every run is in place before rank 0 commits the file
}

template <int D>
MeshFileCounts write_mesh_runs(const std::string& path, const MeshPart<D>& part, bool binary, int version, const EntityOrders& orders) {
  return RunsWriter<D>(path, part, binary, orders).write(version);
}

template MeshFileCounts write_mesh_runs(const std::string&, const MeshPart<2>&, bool, int, const EntityOrders&);
template MeshFileCounts write_mesh_runs(const std::string&, const MeshPart<3>&, bool, int, const EntityOrders&);

}  // namespace hocav
