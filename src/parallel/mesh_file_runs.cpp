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
#include "parallel/file_in_runs.hpp"
#include "parallel/file_numbers.hpp"

namespace hocav {
namespace {

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
        mesh_(part.mesh),
        binary_(binary),
        element_order_(orders.elements),
        facet_order_(orders.facets),
        line_order_(orders.lines),
        numbers_(path, part) {
    if (!element_order_.empty() && element_order_.size() != static_cast<std::size_t>(mesh_.element_count()))
      throw std::logic_error("write_mesh_runs: an element order that is not one place per element");
  }

  MeshFileCounts write(int requested_version) {
    const bool p2 = numbers_.p2();
    counts_.vertices = numbers_.vertex_count();
    counts_.nodes = numbers_.node_count();
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

  void write_point(ChunkRecords& out, const Vec<D>& point, int ref) const {
    for (int i = 0; i < D; ++i) out.write_real(point[i]);
    out.write_integer(ref);
    out.end_record();
  }

  void encode_vertices() {
    vertices_ = corners_ = required_vertices_ = records();
    for (const VertexToRun<D>& row : numbers_.vertex_rows()) write_point(vertices_, row.point, row.ref);
    Index next = numbers_.first_vertex();
    for (const VertexToRun<D>& row : numbers_.vertex_rows()) {
      if (row.flags & kCornerFlag) write_id(corners_, next);
      if (row.flags & kRequiredFlag) write_id(required_vertices_, next);
      ++next;
    }
  }

  void encode_nodes() {
    nodes_ = records();
    for (const Vec<D>& node : numbers_.written_nodes()) write_point(nodes_, node, 0);
  }

  static void write_id(ChunkRecords& out, Index id) {
    out.write_integer(std::int64_t{id} + 1);
    out.end_record();
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
    write_numbers(out, numbers_.simplex(vertices), ref);
  }

  // 3D feature lines, each once (FileNumbers::lines_once). Without a line order each process writes
  // those it holds; with one (per line of the part, its place), each line goes on to the process of
  // its run of places. Their ridge and required tags go with them.
  void encode_lines() {
    const bool ordered = sum_over_processes(static_cast<int>(!line_order_.empty())) > 0;
    if (ordered && line_order_.size() != static_cast<std::size_t>(mesh_.line_count()))
      throw std::logic_error("write_mesh_runs: a line order that is not one place per line");
    const std::vector<LineRow> rows = numbers_.lines_once(line_order_);
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
            return PlacedRow<D + D*(D - 1) / 2>{0, mesh_.facet_ref(f), facet_flags(tags, f), numbers_.simplex(mesh_.facet(f))};
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

  // The elements part by part, or in element_order_, window after window of kOrderWindow places.
  void encode_elements() {
    const CountOffset offset = offset_over_processes(mesh_.element_count());
    counts_.elements = offset.total;
    if (sum_over_processes(static_cast<int>(!element_order_.empty())) > 0) {
      std::vector<char> no_flags;
      element_runs_ = encode_in_order<D + 1 + Simplex<D>::kEdges>(element_order_, offset.total, kOrderWindow, no_flags, [&](std::size_t k) {
        const auto element = static_cast<Index>(k);
        return PlacedRow<D + 1 + Simplex<D>::kEdges>{0, mesh_.element_ref(element), 0, numbers_.simplex(mesh_.element(element))};
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
  const Mesh<D>& mesh_;
  bool binary_;
  std::span<const Index> element_order_, facet_order_, line_order_;
  FileNumbers<D> numbers_;
  int version_ = 0;
  MeshFileCounts counts_;
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
  const std::vector<std::vector<std::int64_t>> all = all_gather_values(sizes);  // per process
  std::vector<std::uint64_t> starts(keywords.size(), 0);                        // where each keyword's records begin
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
