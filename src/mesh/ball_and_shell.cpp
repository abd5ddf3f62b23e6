#include "mesh/ball_and_shell.hpp"

#include <array>

#include "base/element_list.hpp"
#include "base/small_set.hpp"

namespace hocav {

template <int D>
int local_vertex(const Mesh<D>& mesh, Index k, Index v) {
  const auto& element = mesh.element(k);
  for (int i = 0; i <= D; ++i)
    if (element[i] == v) return i;
  return -1;
}

template <int D>
void collect_ball(const Mesh<D>& mesh, Index v, std::vector<Index>& ball) {
  ball.clear();
  Index start = mesh.vertex_element(v);
  if (start == kNoIndex) return;
  ElementList members(ball);  // a scan for the usual few dozen elements, hashed past that
  members.push_back(start);
  for (std::size_t next = 0; next < ball.size(); ++next) {
    Index k = ball[next];
    int own = local_vertex(mesh, k, v);
    for (int face = 0; face <= D; ++face) {
      if (face == own) continue;  // the face opposite v does not contain v
      Index neighbor = mesh.neighbor(k, face);
      if (neighbor != kNoIndex && !members.holds(neighbor)) {
        mesh.prefetch_element(neighbor);  // read when its turn comes, and by the ball's users
        members.push_back(neighbor);
      }
    }
  }
}

namespace {

// An element that contains both a and b: a walk through a's ball that stops at the first one.
template <int D>
Index element_of_edge(const Mesh<D>& mesh, Index a, Index b, std::vector<Index>& visited) {
  visited.clear();
  Index start = mesh.vertex_element(a);
  if (start == kNoIndex) return kNoIndex;
  ElementList members(visited);
  members.push_back(start);
  for (std::size_t next = 0; next < visited.size(); ++next) {
    const Index k = visited[next];
    if (local_vertex(mesh, k, b) >= 0) return k;
    const int own = local_vertex(mesh, k, a);
    for (int face = 0; face <= D; ++face) {
      const Index neighbor = face == own ? kNoIndex : mesh.neighbor(k, face);
      if (neighbor != kNoIndex && !members.holds(neighbor)) members.push_back(neighbor);
    }
  }
  return kNoIndex;
}

// From element k of edge (a, b), the next one around the edge across the face opposite `other`
// (a vertex of k other than a and b), or kNoIndex at the boundary.
template <int D>
Index turn_around_edge(const Mesh<D>& mesh, Index k, Index other) {
  return mesh.neighbor(k, local_vertex(mesh, k, other));
}

// The shell of (a, b) from element `start`, which holds both; inlined into both entry points below
// (collect_shell is on the P2 cavity operator's hot path).
template <int D>
inline void walk_shell(const Mesh<D>& mesh, Index start, Index a, Index b, std::vector<Index>& shell) {
  shell.clear();
  shell.push_back(start);
  // Each element of the shell has D − 1 vertices besides a and b; the faces opposite them hold the
  // edge. Turn one way until back at the start or at the boundary, then (open shell) the other way.
  const auto others = [&](Index k) {
    std::array<Index, D - 1> out{};
    int count = 0;
    for (Index v : mesh.element(k))
      if (v != a && v != b && count < D - 1) out[count++] = v;
    return out;
  };
  for (int side = 0; side < D - 1; ++side) {
    Index previous = start, k = turn_around_edge(mesh, start, others(start)[side]);
    while (k != kNoIndex && k != start) {
      shell.push_back(k);
      Index next = kNoIndex;
      for (Index v : others(k))
        if (const Index n = turn_around_edge(mesh, k, v); n != previous) next = n;
      previous = k;
      k = next;
    }
    if (k == start) break;  // closed shell: one way round found all
  }
}

}  // namespace

template <int D>
void collect_shell(const Mesh<D>& mesh, Index a, Index b, std::vector<Index>& shell) {
  const Index start = element_of_edge(mesh, a, b, shell);
  shell.clear();
  if (start != kNoIndex) walk_shell(mesh, start, a, b, shell);
}

template <int D>
void collect_shell_from(const Mesh<D>& mesh, Index start, Index a, Index b, std::vector<Index>& shell) {
  walk_shell(mesh, start, a, b, shell);
}

template <int D>
bool shell_is_closed(const Mesh<D>& mesh, std::span<const Index> shell, Index a, Index b) {
  for (Index k : shell)
    for (int face = 0; face <= D; ++face) {
      const auto& e = mesh.element(k);
      if (e[face] == a || e[face] == b) continue;  // the face opposite a or b misses the edge
      if (mesh.neighbor(k, face) == kNoIndex || mesh.element_face_facet(k, face) != kNoIndex) return false;
    }
  return true;
}

template <int D>
void other_vertices(const Mesh<D>& mesh, std::span<const Index> elements, Index a, Index b, std::vector<Index>& out) {
  out.clear();
  for (Index k : elements)
    for (Index v : mesh.element(k))
      if (v != a && v != b && !small_set_holds(out, v)) out.push_back(v);
}

template bool shell_is_closed(const Mesh<2>&, std::span<const Index>, Index, Index);
template bool shell_is_closed(const Mesh<3>&, std::span<const Index>, Index, Index);
template void other_vertices(const Mesh<2>&, std::span<const Index>, Index, Index, std::vector<Index>&);
template void other_vertices(const Mesh<3>&, std::span<const Index>, Index, Index, std::vector<Index>&);
template void collect_ball(const Mesh<2>&, Index, std::vector<Index>&);
template void collect_ball(const Mesh<3>&, Index, std::vector<Index>&);
template void collect_shell(const Mesh<2>&, Index, Index, std::vector<Index>&);
template void collect_shell(const Mesh<3>&, Index, Index, std::vector<Index>&);
template void collect_shell_from(const Mesh<2>&, Index, Index, Index, std::vector<Index>&);
template void collect_shell_from(const Mesh<3>&, Index, Index, Index, std::vector<Index>&);
template int local_vertex(const Mesh<2>&, Index, Index);
template int local_vertex(const Mesh<3>&, Index, Index);

}  // namespace hocav
