#include "mesh/baffle_orientation.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
#include <tuple>

namespace hocav {
namespace {

// A side of a baffle facet (an edge in 3D, a vertex in 2D) with the direction the facet gives it:
// two facets of a patch agree when they give their shared side opposite directions.
struct BaffleSide {
  int ref;
  std::uint64_t key;  // the side without its direction
  int direction;      // +1 or -1
  std::size_t baffle;
  auto order() const { return std::tie(ref, key); }
};

template <int D>
bool is_baffle(const Mesh<D>& mesh, Index f) {
  if (mesh.facet_removed(f)) return false;
  const Index k = mesh.facet_element_face(f) / (D + 1);
  const Index across = mesh.neighbor(k, static_cast<int>(mesh.facet_element_face(f) % (D + 1)));
  return across != kNoIndex && mesh.element_ref(across) == mesh.element_ref(k);
}

template <int D>
void append_sides(const typename Mesh<D>::Facet& facet, int ref, std::size_t baffle, std::vector<BaffleSide>& sides) {
  if constexpr (D == 2) {
    sides.push_back({ref, static_cast<std::uint64_t>(facet[0]), -1, baffle});  // the tail
    sides.push_back({ref, static_cast<std::uint64_t>(facet[1]), +1, baffle});  // the head
  } else {
    for (int i = 0; i < 3; ++i) {
      const auto a = static_cast<std::uint64_t>(facet[i]), b = static_cast<std::uint64_t>(facet[(i + 1) % 3]);
      sides.push_back({ref, std::min(a, b) << 32 | std::max(a, b), a < b ? +1 : -1, baffle});
    }
  }
}

// Per baffle, the sides it shares with exactly one other baffle of its ref, each as positions in
// the sorted side list: (its own, the other baffle's).
using SharedSides = std::vector<std::vector<std::array<std::size_t, 2>>>;

// Per baffle, whether to turn it (1) or not (0): each patch is walked from its first baffle, kept,
// and each baffle reached is turned when it gives the side it was reached by the same direction.
std::vector<signed char> turns_by_patch(const std::vector<BaffleSide>& sides, const SharedSides& shared) {
  std::vector<signed char> turn(shared.size(), -1);  // -1: not reached yet
  std::vector<std::size_t> stack;
  for (std::size_t seed = 0; seed < shared.size(); ++seed) {
    if (turn[seed] >= 0) continue;
    turn[seed] = 0;
    stack.assign(1, seed);
    while (!stack.empty()) {
      const std::size_t b = stack.back();
      stack.pop_back();
      for (const auto& [own, other] : shared[b]) {
        const BaffleSide& there = sides[other];
        if (turn[there.baffle] >= 0) continue;  // reached: it agrees, or the patch cannot be oriented
        const int direction_here = turn[b] == 1 ? -sides[own].direction : sides[own].direction;
        turn[there.baffle] = there.direction == direction_here ? 1 : 0;
        stack.push_back(there.baffle);
      }
    }
  }
  return turn;
}

}  // namespace

template <int D>
std::vector<char> baffle_turns(std::span<const typename Mesh<D>::Facet> baffles, std::span<const int> refs) {
  std::vector<BaffleSide> sides;
  for (std::size_t b = 0; b < baffles.size(); ++b) append_sides<D>(baffles[b], refs[b], b, sides);
  std::stable_sort(sides.begin(), sides.end(), [](const BaffleSide& x, const BaffleSide& y) { return x.order() < y.order(); });
  // Per baffle, each side it shares with exactly one other baffle of its ref.
  SharedSides shared(baffles.size());
  for (std::size_t first = 0, last; first < sides.size(); first = last) {
    for (last = first + 1; last < sides.size() && sides[last].order() == sides[first].order();) ++last;
    if (last - first != 2) continue;  // a patch's border, or a junction of three or more
    shared[sides[first].baffle].push_back({first, first + 1});
    shared[sides[first + 1].baffle].push_back({first + 1, first});
  }
  std::vector<char> turns;
  for (signed char turn : turns_by_patch(sides, shared)) turns.push_back(static_cast<char>(turn == 1));
  return turns;
}

template <int D>
std::vector<Index> baffle_facets_to_turn(const Mesh<D>& mesh) {
  std::vector<Index> baffles;
  std::vector<typename Mesh<D>::Facet> vertices;
  std::vector<int> refs;
  for (Index f = 0; f < mesh.facet_count(); ++f)
    if (is_baffle(mesh, f)) {
      baffles.push_back(f);
      vertices.push_back(mesh.facet(f));
      refs.push_back(mesh.facet_ref(f));
    }
  const std::vector<char> turns = baffle_turns<D>(vertices, refs);
  std::vector<Index> to_turn;
  for (std::size_t b = 0; b < baffles.size(); ++b)
    if (turns[b]) to_turn.push_back(baffles[b]);
  return to_turn;
}

template std::vector<Index> baffle_facets_to_turn(const Mesh<2>&);
template std::vector<Index> baffle_facets_to_turn(const Mesh<3>&);
template std::vector<char> baffle_turns<2>(std::span<const Mesh<2>::Facet>, std::span<const int>);
template std::vector<char> baffle_turns<3>(std::span<const Mesh<3>::Facet>, std::span<const int>);

}  // namespace hocav
