#include "mesh/ball_and_shell.hpp"

#include <algorithm>

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
  ball.push_back(start);
  // Balls hold a few dozen elements: a linear membership test beats any set.
  for (std::size_t next = 0; next < ball.size(); ++next) {
    Index k = ball[next];
    int own = local_vertex(mesh, k, v);
    for (int face = 0; face <= D; ++face) {
      if (face == own) continue;  // the face opposite v does not contain v
      Index neighbor = mesh.neighbor(k, face);
      if (neighbor != kNoIndex && std::find(ball.begin(), ball.end(), neighbor) == ball.end()) {
        mesh.prefetch_element(neighbor);  // read when its turn comes, and by the ball's users
        ball.push_back(neighbor);
      }
    }
  }
}

template <int D>
void collect_shell(const Mesh<D>& mesh, Index a, Index b, std::vector<Index>& shell) {
  collect_ball(mesh, a, shell);
  std::erase_if(shell, [&](Index k) { return local_vertex(mesh, k, b) < 0; });
}

template void collect_ball(const Mesh<2>&, Index, std::vector<Index>&);
template void collect_ball(const Mesh<3>&, Index, std::vector<Index>&);
template void collect_shell(const Mesh<2>&, Index, Index, std::vector<Index>&);
template void collect_shell(const Mesh<3>&, Index, Index, std::vector<Index>&);
template int local_vertex(const Mesh<2>&, Index, Index);
template int local_vertex(const Mesh<3>&, Index, Index);

}  // namespace hocav
