#include "parallel/back_mesh_share.hpp"

#include <algorithm>
#include <cmath>

#include "base/error.hpp"
#include "mesh/mesh_box.hpp"
#include "parallel/byte_stream.hpp"
#include "parallel/communicator.hpp"

namespace hocav {
namespace {

// What one process sends another of its back elements: the elements by global vertex ids, and the
// vertices they use with their points and, field after field, their log-metrics.
template <int D>
struct SharePiece {
  std::vector<int> field_count;  // one value
  std::vector<Index> vertex_ids;
  std::vector<Vec<D>> points;
  std::vector<SymMat<D>> log_metrics;  // field-major: field f of vertex i at f * vertex_ids.size() + i
  std::vector<typename Mesh<D>::Element> elements;

  std::vector<std::byte> bytes() const {
    ByteWriter out;
    out.put(field_count), out.put(vertex_ids), out.put(points), out.put(log_metrics), out.put(elements);
    return std::move(out.bytes);
  }

  static SharePiece read(const std::vector<std::byte>& bytes) {
    ByteReader in(bytes);
    SharePiece piece;
    piece.field_count = in.take<int>(), piece.vertex_ids = in.take<Index>(), piece.points = in.take<Vec<D>>();
    piece.log_metrics = in.take<SymMat<D>>(), piece.elements = in.take<typename Mesh<D>::Element>();
    const std::size_t n = piece.vertex_ids.size();
    if (!in.at_end() || piece.field_count.size() != 1 || piece.points.size() != n ||
        piece.log_metrics.size() != n * static_cast<std::size_t>(piece.field_count[0]))
      throw Error("a back-mesh share message has arrays of different lengths");
    return piece;
  }
};

// The piece of back mesh `mesh` (vertex v's global id global_ids[v], or v when empty) made of the
// elements k for which keep(k).
template <int D, typename Keep>
SharePiece<D> piece_of(const Mesh<D>& mesh, std::span<const Index> global_ids, const std::vector<std::vector<SymMat<D>>>& log_metrics,
                       Keep&& keep) {
  SharePiece<D> piece;
  piece.field_count = {static_cast<int>(log_metrics.size())};
  std::vector<Index> local(static_cast<std::size_t>(mesh.vertex_count()), kNoIndex);
  std::vector<Index> used;
  auto global = [&](Index v) { return global_ids.empty() ? v : global_ids[v]; };
  for (Index k = 0; k < mesh.element_count(); ++k) {
    if (!keep(k)) continue;
    typename Mesh<D>::Element element = mesh.element(k);
    for (Index& v : element) {
      if (local[v] == kNoIndex) {
        local[v] = static_cast<Index>(used.size());
        used.push_back(v);
      }
      v = global(v);
    }
    piece.elements.push_back(element);
  }
  for (Index v : used) {
    piece.vertex_ids.push_back(global(v));
    piece.points.push_back(mesh.vertex(v));
  }
  for (const std::vector<SymMat<D>>& field : log_metrics)
    for (Index v : used) piece.log_metrics.push_back(field[v]);
  return piece;
}

// The share made of the pieces in `messages` (empty ones skipped): each vertex once, in the order of
// the global ids, the elements piece after piece.
template <int D>
BackMeshShare<D> share_of_messages(const std::vector<std::vector<std::byte>>& messages) {
  std::vector<SharePiece<D>> pieces;
  for (const std::vector<std::byte>& bytes : messages)
    if (!bytes.empty()) pieces.push_back(SharePiece<D>::read(bytes));
  BackMeshShare<D> share;
  if (pieces.empty()) return share;
  const int fields = pieces[0].field_count[0];
  for (const SharePiece<D>& piece : pieces) {
    if (piece.field_count[0] != fields) throw Error("the back-mesh share messages disagree on the number of fields");
    share.global_ids.insert(share.global_ids.end(), piece.vertex_ids.begin(), piece.vertex_ids.end());
  }
  std::sort(share.global_ids.begin(), share.global_ids.end());
  share.global_ids.erase(std::unique(share.global_ids.begin(), share.global_ids.end()), share.global_ids.end());
  const std::size_t n = share.global_ids.size();
  std::vector<Vec<D>> points(n);
  share.log_metrics.assign(static_cast<std::size_t>(fields), std::vector<SymMat<D>>(n));
  auto local = [&](Index id) {
    return static_cast<Index>(std::lower_bound(share.global_ids.begin(), share.global_ids.end(), id) - share.global_ids.begin());
  };
  for (const SharePiece<D>& piece : pieces)
    for (std::size_t i = 0; i < piece.vertex_ids.size(); ++i) {
      const Index v = local(piece.vertex_ids[i]);
      points[v] = piece.points[i];
      for (int f = 0; f < fields; ++f) share.log_metrics[f][v] = piece.log_metrics[f * piece.vertex_ids.size() + i];
    }
  for (const Vec<D>& point : points) share.mesh.add_vertex(point);
  for (const SharePiece<D>& piece : pieces)
    for (typename Mesh<D>::Element element : piece.elements) {
      for (Index& v : element) v = local(v);
      share.mesh.add_element(element);
    }
  return share;
}

long long bytes_to_others(const std::vector<std::vector<std::byte>>& outgoing) {
  long long sum = 0;
  for (std::size_t p = 0; p < outgoing.size(); ++p)
    if (static_cast<int>(p) != process_rank()) sum += static_cast<long long>(outgoing[p].size());
  return sum;
}

}  // namespace

template <int D>
BackMeshShare<D> scatter_back_mesh(const Mesh<D>& back, std::span<const int> part_of,
                                   const std::vector<std::vector<SymMat<D>>>& log_metrics, long long* bytes_sent) {
  std::vector<std::vector<std::byte>> outgoing(static_cast<std::size_t>(process_count()));
  if (process_rank() == 0) {
    if (part_of.size() != static_cast<std::size_t>(back.element_count())) throw Error("a back-mesh scatter needs a process per element");
    for (int p = 0; p < process_count(); ++p)
      outgoing[p] = piece_of(back, {}, log_metrics, [&](Index k) { return part_of[k] == p; }).bytes();
  }
  if (bytes_sent) *bytes_sent += bytes_to_others(outgoing);
  return share_of_messages<D>(exchange_bytes(outgoing));
}

namespace {

// The cells of `region`'s grid that `box` meets, per axis the first and the last; false when it
// meets none.
template <int D>
bool cell_range(const ShareRegion<D>& region, const Box<D>& box, std::array<int, D>& first, std::array<int, D>& last) {
  if (region.box.is_empty() || !region.box.overlaps(box)) return false;
  for (int i = 0; i < D; ++i) {
    const double extent = region.box.upper[i] - region.box.lower[i];
    const auto cell = [&](double x) {
      return extent > 0 ? std::clamp(static_cast<int>((x - region.box.lower[i]) / extent * kShareCells), 0, kShareCells - 1) : 0;
    };
    first[i] = cell(box.lower[i]), last[i] = cell(box.upper[i]);
  }
  return true;
}

// Calls visit(cell index) for every cell from `first` to `last`.
template <int D, typename Visit>
void for_each_cell(const std::array<int, D>& first, const std::array<int, D>& last, Visit&& visit) {
  std::array<int, D> at = first;
  for (;;) {
    int index = 0;
    for (int i = D - 1; i >= 0; --i) index = index * kShareCells + at[i];
    visit(index);
    int i = 0;
    while (i < D && at[i] == last[i]) at[i] = first[i], ++i;
    if (i == D) return;
    ++at[i];
  }
}

}  // namespace

template <int D>
bool ShareRegion<D>::meets(const Box<D>& other) const {
  std::array<int, D> first, last;
  if (!cell_range<D>(*this, other, first, last)) return false;
  bool met = false;
  for_each_cell<D>(first, last, [&](int cell) { met = met || marked[cell]; });
  return met;
}

template <int D>
ShareRegion<D> share_region(const Mesh<D>& mesh) {
  ShareRegion<D> region;
  if (mesh.element_count() == 0) return region;
  region.box = vertex_box(mesh);
  const double margin = kShareMargin * norm(region.box.upper - region.box.lower);
  for (int i = 0; i < D; ++i) region.box.lower[i] -= margin, region.box.upper[i] += margin;
  std::array<char, ShareRegion<D>::kCells> met{};
  std::array<int, D> first, last;
  for (Index k = 0; k < mesh.element_count(); ++k)
    if (cell_range<D>(region, element_box(mesh, k), first, last)) for_each_cell<D>(first, last, [&](int cell) { met[cell] = 1; });
  // Each met cell and its neighbours.
  for (int cell = 0; cell < ShareRegion<D>::kCells; ++cell) {
    if (!met[cell]) continue;
    for (int i = 0, rest = cell; i < D; ++i, rest /= kShareCells) {
      const int at = rest % kShareCells;
      first[i] = std::max(at - 1, 0), last[i] = std::min(at + 1, kShareCells - 1);
    }
    for_each_cell<D>(first, last, [&](int near) { region.marked[near] = 1; });
  }
  return region;
}

template <int D>
BackMeshShare<D> share_around(const BackMeshShare<D>& home, const ShareRegion<D>& region, long long* bytes_sent) {
  const std::vector<ShareRegion<D>> regions = all_gather_value(region);
  std::vector<Box<D>> element_boxes;
  Box<D> home_box = Box<D>::empty();
  for (Index k = 0; k < home.mesh.element_count(); ++k) {
    element_boxes.push_back(element_box(home.mesh, k));
    home_box.add(element_boxes.back());
  }
  std::vector<std::vector<std::byte>> outgoing(regions.size());
  for (std::size_t p = 0; p < regions.size(); ++p)
    if (!home_box.is_empty() && home_box.overlaps(regions[p].box))  // (most regions, with many processes, lie elsewhere)
      outgoing[p] = piece_of(home.mesh, std::span<const Index>(home.global_ids), home.log_metrics, [&](Index k) {
                      return regions[p].meets(element_boxes[k]);
                    }).bytes();
  if (bytes_sent) *bytes_sent += bytes_to_others(outgoing);
  return share_of_messages<D>(exchange_bytes(outgoing));
}

template struct ShareRegion<2>;
template struct ShareRegion<3>;
template ShareRegion<2> share_region(const Mesh<2>&);
template ShareRegion<3> share_region(const Mesh<3>&);
template BackMeshShare<2> scatter_back_mesh(const Mesh<2>&, std::span<const int>, const std::vector<std::vector<SymMat<2>>>&, long long*);
template BackMeshShare<3> scatter_back_mesh(const Mesh<3>&, std::span<const int>, const std::vector<std::vector<SymMat<3>>>&, long long*);
template BackMeshShare<2> share_around(const BackMeshShare<2>&, const ShareRegion<2>&, long long*);
template BackMeshShare<3> share_around(const BackMeshShare<3>&, const ShareRegion<3>&, long long*);

}  // namespace hocav
