#include "cavity/cavity_operations.hpp"

#include <algorithm>
#include <cmath>
#include <span>

#include "base/element_list.hpp"
#include "geom/barycentric.hpp"
#include "mesh/ball_and_shell.hpp"
#include "mesh/measure.hpp"

namespace hocav {
namespace {

// A new element thinner than this times its longest edge to the power D is flat: the cavity
// operator's default bound.
constexpr double kVisibleMeasure = CavityOptions{}.min_relative_measure;

template <int D>
CavityStatus plan_and_commit(Mesh<D>& mesh, CavityWorkspace<D>& work, Index vertex, const CavityOptions& options) {
  CavityStatus status = work.cavity_operator.plan(mesh, work.cavity, vertex, options);
  if (status == CavityStatus::kAccepted) work.cavity_operator.commit(mesh);
  return status;
}

// Whether x lies strictly inside the circumsphere of element k, distances measured in `metric`.
template <int D>
bool in_circumsphere(const Mesh<D>& mesh, Index k, const Vec<D>& x, const SymMat<D>& metric) {
  // The centre c solves (p_i − p_0)ᵀ M (c − p_0) = |p_i − p_0|²_M / 2 for i = 1..D.
  const auto& e = mesh.element(k);
  double a[D][D + 1];
  for (int i = 0; i < D; ++i) {
    Vec<D> edge = mesh.vertex(e[i + 1]) - mesh.vertex(e[0]);
    Vec<D> row = metric * edge;
    for (int j = 0; j < D; ++j) a[i][j] = row[j];
    a[i][D] = 0.5 * quadratic_form(metric, edge);
  }
  // Gaussian elimination with partial pivoting on the D × (D + 1) system.
  for (int col = 0; col < D; ++col) {
    int pivot = col;
    for (int r = col + 1; r < D; ++r)
      if (std::abs(a[r][col]) > std::abs(a[pivot][col])) pivot = r;
    if (a[pivot][col] == 0) return false;
    std::swap(a[pivot], a[col]);
    for (int r = 0; r < D; ++r) {
      if (r == col) continue;
      double factor = a[r][col] / a[col][col];
      for (int j = col; j <= D; ++j) a[r][j] -= factor * a[col][j];
    }
  }
  Vec<D> offset;  // c − p_0
  for (int i = 0; i < D; ++i) offset[i] = a[i][D] / a[i][i];
  double radius2 = quadratic_form(metric, offset);
  return quadratic_form(metric, x - mesh.vertex(e[0]) - offset) < radius2 * (1 - 1e-12);
}

// Whether element k with its vertex opposite `face` moved to x keeps a positive measure (beyond
// the cavity operator's flatness bound): then x sees that face of k from inside.
template <int D>
bool sees_face(const Mesh<D>& mesh, Index k, int face, const Vec<D>& x) {
  SimplexPoints<D> points;
  for (int i = 0; i <= D; ++i) points[i] = i == face ? x : mesh.vertex(mesh.element(k)[i]);
  const double measure = signed_measure<D>(points);
  if (!(measure > 0)) return false;
  double longest2 = 0;
  for (int i = 0; i <= D; ++i)
    for (int j = 0; j < i; ++j) longest2 = std::max(longest2, dot(points[i] - points[j], points[i] - points[j]));
  const double longest_power = D == 2 ? longest2 : longest2 * std::sqrt(longest2);  // |longest|^D without pow
  return measure > kVisibleMeasure * longest_power;
}

// Whether x sees every face of element k on the cavity's boundary.
template <int D>
bool sees_boundary_faces(const Mesh<D>& mesh, const ElementList& cavity, Index k, const Vec<D>& x) {
  for (int face = 0; face <= D; ++face) {
    const Index n = mesh.neighbor(k, face);
    if ((n == kNoIndex || !cavity.holds(n)) && !sees_face(mesh, k, face, x)) return false;
  }
  return true;
}

// Moves the elements past the cavity's first `kept` that have a boundary face x does not see to
// `dropped`; false when there was none.
template <int D>
bool drop_hidden(const Mesh<D>& mesh, std::vector<Index>& cavity, std::size_t kept, std::vector<Index>& dropped, const Vec<D>& x) {
  std::vector<char> hidden(cavity.size(), 0);
  {
    const ElementList members(cavity);
    for (std::size_t i = kept; i < cavity.size(); ++i) hidden[i] = !sees_boundary_faces<D>(mesh, members, cavity[i], x);
  }
  if (std::find(hidden.begin(), hidden.end(), 1) == hidden.end()) return false;
  std::size_t out = 0;
  for (std::size_t i = 0; i < cavity.size(); ++i)
    if (hidden[i])
      dropped.push_back(cavity[i]);
    else
      cavity[out++] = cavity[i];
  cavity.resize(out);
  return true;
}

// Moves the elements past the cavity's first `kept` that the first `kept` do not reach through
// faces inside the cavity to `dropped`; the cavity keeps the reached ones, in the order reached.
template <int D>
void keep_connected(const Mesh<D>& mesh, std::vector<Index>& cavity, std::size_t kept, std::vector<Index>& dropped) {
  std::vector<Index> reached(cavity.begin(), cavity.begin() + static_cast<std::ptrdiff_t>(kept));
  ElementList is_reached(reached);
  {
    const ElementList in_cavity(cavity);
    for (std::size_t next = 0; next < reached.size(); ++next)
      for (int face = 0; face <= D; ++face) {
        const Index n = mesh.neighbor(reached[next], face);
        if (n != kNoIndex && in_cavity.holds(n) && !is_reached.holds(n)) is_reached.push_back(n);
      }
  }
  for (Index k : cavity)
    if (!is_reached.holds(k)) dropped.push_back(k);
  cavity.swap(reached);
}

}  // namespace

template <int D>
void make_star_shaped(const Mesh<D>& mesh, std::vector<Index>& cavity, std::size_t kept, std::vector<Index>& dropped, const Vec<D>& x) {
  while (drop_hidden(mesh, cavity, kept, dropped, x)) keep_connected(mesh, cavity, kept, dropped);
}

template <int D>
void grow_delaunay_cavity(const Mesh<D>& mesh, std::vector<Index>& cavity, std::vector<Index>& refused, const Vec<D>& x,
                          const SymMat<D>& metric) {
  // An element refused once is not tested again from its other faces on the cavity.
  refused.clear();
  ElementList in_cavity(cavity), tested(refused);
  for (std::size_t next = 0; next < cavity.size(); ++next)
    for (int face = 0; face <= D; ++face) {
      Index n = mesh.neighbor(cavity[next], face);
      if (n == kNoIndex || in_cavity.holds(n) || tested.holds(n)) continue;
      if (mesh.face_has_facet(cavity[next], face)) continue;  // stay on one side of surfaces
      if (in_circumsphere(mesh, n, x, metric))
        in_cavity.push_back(n);
      else
        tested.push_back(n);
    }
}

template <int D>
CavityStatus reinsert_vertex(Mesh<D>& mesh, CavityWorkspace<D>& work, Index v, const CavityOptions& options) {
  collect_ball(mesh, v, work.cavity);
  return plan_and_commit(mesh, work, v, options);
}

template <int D>
CavityStatus collapse_edge(Mesh<D>& mesh, CavityWorkspace<D>& work, Index removed, Index kept, CavityOptions options) {
  collect_ball(mesh, removed, work.cavity);
  options.removable_vertex = removed;
  return plan_and_commit(mesh, work, kept, options);
}

template <int D>
CavityStatus swap_edge(Mesh<D>& mesh, CavityWorkspace<D>& work, Index a, Index b, Index apex, const CavityOptions& options) {
  collect_shell(mesh, a, b, work.cavity);
  return plan_and_commit(mesh, work, apex, options);
}

template <int D>
CavityStatus insert_vertex(Mesh<D>& mesh, CavityWorkspace<D>& work, const Vec<D>& x, Index hint, const SymMat<D>& metric,
                           const CavityOptions& options, Index* inserted) {
  // The element containing x, by a walk from the hint.
  Index k = hint;
  for (int step = 0; step < 100000; ++step) {
    SimplexPoints<D> points;
    for (int i = 0; i <= D; ++i) points[i] = mesh.vertex(mesh.element(k)[i]);
    auto lambda = barycentric_coordinates<D>(points, x);
    int face = static_cast<int>(std::min_element(lambda.begin(), lambda.end()) - lambda.begin());
    if (lambda[face] >= 0) break;
    Index next = mesh.neighbor(k, face);
    if (next == kNoIndex) return CavityStatus::kNotStarShaped;  // outside the mesh
    k = next;
  }
  work.cavity.assign(1, k);
  grow_delaunay_cavity(mesh, work.cavity, work.refused, x, metric);
  Index vertex = mesh.add_vertex(x);
  CavityStatus status = plan_and_commit(mesh, work, vertex, options);
  if (status != CavityStatus::kAccepted)
    mesh.pop_vertex();
  else if (inserted)
    *inserted = vertex;
  return status;
}

#define HOCAV_INSTANTIATE(D)                                                                                                     \
  template void grow_delaunay_cavity(const Mesh<D>&, std::vector<Index>&, std::vector<Index>&, const Vec<D>&, const SymMat<D>&); \
  template void make_star_shaped(const Mesh<D>&, std::vector<Index>&, std::size_t, std::vector<Index>&, const Vec<D>&);          \
  template CavityStatus reinsert_vertex(Mesh<D>&, CavityWorkspace<D>&, Index, const CavityOptions&);                             \
  template CavityStatus collapse_edge(Mesh<D>&, CavityWorkspace<D>&, Index, Index, CavityOptions);                               \
  template CavityStatus swap_edge(Mesh<D>&, CavityWorkspace<D>&, Index, Index, Index, const CavityOptions&);                     \
  template CavityStatus insert_vertex(Mesh<D>&, CavityWorkspace<D>&, const Vec<D>&, Index, const SymMat<D>&, const CavityOptions&, Index*);
HOCAV_INSTANTIATE(2)
HOCAV_INSTANTIATE(3)
#undef HOCAV_INSTANTIATE

}  // namespace hocav
