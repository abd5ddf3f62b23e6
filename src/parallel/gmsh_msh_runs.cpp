#include "parallel/gmsh_msh_runs.hpp"

#include <algorithm>
#include <array>
#include <functional>
#include <numeric>
#include <sstream>
#include <vector>

#include "base/error.hpp"
#include "geom/box.hpp"
#include "io/gmsh_msh_text.hpp"
#include "io/record_run.hpp"
#include "parallel/communicator.hpp"
#include "parallel/file_in_runs.hpp"
#include "parallel/file_numbers.hpp"

namespace hocav {
namespace {

using gmsh_msh::TextWriter;
using OrderedRow = PlacedRow<10>;

// The entities of one dimension this process writes: per entity its ref, its file numbers (in
// hocav's local order, from 0; found when it is written) and, when the dimension has an order, its
// place among the file's entities of the dimension.
struct WrittenRows {
  std::vector<int> refs;
  std::function<std::array<Index, 10>(std::size_t)> numbers;
  std::vector<Index> places;
};

template <std::size_t M>
std::array<Index, 10> padded(const std::array<Index, M>& entity) {
  std::array<Index, 10> row;
  row.fill(kNoIndex);
  std::copy(entity.begin(), entity.end(), row.begin());
  return row;
}

// Per dimension (points, lines, facets, elements) what this process writes: the corners among its
// vertices, its feature lines once (3D), its facets but the interfaces', its elements; with the
// places `orders` gives the lines, facets and elements.
template <int D>
std::array<WrittenRows, 4> rows_written_here(const MeshPart<D>& part, const FileNumbers<D>& numbers, const EntityOrders& orders) {
  const Mesh<D>& mesh = part.mesh;
  std::array<WrittenRows, 4> rows;
  std::vector<Index> corners;  // their file numbers
  for (std::size_t i = 0; i < numbers.vertex_rows().size(); ++i)
    if (numbers.vertex_rows()[i].flags & kCornerFlag) {
      rows[0].refs.push_back(numbers.vertex_rows()[i].ref);
      corners.push_back(numbers.first_vertex() + static_cast<Index>(i));
    }
  rows[0].numbers = [corners](std::size_t i) { return padded(std::array<Index, 1>{corners[i]}); };
  if constexpr (D == 3) {
    std::vector<LineRow> lines = numbers.lines_once(orders.lines);
    for (const LineRow& line : lines) {
      rows[1].refs.push_back(line.ref);
      if (!orders.lines.empty()) rows[1].places.push_back(line.place);
    }
    rows[1].numbers = [lines = std::move(lines)](std::size_t i) { return padded(lines[i].numbers); };
  }
  std::vector<Index> facets;  // the part's but the interfaces'
  for (Index f = 0; f < mesh.facet_count(); ++f)
    if (mesh.facet_ref(f) != kInterfaceRef) {
      rows[D - 1].refs.push_back(mesh.facet_ref(f));
      facets.push_back(f);
    }
  rows[D - 1].numbers = [&mesh, &numbers, facets](std::size_t i) { return padded(numbers.simplex(mesh.facet(facets[i]))); };
  rows[D - 1].places.assign(orders.facets.begin(), orders.facets.end());
  for (Index k = 0; k < mesh.element_count(); ++k) rows[D].refs.push_back(mesh.element_ref(k));
  rows[D].numbers = [&mesh, &numbers](std::size_t k) { return padded(numbers.simplex(mesh.element(static_cast<Index>(k)))); };
  rows[D].places.assign(orders.elements.begin(), orders.elements.end());
  for (const WrittenRows& dimension : rows)
    if (!dimension.places.empty() && dimension.places.size() != dimension.refs.size())
      throw std::logic_error("write_gmsh_msh_runs: an order that is not one place per entity");
  return rows;
}

// The refs of each dimension over every process, sorted: the file's entities.
std::array<std::vector<int>, 4> refs_over_processes(const std::array<WrittenRows, 4>& rows) {
  std::array<std::vector<int>, 4> refs;
  for (std::size_t d = 0; d < 4; ++d) {
    std::vector<int> own = rows[d].refs;
    std::sort(own.begin(), own.end());
    own.erase(std::unique(own.begin(), own.end()), own.end());
    refs[d] = all_gather_values_joined(own);
    std::sort(refs[d].begin(), refs[d].end());
    refs[d].erase(std::unique(refs[d].begin(), refs[d].end()), refs[d].end());
  }
  return refs;
}

// Where a dimension's entities go in the file. Without an order each process writes its own, in one
// window; with one, window after window of its places, the process of a place's run within its
// window writes the entity (as the Gamma writer's orders, docs/distributed.md §Writing in runs), so
// that each ref's block holds its entities in the order's. `counts` holds how many entities of each
// entity (ref) each process writes in each window; `first_tags` the tag of this process's first.
struct DimensionLayout {
  bool ordered = false;
  Index total = 0;  // the dimension's entities over the file
  int windows = 1;
  std::vector<Index> counts;            // [(entity * windows + window) * processes + process]
  std::vector<std::size_t> first_tags;  // [entity * windows + window]
  std::vector<std::size_t> totals;      // per entity, its block's size

  std::size_t at(std::size_t entity, int window, int process) const {
    return (entity * static_cast<std::size_t>(windows) + static_cast<std::size_t>(window)) * static_cast<std::size_t>(process_count()) +
           static_cast<std::size_t>(process);
  }
  // The window and the writing process of place `place`.
  std::pair<int, int> holder(Index place) const {
    const int window = slice_holding(place, total, windows);
    const Index begin = slice_start(total, window, windows), size = slice_start(total, window + 1, windows) - begin;
    return {window, slice_holding(place - begin, size, process_count())};
  }
};

Error no_permutation(const std::string& path) { return Error(path + ": the order of the entities written is no permutation of them"); }

std::size_t entity_of(const std::vector<int>& refs, int ref) {
  return static_cast<std::size_t>(std::lower_bound(refs.begin(), refs.end(), ref) - refs.begin());
}

// The layouts of the four dimensions, their tags numbered block after block (dimension, then ref),
// window after window within a block, rank after rank within a window, from 1. Throws Error when an
// order places an entity outside its dimension.
std::array<DimensionLayout, 4> layouts_of(const std::array<WrittenRows, 4>& rows, const std::array<std::vector<int>, 4>& refs,
                                          const std::string& path) {
  std::array<DimensionLayout, 4> layouts;
  std::size_t tag = 1;
  for (std::size_t d = 0; d < 4; ++d) {
    DimensionLayout& layout = layouts[d];
    layout.ordered = sum_over_processes(static_cast<int>(!rows[d].places.empty())) > 0;
    layout.total = sum_over_processes(static_cast<Index>(rows[d].refs.size()));
    if (layout.ordered) layout.windows = static_cast<int>(std::max<Index>(1, (layout.total + kOrderWindow - 1) / kOrderWindow));
    std::vector<Index> own(refs[d].size() * static_cast<std::size_t>(layout.windows * process_count()), 0);
    for (std::size_t i = 0; i < rows[d].refs.size(); ++i) {
      if (layout.ordered && (rows[d].places[i] < 0 || rows[d].places[i] >= layout.total)) throw no_permutation(path);
      const auto [window, process] = layout.ordered ? layout.holder(rows[d].places[i]) : std::pair{0, process_rank()};
      ++own[layout.at(entity_of(refs[d], rows[d].refs[i]), window, process)];
    }
    layout.counts.assign(own.size(), 0);
    for (const std::vector<Index>& each : all_gather_values(own))
      for (std::size_t i = 0; i < own.size(); ++i) layout.counts[i] += each[i];
    layout.first_tags.assign(refs[d].size() * static_cast<std::size_t>(layout.windows), 0);
    layout.totals.assign(refs[d].size(), 0);
    for (std::size_t e = 0; e < refs[d].size(); ++e)
      for (int w = 0; w < layout.windows; ++w)
        for (int r = 0; r < process_count(); ++r) {
          if (r == process_rank()) layout.first_tags[e * static_cast<std::size_t>(layout.windows) + static_cast<std::size_t>(w)] = tag;
          const auto count = static_cast<std::size_t>(layout.counts[layout.at(e, w, r)]);
          layout.totals[e] += count;
          tag += count;
        }
  }
  return layouts;
}

template <typename Write>
std::string text_of(Write write) {
  std::ostringstream stream;
  TextWriter out(stream);
  write(out);
  out.flush();
  return std::move(stream).str();
}

// The element lines of one window, its rows sorted by ref (`row_refs`, their numbers from
// `numbers_of`), each entity's into texts[entity * windows + window], tagged from the layout's
// first tag of that slot.
void write_window(std::vector<std::string>& texts, int window, const DimensionLayout& layout, const std::vector<int>& refs,
                  const gmsh_msh::ElementType& type, const std::vector<int>& row_refs, auto numbers_of) {
  std::size_t at = 0;
  for (std::size_t e = 0; e < refs.size(); ++e) {
    const std::size_t slot = e * static_cast<std::size_t>(layout.windows) + static_cast<std::size_t>(window);
    texts[slot] = text_of([&](TextWriter& out) {
      for (std::size_t tag = layout.first_tags[slot]; at < row_refs.size() && row_refs[at] == refs[e]; ++at)
        gmsh_msh::write_element(out, tag++, type, numbers_of(at).data());
    });
  }
}

// This process's rows of one window of an ordered dimension: each of its entities placed in the
// window sent to the process of its place's run, which checks that its run's places came once each.
// `by_place`: the rows by place, and `next` the first not sent yet (the windows come in order).
std::vector<OrderedRow> window_rows(const WrittenRows& rows, const std::vector<std::size_t>& by_place, std::size_t& next,
                                    const DimensionLayout& layout, int window, const std::string& path) {
  std::vector<std::vector<OrderedRow>> outgoing(static_cast<std::size_t>(process_count()));
  for (; next < by_place.size() && layout.holder(rows.places[by_place[next]]).first == window; ++next) {
    const std::size_t i = by_place[next];
    outgoing[static_cast<std::size_t>(layout.holder(rows.places[i]).second)].push_back({rows.places[i], rows.refs[i], 0, rows.numbers(i)});
  }
  std::vector<OrderedRow> arrived = exchange_values_joined(outgoing);
  std::vector<Index> places;
  for (const OrderedRow& row : arrived) places.push_back(row.place);
  std::sort(places.begin(), places.end());
  const Index begin = slice_start(layout.total, window, layout.windows),
              size = slice_start(layout.total, window + 1, layout.windows) - begin;
  const Index first = begin + slice_start(size, process_rank(), process_count());
  const Index end = begin + slice_start(size, process_rank() + 1, process_count());
  if (static_cast<Index>(places.size()) != end - first ||
      std::adjacent_find(places.begin(), places.end(), [](Index a, Index b) { return b != a + 1; }) != places.end() ||
      (!places.empty() && places.front() != first))
    throw no_permutation(path);
  std::sort(arrived.begin(), arrived.end(),
            [](const OrderedRow& a, const OrderedRow& b) { return std::pair(a.ref, a.place) < std::pair(b.ref, b.place); });
  return arrived;
}

// This process's lines of every block and window of one dimension: texts[entity * windows + window].
std::vector<std::string> dimension_texts(const WrittenRows& rows, const std::vector<int>& refs, const DimensionLayout& layout,
                                         const gmsh_msh::ElementType& type, const std::string& path) {
  std::vector<std::string> texts(refs.size() * static_cast<std::size_t>(layout.windows));
  if (!layout.ordered) {
    std::vector<std::size_t> by_ref(rows.refs.size());
    std::iota(by_ref.begin(), by_ref.end(), std::size_t{0});
    std::stable_sort(by_ref.begin(), by_ref.end(), [&](std::size_t a, std::size_t b) { return rows.refs[a] < rows.refs[b]; });
    std::vector<int> sorted_refs;
    for (std::size_t i : by_ref) sorted_refs.push_back(rows.refs[i]);
    write_window(texts, 0, layout, refs, type, sorted_refs, [&](std::size_t at) { return rows.numbers(by_ref[at]); });
    return texts;
  }
  std::vector<std::size_t> by_place(rows.places.size());
  std::iota(by_place.begin(), by_place.end(), std::size_t{0});
  std::sort(by_place.begin(), by_place.end(), [&](std::size_t a, std::size_t b) { return rows.places[a] < rows.places[b]; });
  std::size_t next = 0;
  for (int window = 0; window < layout.windows; ++window) {
    const std::vector<OrderedRow> arrived = window_rows(rows, by_place, next, layout, window, path);
    std::vector<int> sorted_refs;
    for (const OrderedRow& row : arrived) sorted_refs.push_back(row.ref);
    write_window(texts, window, layout, refs, type, sorted_refs, [&](std::size_t at) { return arrived[at].numbers; });
  }
  return texts;
}

// The bounding box of every node of the file, and the first point of each point entity (the first
// corner of its ref in file order).
template <int D>
struct EntityPlaces {
  Vec<D> low, high;
  std::vector<Vec<D>> points;
};

template <int D>
struct FirstPoint {
  Vec<D> point;
  int any = 0;
};

template <int D>
EntityPlaces<D> entity_places(const FileNumbers<D>& numbers, const WrittenRows& corners, const std::vector<int>& corner_refs) {
  Box<D> own = Box<D>::empty();
  for (const VertexToRun<D>& row : numbers.vertex_rows()) own.add(row.point);
  for (const Vec<D>& node : numbers.written_nodes()) own.add(node);
  Box<D> box = Box<D>::empty();
  for (const Box<D>& each : all_gather_value(own)) box.add(each);
  EntityPlaces<D> places;  // (an empty mesh's box: zeros, as write_gmsh_msh writes it)
  if (!box.is_empty()) places.low = box.lower, places.high = box.upper;
  std::vector<FirstPoint<D>> firsts(corner_refs.size());
  for (std::size_t i = 0; i < corners.refs.size(); ++i) {  // (in file order)
    const std::size_t entity = entity_of(corner_refs, corners.refs[i]);
    if (firsts[entity].any) continue;
    firsts[entity] = {numbers.vertex_rows()[static_cast<std::size_t>(corners.numbers(i)[0] - numbers.first_vertex())].point, 1};
  }
  const std::vector<FirstPoint<D>> all = all_gather_values_joined(firsts);  // rank after rank
  places.points.resize(corner_refs.size());
  for (std::size_t entity = 0; entity < corner_refs.size(); ++entity)
    for (std::size_t r = 0; r < static_cast<std::size_t>(process_count()); ++r)
      if (const FirstPoint<D>& first = all[r * corner_refs.size() + entity]; first.any) {
        places.points[entity] = first.point;  // the lowest rank's
        break;
      }
  return places;
}

template <int D>
void write_points(TextWriter& out, const auto& points, auto point_of) {
  for (const auto& each : points) {
    gmsh_msh::write_point(out, point_of(each));
    out << '\n';
  }
}

void write_tags(TextWriter& out, Index first, std::size_t count) {
  for (std::size_t i = 0; i < count; ++i) out << first + static_cast<Index>(i) + 1 << '\n';
}

}  // namespace

template <int D>
MeshFileCounts write_gmsh_msh_runs(const std::string& path, const MeshPart<D>& part, const EntityOrders& orders) {
  const FileNumbers<D> numbers(path, part);
  const std::array<WrittenRows, 4> rows = rows_written_here(part, numbers, orders);
  const std::array<std::vector<int>, 4> refs = refs_over_processes(rows);
  const std::array<DimensionLayout, 4> layouts = layouts_of(rows, refs, path);
  const EntityPlaces<D> places = entity_places(numbers, rows[0], refs[0]);
  const Index node_count = numbers.vertex_count() + numbers.node_count();
  const bool head = process_rank() == 0;
  std::size_t blocks = 0, element_count = 0;
  for (std::size_t d = 0; d < 4; ++d) blocks += refs[d].size(), element_count += static_cast<std::size_t>(layouts[d].total);
  std::vector<std::string> segments;
  segments.push_back(text_of([&](TextWriter& out) {
    if (!head) return;
    out << gmsh_msh::kMeshFormat;
    gmsh_msh::write_entities(out, refs, places.points, places.low, places.high);
    gmsh_msh::write_nodes_head(out, D, node_count);
  }));
  segments.push_back(text_of([&](TextWriter& out) { write_tags(out, numbers.first_vertex(), numbers.vertex_rows().size()); }));
  segments.push_back(text_of([&](TextWriter& out) { write_tags(out, numbers.first_node(), numbers.written_nodes().size()); }));
  segments.push_back(
      text_of([&](TextWriter& out) { write_points<D>(out, numbers.vertex_rows(), [](const VertexToRun<D>& row) { return row.point; }); }));
  segments.push_back(
      text_of([&](TextWriter& out) { write_points<D>(out, numbers.written_nodes(), [](const Vec<D>& node) { return node; }); }));
  segments.push_back(text_of([&](TextWriter& out) {
    if (!head) return;
    if (node_count > 0) out << "$EndNodes\n";
    gmsh_msh::write_elements_head(out, blocks, element_count);
  }));
  for (std::size_t d = 0; d < 4; ++d) {
    const gmsh_msh::ElementType& type = gmsh_msh::element_type(static_cast<int>(d), d == 0 || !numbers.p2() ? 1 : 2);
    std::vector<std::string> texts = dimension_texts(rows[d], refs[d], layouts[d], type, path);
    for (std::size_t e = 0; e < refs[d].size(); ++e) {
      segments.push_back(text_of([&](TextWriter& out) {
        if (head) gmsh_msh::write_block_head(out, e + 1, type, layouts[d].totals[e]);
      }));
      for (int w = 0; w < layouts[d].windows; ++w)
        segments.push_back(std::move(texts[e * static_cast<std::size_t>(layouts[d].windows) + static_cast<std::size_t>(w)]));
    }
  }
  segments.push_back(head ? "$EndElements\n" : "");
  write_segments_in_runs(path, segments);
  return {numbers.vertex_count(), numbers.node_count(), layouts[D].total, layouts[D - 1].total, D == 3 ? layouts[1].total : 0};
}

template MeshFileCounts write_gmsh_msh_runs(const std::string&, const MeshPart<2>&, const EntityOrders&);
template MeshFileCounts write_gmsh_msh_runs(const std::string&, const MeshPart<3>&, const EntityOrders&);

}  // namespace hocav
