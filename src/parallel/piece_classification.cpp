#include "parallel/piece_classification.hpp"

#include <unordered_set>

#include "adapt/vertex_classes.hpp"

namespace hocav {
namespace {

// What the classification added to the boundary, by global vertex ids: its corners, and its
// feature lines with their refs.
struct FoundFeatures {
  std::vector<Index> corners;
  std::vector<std::array<Index, 2>> lines;
  std::vector<int> line_refs;
};

template <int D>
FoundFeatures classify_boundary(MeshPart<D>& boundary, double feature_angle_degrees) {
  Mesh<D>& mesh = boundary.mesh;
  const std::size_t corners_before = mesh.corners().size();
  const Index lines_before = mesh.line_count();
  classify_vertices(mesh, feature_angle_degrees, NonManifoldPlaces{});
  FoundFeatures found;
  for (std::size_t c = corners_before; c < mesh.corners().size(); ++c) found.corners.push_back(boundary.global_ids[mesh.corners()[c]]);
  for (Index l = lines_before; l < mesh.line_count(); ++l) {
    found.lines.push_back({boundary.global_ids[mesh.line(l)[0]], boundary.global_ids[mesh.line(l)[1]]});
    found.line_refs.push_back(mesh.line_ref(l));
  }
  return found;
}

// The keys (Mesh::edge_key of local ids) of the edges of the piece's elements.
template <int D>
std::unordered_set<std::uint64_t> element_edge_keys(const Mesh<D>& mesh) {
  std::unordered_set<std::uint64_t> keys;
  for (const auto& element : mesh.elements())
    for (int i = 0; i <= D; ++i)
      for (int j = i + 1; j <= D; ++j) keys.insert(Mesh<D>::edge_key(element[i], element[j]));
  return keys;
}

// Adds to the piece what `found` lists that it holds: a corner at a vertex of its, a feature line
// (a ridge) along an edge of its elements.
template <int D>
void add_found_features(MeshPart<D>& piece, const FoundFeatures& found) {
  Mesh<D>& mesh = piece.mesh;
  const std::unordered_map<Index, Index> local = local_ids_of(piece);
  const auto local_of = [&](Index global) {
    const auto at = local.find(global);
    return at == local.end() ? kNoIndex : at->second;
  };
  for (Index global : found.corners)
    if (const Index v = local_of(global); v != kNoIndex) mesh.corners().push_back(v);
  if (found.lines.empty()) return;
  const std::unordered_set<std::uint64_t> edges = element_edge_keys(mesh);
  for (std::size_t l = 0; l < found.lines.size(); ++l) {
    const Index a = local_of(found.lines[l][0]), b = local_of(found.lines[l][1]);
    if (a != kNoIndex && b != kNoIndex && edges.contains(Mesh<D>::edge_key(a, b)))
      mesh.ridges().push_back(mesh.add_line({a, b}, found.line_refs[l]));
  }
}

}  // namespace

template <int D>
void classify_piece_vertices(MeshPart<D>& piece, MeshPart<D> boundary, double feature_angle_degrees) {
  add_found_features(piece, classify_boundary(boundary, feature_angle_degrees));
}

template void classify_piece_vertices(MeshPart<2>&, MeshPart<2>, double);
template void classify_piece_vertices(MeshPart<3>&, MeshPart<3>, double);

}  // namespace hocav
