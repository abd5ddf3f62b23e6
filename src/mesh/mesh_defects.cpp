#include "mesh/mesh_defects.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "mesh/ball_and_shell.hpp"
#include "mesh/simplex.hpp"

namespace hocav {
namespace {

// An inner vertex's elements fill its full angle once; overlapping elements fill it twice or more.
// The margin leaves room for rounding without missing a second turn.
constexpr double kOverlapAngleRatio = 1.5;

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

std::vector<Index> NonManifoldPlaces::every_vertex() const {
  std::vector<Index> every = vertices;
  for (const std::uint64_t key : edges) {
    every.push_back(static_cast<Index>(key >> 32));
    every.push_back(static_cast<Index>(key & 0xffffffffu));
  }
  std::sort(every.begin(), every.end());
  every.erase(std::unique(every.begin(), every.end()), every.end());
  return every;
}

template <int D>
NonManifoldPlaces non_manifold_places(const Mesh<D>& mesh) {
  NonManifoldPlaces places;
  if (!mesh.has_topology()) return places;
  const auto vertex_count = static_cast<std::size_t>(mesh.vertex_count());
  std::vector<Index> incident(vertex_count, 0);
  std::vector<char> on_boundary(vertex_count, 0);
  std::vector<std::uint64_t> boundary_face_edges;  // 3D: each boundary face's edges
  for (Index k = 0; k < mesh.element_count(); ++k) {
    const auto& element = mesh.element(k);
    for (Index v : element) ++incident[v];
    for (int face = 0; face <= D; ++face) {
      if (mesh.neighbor(k, face) != kNoIndex) continue;
      const auto& local = face_vertices<D>(face);
      for (int j = 0; j < D; ++j) on_boundary[element[local[j]]] = 1;
      if constexpr (D == 3)
        for (int j = 0; j < 3; ++j) boundary_face_edges.push_back(Mesh<D>::edge_key(element[local[j]], element[local[(j + 1) % 3]]));
    }
  }
  // A walk around an inner vertex meets no boundary face, so it goes all around: only boundary
  // vertices are walked.
  std::vector<Index> ball;
  for (Index v = 0; v < mesh.vertex_count(); ++v) {
    if (!on_boundary[v]) continue;
    collect_ball(mesh, v, ball);  // reaches one side of a pinch only
    if (static_cast<Index>(ball.size()) < incident[v]) places.vertices.push_back(v);
  }
  std::sort(boundary_face_edges.begin(), boundary_face_edges.end());
  for (auto run = boundary_face_edges.begin(); run != boundary_face_edges.end();) {
    const auto end = std::upper_bound(run, boundary_face_edges.end(), *run);
    if (end - run > 2) places.edges.push_back(*run);
    run = end;
  }
  return places;
}

template <int D>
MeshDefects find_mesh_defects(const Mesh<D>& mesh, std::size_t max_examples) {
  DefectFinder finder(max_examples);
  MeshDefects& defects = finder.defects;
  if (!mesh.has_topology()) return defects;
  const auto vertex_count = static_cast<std::size_t>(mesh.vertex_count());
  std::vector<bool> on_boundary(vertex_count, false);
  std::vector<double> angle(vertex_count, 0.0);
  for (Index k = 0; k < mesh.element_count(); ++k) {
    const auto& element = mesh.element(k);
    for (int i = 0; i <= D; ++i) angle[element[static_cast<std::size_t>(i)]] += corner_angle(mesh, k, i);
    for (int face = 0; face <= D; ++face) {
      if (mesh.neighbor(k, face) != kNoIndex) continue;
      if (mesh.element_face_facet(k, face) == kNoIndex)
        finder.add(defects.open_faces, "face " + one_based(face) + " of element " + one_based(k) + " has no boundary facet");
      for (int j = 0; j < D; ++j)
        on_boundary[element[static_cast<std::size_t>(face_vertices<D>(face)[static_cast<std::size_t>(j)])]] = true;
    }
  }
  const NonManifoldPlaces places = non_manifold_places(mesh);
  const double full_angle = D == 2 ? 2 * std::numbers::pi : 4 * std::numbers::pi;
  auto pinched = places.vertices.begin();
  for (Index v = 0; v < mesh.vertex_count(); ++v) {
    if (pinched != places.vertices.end() && *pinched == v) {
      ++pinched;
      finder.add(defects.non_manifold_vertices, "vertex " + one_based(v) + " joins parts that share no face");
    } else if (!on_boundary[v] && angle[v] > kOverlapAngleRatio * full_angle) {
      finder.add(defects.overlap_vertices, "the elements around inner vertex " + one_based(v) + " overlap");
    }
  }
  for (const std::uint64_t key : places.edges)
    finder.add(defects.non_manifold_edges, "edge (" + one_based(static_cast<Index>(key >> 32)) + ", " +
                                               one_based(static_cast<Index>(key & 0xffffffffu)) + ") has more than two boundary faces");
  return defects;
}

template MeshDefects find_mesh_defects(const Mesh<2>&, std::size_t);
template MeshDefects find_mesh_defects(const Mesh<3>&, std::size_t);
template NonManifoldPlaces non_manifold_places(const Mesh<2>&);
template NonManifoldPlaces non_manifold_places(const Mesh<3>&);

}  // namespace hocav
