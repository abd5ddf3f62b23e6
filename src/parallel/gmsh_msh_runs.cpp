#include "parallel/gmsh_msh_runs.hpp"

#include <algorithm>
#include <array>
#include <functional>
#include <numeric>
#include <sstream>
#include <vector>

#include "io/gmsh_msh_text.hpp"
#include "parallel/communicator.hpp"
#include "parallel/file_in_runs.hpp"
#include "parallel/file_numbers.hpp"

namespace hocav {
namespace {

using gmsh_msh::TextWriter;

// The entities of one dimension this process writes: per entity its ref and, found when it is
// written, its file numbers (in hocav's local order, from 0); and their order in the file's blocks
// (stable by ref).
struct WrittenRows {
  std::vector<int> refs;
  std::function<std::array<Index, 10>(std::size_t)> numbers;
  std::vector<std::size_t> by_ref;

  void sort_by_ref() {
    by_ref.resize(refs.size());
    std::iota(by_ref.begin(), by_ref.end(), std::size_t{0});
    std::stable_sort(by_ref.begin(), by_ref.end(), [&](std::size_t a, std::size_t b) { return refs[a] < refs[b]; });
  }
};

template <std::size_t M>
std::array<Index, 10> padded(const std::array<Index, M>& entity) {
  std::array<Index, 10> row;
  row.fill(kNoIndex);
  std::copy(entity.begin(), entity.end(), row.begin());
  return row;
}

// Per dimension (points, lines, facets, elements) what this process writes: the corners among its
// vertices, its feature lines once (3D), its facets but the interfaces', its elements.
template <int D>
std::array<WrittenRows, 4> rows_written_here(const MeshPart<D>& part, const FileNumbers<D>& numbers) {
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
    std::vector<LineRow> lines = numbers.lines_once({});
    for (const LineRow& line : lines) rows[1].refs.push_back(line.ref);
    rows[1].numbers = [lines = std::move(lines)](std::size_t i) { return padded(lines[i].numbers); };
  }
  std::vector<Index> facets;  // the part's but the interfaces'
  for (Index f = 0; f < mesh.facet_count(); ++f)
    if (mesh.facet_ref(f) != kInterfaceRef) {
      rows[D - 1].refs.push_back(mesh.facet_ref(f));
      facets.push_back(f);
    }
  rows[D - 1].numbers = [&mesh, &numbers, facets](std::size_t i) { return padded(numbers.simplex(mesh.facet(facets[i]))); };
  for (Index k = 0; k < mesh.element_count(); ++k) rows[D].refs.push_back(mesh.element_ref(k));
  rows[D].numbers = [&mesh, &numbers](std::size_t k) { return padded(numbers.simplex(mesh.element(static_cast<Index>(k)))); };
  for (WrittenRows& dimension : rows) dimension.sort_by_ref();
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

// The file's blocks (an entity: a dimension and a ref), in order, with what this process writes of
// each: its rows (by_ref positions [begin, end)), the block's size and the tag of its first row.
struct Block {
  int dimension;
  std::size_t entity;  // from 1
  std::size_t begin, end, total, first_tag;
};

std::vector<Block> blocks_of(const std::array<WrittenRows, 4>& rows, const std::array<std::vector<int>, 4>& refs) {
  std::vector<Block> blocks;
  std::vector<Index> own;  // rows per block
  for (int d = 0; d < 4; ++d) {
    const WrittenRows& written = rows[static_cast<std::size_t>(d)];
    std::size_t at = 0;
    for (std::size_t entity = 0; entity < refs[static_cast<std::size_t>(d)].size(); ++entity) {
      const std::size_t begin = at;
      while (at < written.by_ref.size() && written.refs[written.by_ref[at]] == refs[static_cast<std::size_t>(d)][entity]) ++at;
      blocks.push_back({d, entity + 1, begin, at, 0, 0});
      own.push_back(static_cast<Index>(at - begin));
    }
  }
  const std::vector<std::vector<Index>> counts = all_gather_values(own);  // per process
  std::size_t tag = 1;
  for (std::size_t b = 0; b < blocks.size(); ++b)
    for (int r = 0; r < process_count(); ++r) {
      if (r == process_rank()) blocks[b].first_tag = tag;
      const auto count = static_cast<std::size_t>(counts[static_cast<std::size_t>(r)][b]);
      blocks[b].total += count;
      tag += count;
    }
  return blocks;
}

// The bounding box of every node of the file, and the first point of each point entity (the first
// corner of its ref in file order).
template <int D>
struct EntityPlaces {
  Vec<D> low, high;
  std::vector<Vec<D>> points;
};

template <int D>
struct OwnBox {
  Vec<D> low, high;
  int any = 0;

  void extend(const Vec<D>& point) {
    if (!any) low = high = point;
    any = 1;
    for (int c = 0; c < D; ++c) {
      low[c] = std::min(low[c], point[c]);
      high[c] = std::max(high[c], point[c]);
    }
  }
};

template <int D>
struct FirstPoint {
  Vec<D> point;
  int any = 0;
};

template <int D>
EntityPlaces<D> entity_places(const FileNumbers<D>& numbers, const WrittenRows& corners, const std::vector<int>& corner_refs) {
  OwnBox<D> own;
  for (const VertexToRun<D>& row : numbers.vertex_rows()) own.extend(row.point);
  for (const Vec<D>& node : numbers.written_nodes()) own.extend(node);
  EntityPlaces<D> places;
  OwnBox<D> box;
  for (const OwnBox<D>& each : all_gather_value(own))
    if (each.any) box.extend(each.low), box.extend(each.high);
  places.low = box.low;
  places.high = box.high;
  std::vector<FirstPoint<D>> firsts(corner_refs.size());
  for (std::size_t i : corners.by_ref) {
    const auto entity = static_cast<std::size_t>(std::lower_bound(corner_refs.begin(), corner_refs.end(), corners.refs[i]) -
                                                 corner_refs.begin());
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

template <typename Write>
std::string text_of(Write write) {
  std::ostringstream stream;
  TextWriter out(stream);
  write(out);
  out.flush();
  return std::move(stream).str();
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
MeshFileCounts write_gmsh_msh_runs(const std::string& path, const MeshPart<D>& part) {
  const FileNumbers<D> numbers(path, part);
  const std::array<WrittenRows, 4> rows = rows_written_here(part, numbers);
  const std::array<std::vector<int>, 4> refs = refs_over_processes(rows);
  const std::vector<Block> blocks = blocks_of(rows, refs);
  const EntityPlaces<D> places = entity_places(numbers, rows[0], refs[0]);
  const Index node_count = numbers.vertex_count() + numbers.node_count();
  const bool head = process_rank() == 0;
  std::size_t element_count = 0;
  for (const Block& block : blocks) element_count += block.total;
  const int order = numbers.p2() ? 2 : 1;
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
    gmsh_msh::write_elements_head(out, blocks.size(), element_count);
  }));
  for (const Block& block : blocks) {
    const gmsh_msh::ElementType& type = gmsh_msh::element_type(block.dimension, block.dimension == 0 ? 1 : order);
    segments.push_back(text_of([&](TextWriter& out) {
      if (head) gmsh_msh::write_block_head(out, block.entity, type, block.total);
    }));
    segments.push_back(text_of([&](TextWriter& out) {
      const WrittenRows& written = rows[static_cast<std::size_t>(block.dimension)];
      for (std::size_t i = block.begin; i < block.end; ++i)
        gmsh_msh::write_element(out, block.first_tag + (i - block.begin), type, written.numbers(written.by_ref[i]).data());
    }));
  }
  segments.push_back(head ? "$EndElements\n" : "");
  write_segments_in_runs(path, segments);
  const auto total_of = [&](int dimension) {
    std::size_t total = 0;
    for (const Block& block : blocks)
      if (block.dimension == dimension) total += block.total;
    return static_cast<Index>(total);
  };
  return {numbers.vertex_count(), numbers.node_count(), total_of(D), total_of(D - 1), D == 3 ? total_of(1) : 0};
}

template MeshFileCounts write_gmsh_msh_runs(const std::string&, const MeshPart<2>&);
template MeshFileCounts write_gmsh_msh_runs(const std::string&, const MeshPart<3>&);

}  // namespace hocav
