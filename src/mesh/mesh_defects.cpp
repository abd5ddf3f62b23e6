#include "mesh/mesh_defects.hpp"

#include <cmath>
#include <numbers>
#include <unordered_map>

#include "mesh/ball_and_shell.hpp"
#include "mesh/simplex.hpp"

namespace hocav {
namespace {

// An inner vertex's elements fill its full angle once; overlapping elements fill it twice or more.
// The margin leaves room for rounding without missing a second turn.
constexpr double kOverlapAngleRatio = 1.5;

std::string id(Index i) { return std::to_string(static_cast<long long>(i) + 1); }

std::string counted(Index count, const std::string& singular, const std::string& plural) {
  return std::to_string(count) + " " + (count == 1 ? singular : plural);
}

class DefectFinder {
 public:
  explicit DefectFinder(std::size_t max_examples) : max_examples_(max_examples) {}
  void add(Index& counter, const std::string& example) {
    ++counter;
    if (defects.examples.size() < max_examples_) defects.examples.push_back(example);
  }
  MeshDefects defects;

 private:
  std::size_t max_examples_;
};

// The angle (2D) or solid angle (3D) of element k at its local vertex i.
template <int D>
double corner_angle(const Mesh<D>& mesh, Index k, int i) {
  const auto& element = mesh.element(k);
  const auto& apex = mesh.vertex(element[static_cast<std::size_t>(i)]);
  std::array<Vec<D>, D> sides;
  for (int j = 0; j < D; ++j)
    sides[static_cast<std::size_t>(j)] = mesh.vertex(element[static_cast<std::size_t>((i + 1 + j) % (D + 1))]) - apex;
  if constexpr (D == 2) {
    return std::abs(std::atan2(sides[0][0] * sides[1][1] - sides[0][1] * sides[1][0], dot(sides[0], sides[1])));
  } else {
    // Van Oosterom and Strackee: tan(Ω/2) = |a·(b×c)| / (abc + (a·b)c + (a·c)b + (b·c)a).
    const double a = norm(sides[0]), b = norm(sides[1]), c = norm(sides[2]);
    const double numerator = std::abs(determinant(sides[0], sides[1], sides[2]));
    const double denominator = a * b * c + dot(sides[0], sides[1]) * c + dot(sides[0], sides[2]) * b + dot(sides[1], sides[2]) * a;
    return 2 * std::atan2(numerator, denominator);
  }
}

}  // namespace

std::string MeshDefects::summary() const {
  std::string text;
  auto append = [&text](Index count, const std::string& singular, const std::string& plural) {
    if (count > 0) text += (text.empty() ? "" : ", ") + counted(count, singular, plural);
  };
  append(open_faces, "open boundary face (no boundary facet)", "open boundary faces (no boundary facet)");
  append(non_manifold_vertices, "non-manifold vertex", "non-manifold vertices");
  append(non_manifold_edges, "non-manifold edge", "non-manifold edges");
  append(overlap_vertices, "vertex with overlapping elements", "vertices with overlapping elements");
  if (examples.empty()) return text;
  text += " (first: ";
  for (std::size_t i = 0; i < examples.size(); ++i) text += (i == 0 ? "" : "; ") + examples[i];
  return text + ")";
}

template <int D>
MeshDefects find_mesh_defects(const Mesh<D>& mesh, std::size_t max_examples) {
  DefectFinder finder(max_examples);
  MeshDefects& defects = finder.defects;
  if (!mesh.has_topology()) return defects;
  const auto vertex_count = static_cast<std::size_t>(mesh.vertex_count());
  std::vector<Index> incident(vertex_count, 0);
  std::vector<bool> on_boundary(vertex_count, false);
  std::vector<double> angle(vertex_count, 0.0);
  std::unordered_map<std::uint64_t, int> boundary_edge_uses;  // 3D: boundary faces around each edge
  for (Index k = 0; k < mesh.element_count(); ++k) {
    const auto& element = mesh.element(k);
    for (int i = 0; i <= D; ++i) {
      const Index v = element[static_cast<std::size_t>(i)];
      ++incident[v];
      angle[v] += corner_angle(mesh, k, i);
    }
    for (int face = 0; face <= D; ++face) {
      if (mesh.neighbor(k, face) != kNoIndex) continue;
      if (mesh.element_face_facet(k, face) == kNoIndex)
        finder.add(defects.open_faces, "face " + std::to_string(face + 1) + " of element " + id(k) + " has no boundary facet");
      const auto& local = face_vertices<D>(face);
      for (int j = 0; j < D; ++j) on_boundary[element[static_cast<std::size_t>(local[static_cast<std::size_t>(j)])]] = true;
      if constexpr (D == 3)
        for (int j = 0; j < 3; ++j) {
          Index a = element[static_cast<std::size_t>(local[static_cast<std::size_t>(j)])];
          Index b = element[static_cast<std::size_t>(local[static_cast<std::size_t>((j + 1) % 3)])];
          if (a > b) std::swap(a, b);
          ++boundary_edge_uses[(static_cast<std::uint64_t>(a) << 32) | b];
        }
    }
  }
  std::vector<Index> ball;
  const double full_angle = D == 2 ? 2 * std::numbers::pi : 4 * std::numbers::pi;
  for (Index v = 0; v < mesh.vertex_count(); ++v) {
    if (incident[v] == 0) continue;
    collect_ball(mesh, v, ball);  // reaches one side of a pinch only
    if (static_cast<Index>(ball.size()) < incident[v])
      finder.add(defects.non_manifold_vertices, "vertex " + id(v) + " joins parts that share no face");
    else if (!on_boundary[v] && angle[v] > kOverlapAngleRatio * full_angle)
      finder.add(defects.overlap_vertices, "the elements around inner vertex " + id(v) + " overlap");
  }
  for (const auto& [key, uses] : boundary_edge_uses)
    if (uses > 2)
      finder.add(defects.non_manifold_edges, "edge (" + id(static_cast<Index>(key >> 32)) + ", " +
                                                 id(static_cast<Index>(key & 0xffffffffu)) + ") has " + std::to_string(uses) +
                                                 " boundary faces");
  return defects;
}

template MeshDefects find_mesh_defects(const Mesh<2>&, std::size_t);
template MeshDefects find_mesh_defects(const Mesh<3>&, std::size_t);

}  // namespace hocav
