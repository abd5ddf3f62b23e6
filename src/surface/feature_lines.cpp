// Feature lines (docs/surface.md, "Feature lines").
#include "surface/feature_lines.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

namespace hocav {
namespace {

// The vertices joined to each vertex by an edge whose two facets are on different sides there.
std::vector<std::vector<Index>> feature_neighbours(const Mesh<3>& mesh, const SurfaceTopology<3>& topology,
                                                   const VertexNormals<3>& normals) {
  std::vector<std::vector<Index>> neighbours(static_cast<std::size_t>(mesh.vertex_count()));
  for (Index f = 0; f < mesh.facet_count(); ++f)
    for (int s = 0; s < 3; ++s) {
      const Index g = topology.neighbors[f][s];
      if (g == kNoIndex || g < f) continue;  // each edge once
      const std::array<int, 2> ends{(s + 1) % 3, (s + 2) % 3};
      for (int k = 0; k < 2; ++k) {
        const Index vertex = mesh.facet(f)[ends[k]], other = mesh.facet(f)[ends[1 - k]];
        if (normals.corner_sides[f][ends[k]] != normals.corner_sides[g][facet_local_vertex(mesh, g, vertex)])
          neighbours[vertex].push_back(other);
      }
    }
  return neighbours;
}

// The tangent at x of the circle through p, x, q (the line when they are aligned): for a circle,
// |p − x|² (q − x) − |q − x|² (p − x) is parallel to it.
Vec3 circle_tangent(const Vec3& p, const Vec3& x, const Vec3& q) {
  const Vec3 to_p = p - x, to_q = q - x;
  return dot(to_p, to_p) * to_q - dot(to_q, to_q) * to_p;
}

Vec3 unit_or_zero(const Vec3& v) {
  const double length = norm(v);
  return length > 0 ? v * (1 / length) : Vec3{};
}

template <int D>
std::vector<bool> listed_corners(const Mesh<D>& mesh) {
  std::vector<bool> listed(static_cast<std::size_t>(mesh.vertex_count()), false);
  for (const auto* ids : {&mesh.corners(), &mesh.required_vertices()})
    for (Index v : *ids)
      if (v >= 0 && v < mesh.vertex_count()) listed[v] = true;
  return listed;
}

// n_A × n_B of a vertex's two sides at a ridge (zero where no ridge passes).
Vec3 sides_tangent(const VertexNormals<3>& normals, const std::array<Index, 2>& sides) {
  return sides[0] == kNoIndex ? Vec3{} : cross(normals.normals[sides[0]], normals.normals[sides[1]]);
}

// A listed corner's branches meeting at more than this from a straight continuation make a turn.
const double kMaxTurn = 15 * std::numbers::pi / 180;

// Whether a line passes through v: two feature edges, and not an input corner.
bool passes_through(const FeatureLines<3>& lines, Index v) { return lines.neighbours[v].size() == 2 && !lines.input_corners[v]; }

// A branch leaving within this of the sides' n_A × n_B follows it: the angle under which the
// section fits merge sides, their accuracy.
const double kOnNormalsTangent = 5 * std::numbers::pi / 180;

// Whether the feature line turns at v: two branches whose tangents are more than kMaxTurn from
// opposite (where more meet, each pair of sides has its own n_A × n_B), neither of them along the
// tangent `across` of the sides' normals at a sharp ridge. Between two smooth sides the line is
// smooth with that tangent, and a branch that leaves along it shows the sides are smooth there:
// the other branch's one-sided circle then errs where the curvature varies (the ellipse a slanted
// plane cuts from a rounded corner starts at its sharpest), not because the line kinks.
bool line_turns_at(const Mesh<3>& mesh, const FeatureLines<3>& lines, Index v, const Vec3& across) {
  const auto& neighbours = lines.neighbours[v];
  if (neighbours.size() != 2) return false;
  const Vec3 first = branch_tangent(mesh, lines, v, neighbours[0]), second = branch_tangent(mesh, lines, v, neighbours[1]);
  if (dot(first, second) <= -std::cos(kMaxTurn)) return false;
  if (!(norm(across) > kSharpRidgeSine)) return true;
  const Vec3 line = unit_or_zero(across);
  const double along = std::max(std::abs(dot(first, line)), std::abs(dot(second, line)));
  return along < std::cos(kOnNormalsTangent);
}

}  // namespace

template <int D>
FeatureLines<D> find_feature_lines(const Mesh<D>& mesh, [[maybe_unused]] const SurfaceTopology<D>& topology,
                                   [[maybe_unused]] VertexNormals<D>& normals, [[maybe_unused]] LineTangents rule) {
  FeatureLines<D> lines;
  lines.tangents.assign(static_cast<std::size_t>(mesh.vertex_count()), Vec<D>{});
  lines.neighbours.resize(static_cast<std::size_t>(mesh.vertex_count()));
  lines.input_corners = listed_corners(mesh);
  lines.turns.assign(static_cast<std::size_t>(mesh.vertex_count()), false);
  if constexpr (D == 3) {
    lines.neighbours = feature_neighbours(mesh, topology, normals);
    std::vector<std::array<Index, 2>> side_pair(static_cast<std::size_t>(mesh.vertex_count()), {kNoIndex, kNoIndex});
    for (Index f = 0; f < mesh.facet_count(); ++f)
      for (int s = 0; s < 3; ++s) {
        const Index g = topology.neighbors[f][s];
        if (g == kNoIndex) continue;
        for (int k = 1; k <= 2; ++k) {
          const int i = (s + k) % 3;
          const Index vertex = mesh.facet(f)[i];
          const Index a = normals.corner_sides[f][i], b = normals.corner_sides[g][facet_local_vertex(mesh, g, vertex)];
          if (a != b) side_pair[vertex] = {a, b};
        }
      }
    for (Index v = 0; v < mesh.vertex_count(); ++v)
      if (passes_through(lines, v)) {
        const Vec3 across = sides_tangent(normals, side_pair[v]);
        if (rule == LineTangents::kSharpFromNormals && norm(across) > kSharpRidgeSine) {
          lines.tangents[v] = unit_or_zero(across);
          continue;
        }
        lines.tangents[v] = unit_or_zero(
            circle_tangent(mesh.vertex(lines.neighbours[v][0]), mesh.vertex(v), mesh.vertex(lines.neighbours[v][1])));
      }
    for (Index v = 0; v < mesh.vertex_count(); ++v)
      if (lines.input_corners[v]) lines.turns[v] = line_turns_at(mesh, lines, v, sides_tangent(normals, side_pair[v]));
    for (Index f = 0; f < mesh.facet_count(); ++f)
      for (int i = 0; i < 3; ++i) {
        const Vec3& tangent = lines.tangents[mesh.facet(f)[i]];
        Vec3& normal = normals.normals[normals.corner_sides[f][i]];
        const Vec3 orthogonal = normal - dot(normal, tangent) * tangent;
        if (norm(orthogonal) > 0) normal = orthogonal * (1 / norm(orthogonal));
      }
  }
  return lines;
}

Vec3 branch_tangent(const Mesh<3>& mesh, const FeatureLines<3>& lines, Index v, Index w) {
  const Vec3 chord = mesh.vertex(w) - mesh.vertex(v);
  if (!passes_through(lines, w)) return unit_or_zero(chord);
  const auto& beyond = lines.neighbours[w];
  const Index next = beyond[0] == v ? beyond[1] : beyond[0];
  const Vec3 tangent = unit_or_zero(circle_tangent(mesh.vertex(w), mesh.vertex(v), mesh.vertex(next)));
  return dot(tangent, chord) < 0 ? -tangent : tangent;
}

template FeatureLines<2> find_feature_lines(const Mesh<2>&, const SurfaceTopology<2>&, VertexNormals<2>&, LineTangents);
template FeatureLines<3> find_feature_lines(const Mesh<3>&, const SurfaceTopology<3>&, VertexNormals<3>&, LineTangents);

}  // namespace hocav
