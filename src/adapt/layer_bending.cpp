#include "adapt/layer_bending.hpp"

#include "adapt/element_guard.hpp"

#include <algorithm>
#include <limits>
#include <optional>

#include "base/bisection.hpp"
#include "base/element_list.hpp"
#include "base/index_hash_map.hpp"
#include "geom/closest_point.hpp"
#include "mesh/ball_and_shell.hpp"
#include "mesh/simplex.hpp"

namespace hocav {
namespace {

constexpr std::size_t kMostPatchElements = 4096;

template <int D>
struct NodeMove {
  Index edge;
  Vec<D> start, move;
};

// The elements reached from `seeds` across faces with a vertex within `radius` of `center`.
template <int D>
std::vector<Index> patch_around(const Mesh<D>& mesh, const std::vector<Index>& seeds, const Vec<D>& center, double radius) {
  std::vector<Index> patch(seeds);
  ElementList members(patch);
  auto near = [&](Index k) {
    for (Index v : mesh.element(k))
      if (norm(mesh.vertex(v) - center) < radius) return true;
    return false;
  };
  for (std::size_t next = 0; next < patch.size() && patch.size() < kMostPatchElements; ++next)
    for (int face = 0; face <= D; ++face) {
      const Index n = mesh.neighbor(patch[next], face);
      if (n != kNoIndex && !members.holds(n) && near(n)) members.push_back(n);
    }
  return patch;
}

// The facets on the faces of these elements, once each.
template <int D>
std::vector<Index> facets_of(const Mesh<D>& mesh, const std::vector<Index>& elements) {
  std::vector<Index> facets;
  for (Index k : elements)
    for (int face = 0; face <= D; ++face)
      if (const Index f = mesh.element_face_facet(k, face); f != kNoIndex) facets.push_back(f);
  std::sort(facets.begin(), facets.end());
  facets.erase(std::unique(facets.begin(), facets.end()), facets.end());
  return facets;
}

// Weights of the point of facet `corners` closest to x.
template <int D>
std::array<double, D> closest_weights(const std::array<Vec<D>, D>& corners, const Vec<D>& x) {
  if constexpr (D == 2)
    return closest_on_segment<2>(corners[0], corners[1], x);
  else
    return closest_on_triangle(corners[0], corners[1], corners[2], x);
}

template <int D>
class Bend {
 public:
  Bend(Mesh<D>& mesh, const BoundaryProposals<D>& proposals, const LayerBendOptions<D>& options)
      : mesh_(mesh), proposals_(proposals), options_(options) {}

  LayerBend run(Index a, Index b) {
    const Index edge = mesh_.find_edge(a, b);
    const auto target = proposals_.find(a, b);
    if (edge == kNoIndex || !target) return {};
    std::vector<Index> shell;
    collect_shell(mesh_, a, b, shell);
    const Vec<D> center = 0.5 * (mesh_.vertex(a) + mesh_.vertex(b));
    reach_ = options_.reach_in_bows * bow(a, b, *target);
    const auto patch = patch_around(mesh_, shell, center, 0.5 * norm(mesh_.vertex(b) - mesh_.vertex(a)) + reach_);
    plan_wall_moves(facets_of(mesh_, patch));
    plan_volume_moves(patch);
    guard_.emplace(mesh_, moved_elements(), options_.jacobian_floor, options_.field);
    return made();
  }

 private:
  // Every edge of the wall's facets, toward its proposal (no move when it has none).
  void plan_wall_moves(const std::vector<Index>& facets) {
    for (Index f : facets) {
      const auto& vertices = mesh_.facet(f);
      for (int i = 0; i < D; ++i)
        for (int j = i + 1; j < D; ++j) {
          const Index edge = mesh_.find_edge(vertices[i], vertices[j]);
          if (edge == kNoIndex || planned(edge)) continue;
          const auto target = proposals_.find(vertices[i], vertices[j]);
          plan(edge, target ? *target - mesh_.edge_node(edge) : Vec<D>{});
          if (!target) continue;
          result_.wall_edges.push_back({vertices[i], vertices[j]});
          reach_ = std::max(reach_, options_.reach_in_bows * bow(vertices[i], vertices[j], *target));
        }
      wall_.push_back(f);
    }
  }

  // How far the wall edge (a, b) bows at its proposal: from the chord's middle, or from its node when
  // that is farther. The layers above must follow the whole bow, also where a cavity placed the node
  // part of the way and left them behind.
  double bow(Index a, Index b, const Vec<D>& target) const {
    const Vec<D> middle = 0.5 * (mesh_.vertex(a) + mesh_.vertex(b));
    return std::max(norm(target - middle), norm(target - mesh_.edge_node(mesh_.find_edge(a, b))));
  }

  // A volume edge's node moves by the wall's P2 displacement at its foot (the closest point of the
  // wall's facets), faded linearly with the distance to it.
  void plan_volume_moves(const std::vector<Index>& patch) {
    for (Index k : patch)
      for (int l = 0; l < Simplex<D>::kEdges; ++l) {
        const Index edge = mesh_.element_edge(k, l);
        if (planned(edge) || on_boundary(edge)) continue;
        const Vec<D> move = displacement_at(mesh_.edge_node(edge));
        if (dot(move, move) > 0) {
          plan(edge, move);
          ++result_.volume_nodes;
        }
      }
  }

  Vec<D> displacement_at(const Vec<D>& x) const {
    double best = std::numeric_limits<double>::infinity();
    Vec<D> displacement{};
    for (Index f : wall_) {
      const auto& vertices = mesh_.facet(f);
      std::array<Vec<D>, D> corners;
      for (int i = 0; i < D; ++i) corners[i] = mesh_.vertex(vertices[i]);
      const auto weights = closest_weights<D>(corners, x);
      Vec<D> foot{};
      for (int i = 0; i < D; ++i) foot = foot + weights[i] * corners[i];
      const double distance = norm(foot - x);
      if (distance >= best) continue;
      best = distance;
      displacement = Vec<D>{};
      for (int i = 0; i < D; ++i)
        for (int j = i + 1; j < D; ++j) displacement = displacement + 4 * weights[i] * weights[j] * wall_move(vertices[i], vertices[j]);
    }
    const double fade = 1 - best / reach_;
    return fade > 0 ? fade * displacement : Vec<D>{};
  }

  Vec<D> wall_move(Index a, Index b) const {
    const Index slot = move_of_edge_.find(static_cast<std::uint64_t>(mesh_.find_edge(a, b)));
    return slot == kNoIndex ? Vec<D>{} : moves_[slot].move;
  }

  bool on_boundary(Index edge) {
    const auto& ends = mesh_.edge_vertices(edge);
    collect_shell(mesh_, ends[0], ends[1], shell_);
    return !shell_is_closed<D>(mesh_, shell_, ends[0], ends[1]);
  }

  bool planned(Index edge) const { return move_of_edge_.find(static_cast<std::uint64_t>(edge)) != kNoIndex; }

  void plan(Index edge, const Vec<D>& move) {
    move_of_edge_.insert(static_cast<std::uint64_t>(edge), static_cast<Index>(moves_.size()));
    moves_.push_back({edge, mesh_.edge_node(edge), move});
  }

  // The elements that hold a moving node, once each.
  std::vector<Index> moved_elements() {
    std::vector<Index> elements, shell;
    for (const auto& m : moves_) {
      if (dot(m.move, m.move) == 0) continue;
      const auto& ends = mesh_.edge_vertices(m.edge);
      collect_shell(mesh_, ends[0], ends[1], shell);
      elements.insert(elements.end(), shell.begin(), shell.end());
    }
    std::sort(elements.begin(), elements.end());
    elements.erase(std::unique(elements.begin(), elements.end()), elements.end());
    return elements;
  }

  LayerBend made() {
    if (certified_at(1)) {
      result_.fraction = 1;
      return result_;
    }
    result_.fraction = largest_fraction_holding(options_.correction_steps, [&](double fraction) { return certified_at(fraction); });
    set(result_.fraction);
    return result_;
  }

  void set(double fraction) {
    for (const auto& m : moves_) mesh_.edge_node(m.edge) = m.start + fraction * m.move;
  }

  bool certified_at(double fraction) {
    set(fraction);
    return guard_->holds(result_.elements_certified);
  }

  Mesh<D>& mesh_;
  const BoundaryProposals<D>& proposals_;
  const LayerBendOptions<D>& options_;
  double reach_ = 0;
  std::vector<Index> wall_, shell_;
  std::optional<ElementGuard<D>> guard_;
  std::vector<NodeMove<D>> moves_;
  IndexHashMap move_of_edge_;
  LayerBend result_;
};

}  // namespace

template <int D>
LayerBend bend_layers(Mesh<D>& mesh, const BoundaryProposals<D>& proposals, Index a, Index b, const LayerBendOptions<D>& options) {
  return Bend<D>(mesh, proposals, options).run(a, b);
}

template LayerBend bend_layers(Mesh<2>&, const BoundaryProposals<2>&, Index, Index, const LayerBendOptions<2>&);
template LayerBend bend_layers(Mesh<3>&, const BoundaryProposals<3>&, Index, Index, const LayerBendOptions<3>&);

}  // namespace hocav
