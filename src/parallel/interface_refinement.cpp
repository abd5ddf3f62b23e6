#include "parallel/interface_refinement.hpp"

#include <algorithm>
#include <array>
#include <map>
#include <numbers>
#include <unordered_map>
#include <unordered_set>

#include "adapt/boundary_pieces.hpp"
#include "adapt/metric_measures.hpp"
#include "base/error.hpp"
#include "cavity/cavity_operator.hpp"
#include "mesh/ball_and_shell.hpp"
#include "mesh/mesh_defects.hpp"
#include "parallel/communicator.hpp"
#include "parallel/entity_tags.hpp"
#include "parallel/interface_sides.hpp"

namespace hocav {
namespace {

// The loop's split length: the interface edges it would split, were they not frozen. Once only: a
// lattice's interface is then cut as the serial loop cuts the whole (in eight), and an interface far
// coarser than the metric stays as coarse as before, the parts' splits kept away from it
// (SplitsAtRequiredVertices::kNextToFineRequiredFacets; docs/distributed.md §Interfaces refined first).
constexpr double kSplitLength = std::numbers::sqrt2;
constexpr int kMostTurnRounds = 4;

using EdgeKey = FaceKey<2>;

// One side's view of an interface edge, sent to where the edge's sides meet.
struct EdgeSide {
  EdgeKey edge;
  int process;
  int splittable;
  double length;
};

// The meeting's answer: the global id of the edge's new vertex.
struct EdgeSplit {
  EdgeKey edge;
  Index vertex;
};

// One side's verdict on turning an interface face.
struct TurnSide {
  FaceKey<3> face;
  int process;
  int turnable;
};

template <int D>
EdgeKey global_edge(const MeshPart<D>& part, Index a, Index b) {
  return sorted_key<2>({part.global_ids[a], part.global_ids[b]});
}

// The facets on the faces of these elements through both a and b (local face i is opposite vertex i).
template <int D>
std::vector<Index> facets_through(const Mesh<D>& mesh, std::span<const Index> elements, Index a, Index b) {
  std::vector<Index> facets;
  for (Index k : elements)
    for (int i = 0; i <= D; ++i) {
      const Index opposite = mesh.element(k)[i];
      if (opposite == a || opposite == b) continue;
      if (const Index f = mesh.element_face_facet(k, i); f != kNoIndex) facets.push_back(f);
    }
  return facets;
}

// Plans the star of `shell`, the elements around edge (a, b), from `vertex`, the facets through the
// edge re-starred with it (and `line`, on the edge, when not kNoIndex): a split from its middle, a
// face's turn from another middle.
template <int D>
bool star_planned(const Mesh<D>& mesh, std::span<const Index> shell, Index a, Index b, Index vertex, CavityOperator<D>& op,
                  double min_relative_measure = CavityOptions{}.min_relative_measure, Index line = kNoIndex) {
  const std::vector<Index> facets = facets_through(mesh, shell, a, b);
  CavityOptions options;
  options.removed_facets = facets;
  const Index lines[1] = {line};
  if (line != kNoIndex) options.removed_lines = lines;
  options.min_relative_measure = min_relative_measure;
  return op.plan(mesh, shell, vertex, options) == CavityStatus::kAccepted;
}

// The edges (local ids, a < b) of the part's interface facets.
template <int D>
std::vector<std::array<Index, 2>> interface_edges(const Mesh<D>& mesh) {
  std::unordered_set<std::uint64_t> seen;
  std::vector<std::array<Index, 2>> edges;
  for (Index f = 0; f < mesh.facet_count(); ++f) {
    if (mesh.facet_removed(f) || mesh.facet_ref(f) != kInterfaceRef) continue;
    const auto& facet = mesh.facet(f);
    for (int i = 0; i < D; ++i)
      for (int j = 0; j < i; ++j)
        if (seen.insert(Mesh<D>::edge_key(facet[i], facet[j])).second)
          edges.push_back({std::min(facet[i], facet[j]), std::max(facet[i], facet[j])});
  }
  return edges;
}

// The part's edges that are no interface's alone: those of its feature lines, those of its other
// facets (the domain's boundary, or a facet between materials) with the ref of such a facet, and
// those of its faces that hold two facets (an interface face with a facet of the mesh's own on it,
// of which the elements' faces link one).
struct BoundaryEdges {
  std::unordered_set<std::uint64_t> on_lines, on_doubled_faces;
  std::unordered_map<std::uint64_t, int> on_facets;
};

template <int D>
BoundaryEdges boundary_edges(const Mesh<D>& mesh) {
  BoundaryEdges edges;
  std::map<typename Mesh<D>::Facet, Index> faces;
  for (Index f = 0; f < mesh.facet_count(); ++f) {
    if (mesh.facet_removed(f)) continue;
    auto facet = mesh.facet(f);
    std::sort(facet.begin(), facet.end());
    const bool doubled = ++faces[facet] > 1;
    for (int i = 0; i < D; ++i)
      for (int j = 0; j < i; ++j) {
        const std::uint64_t key = Mesh<D>::edge_key(facet[i], facet[j]);
        if (doubled) edges.on_doubled_faces.insert(key);
        if (mesh.facet_ref(f) != kInterfaceRef) edges.on_facets.emplace(key, mesh.facet_ref(f));
      }
  }
  if constexpr (D == 3)
    for (Index l = 0; l < mesh.line_count(); ++l)
      if (!mesh.line_removed(l)) edges.on_lines.insert(Mesh<D>::edge_key(mesh.line(l)[0], mesh.line(l)[1]));
  return edges;
}

// Whether the domain's boundary lets interface edge (a, b), its shell `shell`, be split at its
// middle: the edge is off it, or it is where the interface meets a side (the shell's two facets
// through the edge one of the interface and one of the side) and the side's geometry puts the
// middle where it is (a flat side: both sides of the interface then hold the new vertex on the
// geometry). A feature line's edge, and a curved side's, are kept: their middles would need the
// geometry on both sides.
template <int D>
bool boundary_lets_split(const Mesh<D>& mesh, const BoundaryEdges& edges, const BoundaryGeometry<D>* geometry, std::span<const Index> shell,
                         Index a, Index b) {
  const std::uint64_t key = Mesh<D>::edge_key(a, b);
  if (edges.on_lines.contains(key) || edges.on_doubled_faces.contains(key)) return false;
  const auto side = edges.on_facets.find(key);
  if (side == edges.on_facets.end()) return true;
  if (!geometry) return false;
  const std::vector<Index> facets = facets_through(mesh, shell, a, b);
  if (facets.size() != 2) return false;
  const std::array<int, 2> refs{mesh.facet_ref(facets[0]), mesh.facet_ref(facets[1])};
  if (std::minmax(refs[0], refs[1]) != std::minmax(kInterfaceRef, side->second)) return false;
  const Vec<D> middle = 0.5 * (mesh.vertex(a) + mesh.vertex(b));
  return at_straight_middle<D>(geometry->project(middle, {side->second}).point, mesh.vertex(a), mesh.vertex(b));
}

// Per edge, how many of the mesh's elements hold it (a shell walk finds only the fan it starts in).
template <int D>
std::unordered_map<std::uint64_t, Index> holder_counts(const Mesh<D>& mesh, std::span<const std::array<Index, 2>> edges) {
  std::unordered_map<std::uint64_t, Index> counts;
  for (const auto& [a, b] : edges) counts.emplace(Mesh<D>::edge_key(a, b), 0);
  for (const auto& element : mesh.elements())
    for (int i = 0; i <= D; ++i)
      for (int j = 0; j < i; ++j)
        if (auto it = counts.find(Mesh<D>::edge_key(element[i], element[j])); it != counts.end()) ++it->second;
  return counts;
}

// Per vertex, whether the walks around it (collect_ball, collect_shell) reach every element that
// holds it: not so at the mesh's non-manifold places, such as a vertex a part holds in separate fans.
template <int D>
std::vector<char> whole_balls(const Mesh<D>& mesh) {
  std::vector<char> whole(static_cast<std::size_t>(mesh.vertex_count()), 1);
  for (Index v : non_manifold_places(mesh).every_vertex()) whole[v] = 0;
  return whole;
}

// Whether the elements holding edge (a, b) are its one fan `shell`, all of one ref.
template <int D>
bool one_fan_of_one_ref(const Mesh<D>& mesh, std::span<const Index> shell, Index holders) {
  if (static_cast<Index>(shell.size()) != holders) return false;
  return std::all_of(shell.begin(), shell.end(), [&](Index k) { return mesh.element_ref(k) == mesh.element_ref(shell.front()); });
}

// Where an interface meets a side of the domain along edge (a, b) (its facets there of two refs), a
// line on the edge for the time of its split: the operator re-stars each ref's facets within that
// ref, and where two refs meet it needs the line between them. kNoIndex elsewhere.
template <int D>
Index junction_line(Mesh<D>& mesh, std::span<const Index> shell, Index a, Index b) {
  if constexpr (D == 3) {
    const std::vector<Index> facets = facets_through(mesh, shell, a, b);
    for (Index f : facets)
      if (mesh.facet_ref(f) != mesh.facet_ref(facets.front())) return mesh.add_line({a, b});
  }
  return kNoIndex;
}

// Removes the lines at vertex m: a junction line's halves after its split (the part had no line there).
template <int D>
void remove_lines_at(Mesh<D>& mesh, Index m) {
  if constexpr (D == 3)
    for (Index l = 0; l < mesh.line_count(); ++l)
      if (!mesh.line_removed(l) && (mesh.line(l)[0] == m || mesh.line(l)[1] == m)) mesh.remove_line(l);
}

// Whether the split of edge (a, b) at its middle, its shell `shell`, would be accepted (a bisection
// is valid, but may be too flat for the operator's measure floor).
template <int D>
bool split_accepted(Mesh<D>& mesh, Index a, Index b, std::span<const Index> shell, CavityOperator<D>& op) {
  const Index line = junction_line(mesh, shell, a, b);
  const Index m = mesh.add_vertex(0.5 * (mesh.vertex(a) + mesh.vertex(b)));
  const bool accepted = star_planned(mesh, shell, a, b, m, op, CavityOptions{}.min_relative_measure, line);
  mesh.pop_vertex();
  if (line != kNoIndex) mesh.remove_line(line);
  return accepted;
}

// This process's view of each interface edge: whether it may split it, and its length.
template <int D>
std::vector<EdgeSide> edge_sides(MeshPart<D>& part, const AdaptationMetric<D>& metric, const BoundaryGeometry<D>* geometry,
                                 std::span<const std::array<Index, 2>> edges, CavityOperator<D>& op) {
  Mesh<D>& mesh = part.mesh;
  const BoundaryEdges on_boundary = boundary_edges(mesh);
  const std::unordered_map<std::uint64_t, Index> holders = holder_counts(mesh, edges);
  const std::vector<char> whole = whole_balls(mesh);
  std::unordered_map<Index, SymMat<D>> metrics;
  Index hint = kNoIndex;
  const auto metric_of = [&](Index v) -> const SymMat<D>& {
    const auto [it, fresh] = metrics.try_emplace(v);
    if (fresh) it->second = metric.metric_at(mesh.vertex(v), hint);
    return it->second;
  };
  std::vector<EdgeSide> sides;
  std::vector<Index> shell;
  for (const auto& [a, b] : edges) {
    collect_shell(mesh, a, b, shell);
    const std::uint64_t key = Mesh<D>::edge_key(a, b);
    const bool splittable = whole[a] && whole[b] && boundary_lets_split(mesh, on_boundary, geometry, std::span<const Index>(shell), a, b) &&
                            one_fan_of_one_ref(mesh, shell, holders.at(key)) && split_accepted(mesh, a, b, shell, op);
    const double length = metric_edge_length<D>(mesh.vertex(a), mesh.vertex(b), metric_of(a), metric_of(b));
    sides.push_back({global_edge(part, a, b), process_rank(), splittable ? 1 : 0, length});
  }
  return sides;
}

// Every process at once: the edges its sides split, each with its new vertex's global id. Where the
// sides of an edge meet, it is split when every side may and the longest view is above `bound`; the
// ids are numbered from next_global_id by meeting process, each's edges in the order of their keys.
std::map<EdgeKey, Index> agreed_splits(const std::vector<EdgeSide>& own, double bound, Index& next_global_id) {
  std::vector<std::vector<EdgeSide>> outgoing(static_cast<std::size_t>(process_count()));
  for (const EdgeSide& side : own) outgoing[static_cast<std::size_t>(meeting_process<2>(side.edge, process_count()))].push_back(side);
  std::map<EdgeKey, std::vector<EdgeSide>> met;
  for (const EdgeSide& side : exchange_values_joined(outgoing)) met[side.edge].push_back(side);
  std::vector<const std::vector<EdgeSide>*> split;
  for (const auto& [edge, sides] : met) {
    double longest = 0;
    bool splittable = true;
    for (const EdgeSide& side : sides) {
      longest = std::max(longest, side.length);
      splittable = splittable && side.splittable != 0;
    }
    if (splittable && longest > bound) split.push_back(&sides);
  }
  const CountOffset offset = offset_over_processes(static_cast<Index>(split.size()));
  std::vector<std::vector<EdgeSplit>> answers(outgoing.size());
  Index id = next_global_id + offset.before;
  for (const std::vector<EdgeSide>* sides : split) {
    for (const EdgeSide& side : *sides) answers[static_cast<std::size_t>(side.process)].push_back({side.edge, id});
    ++id;
  }
  next_global_id += offset.total;
  std::map<EdgeKey, Index> splits;
  for (const EdgeSplit& answer : exchange_values_joined(answers)) splits.emplace(answer.edge, answer.vertex);
  return splits;
}

// Splits edge (a, b) of the part at its middle, a new interface vertex of global id `global_id`.
template <int D>
Index split_interface_edge(MeshPart<D>& part, Index a, Index b, Index global_id, CavityOperator<D>& op, std::vector<Index>& shell) {
  Mesh<D>& mesh = part.mesh;
  collect_shell(mesh, a, b, shell);
  const Index line = junction_line(mesh, std::span<const Index>(shell), a, b);
  const Index m = mesh.add_vertex(0.5 * (mesh.vertex(a) + mesh.vertex(b)));
  // (Every side agreed on the split when its plan passed the measure floor; bisections since may
  // have thinned the shell, and halves of a positive element are positive.)
  if (!star_planned(mesh, std::span<const Index>(shell), a, b, m, op, 0, line))
    throw Error("distributed adaptation: the agreed split of an interface edge was refused");
  op.commit(mesh);
  if (line != kNoIndex) remove_lines_at(mesh, m);
  mesh.required_vertices().push_back(m);
  part.global_ids.push_back(global_id);
  if (!part.pinned.empty()) part.pinned.push_back(0);
  return m;
}

// An interface face whose three edges were split: its corners, and per corner the middle of the
// edge opposite it.
struct SplitFace {
  FaceKey<3> key;
  std::array<Index, 3> corners, middles;
};

// A face's turn on this side: its median (a middle and the corner opposite it), the vertex its
// two triangles are re-starred from, and whether the star is valid here.
struct Turn {
  Index middle = kNoIndex, corner = kNoIndex, apex = kNoIndex;
  std::vector<Index> shell;
};

// The median of `face` on this side: the bisections left one, from the first split's middle to the
// corner opposite it; its shell in `turn`.
Turn median_of(const Mesh<3>& mesh, const SplitFace& face) {
  Turn turn;
  for (int i = 0; i < 3 && turn.shell.empty(); ++i) {
    collect_shell(mesh, face.middles[i], face.corners[i], turn.shell);
    if (!turn.shell.empty()) std::tie(turn.middle, turn.corner) = std::pair(face.middles[i], face.corners[i]);
  }
  return turn;
}

// Where this side can turn the median: its elements one fan on two interface facets, and the star
// of their triangles from another middle valid (it gives the face's corner triangles and its
// middle one); `turn.apex` is that middle, kNoIndex where it cannot.
void plan_turn(const Mesh<3>& mesh, const MeshPart<3>& part, const SplitFace& face, Index holders, Turn& turn, CavityOperator<3>& op) {
  if (turn.shell.empty()) return;
  if (!one_fan_of_one_ref(mesh, turn.shell, holders) || facets_through(mesh, turn.shell, turn.middle, turn.corner).size() != 2) return;
  std::vector<Index> apexes;
  for (Index m : face.middles)
    if (m != turn.middle) apexes.push_back(m);
  std::sort(apexes.begin(), apexes.end(), [&](Index x, Index y) { return part.global_ids[x] < part.global_ids[y]; });
  for (Index apex : apexes)
    if (star_planned(mesh, std::span<const Index>(turn.shell), turn.middle, turn.corner, apex, op)) {
      turn.apex = apex;
      return;
    }
}

// This side's turns of `faces`, planned.
std::vector<Turn> planned_turns(const MeshPart<3>& part, std::span<const SplitFace> faces, CavityOperator<3>& op) {
  std::vector<Turn> turns;
  std::vector<std::array<Index, 2>> medians;
  for (const SplitFace& face : faces) {
    turns.push_back(median_of(part.mesh, face));
    if (!turns.back().shell.empty())
      medians.push_back({std::min(turns.back().middle, turns.back().corner), std::max(turns.back().middle, turns.back().corner)});
  }
  const std::unordered_map<std::uint64_t, Index> holders = holder_counts(part.mesh, medians);
  const std::vector<char> whole = whole_balls(part.mesh);
  for (std::size_t t = 0; t < turns.size(); ++t)
    if (!turns[t].shell.empty() && whole[turns[t].middle] && whole[turns[t].corner])
      plan_turn(part.mesh, part, faces[t], holders.at(Mesh<3>::edge_key(turns[t].middle, turns[t].corner)), turns[t], op);
  return turns;
}

// Drops the turns that another's commit would change: shells that share an element, or a shell
// with both ends of another's median (its star would make an element on that median). The others
// commit in any order, each on the shell it planned.
void drop_interfering(const Mesh<3>& mesh, std::vector<Turn>& turns) {
  std::unordered_map<Index, std::size_t> owner;
  std::unordered_map<std::uint64_t, std::size_t> median;
  for (std::size_t t = 0; t < turns.size(); ++t)
    if (turns[t].apex != kNoIndex) median.emplace(Mesh<3>::edge_key(turns[t].middle, turns[t].corner), t);
  std::vector<char> interfering(turns.size(), 0);
  const auto interfere = [&](std::size_t t, std::size_t u) {
    if (t != u) interfering[t] = interfering[u] = 1;
  };
  for (std::size_t t = 0; t < turns.size(); ++t) {
    if (turns[t].apex == kNoIndex) continue;
    std::vector<Index> vertices;
    for (Index k : turns[t].shell) {
      if (const auto [it, fresh] = owner.emplace(k, t); !fresh) interfere(t, it->second);
      vertices.insert(vertices.end(), mesh.element(k).begin(), mesh.element(k).end());
    }
    std::sort(vertices.begin(), vertices.end());
    vertices.erase(std::unique(vertices.begin(), vertices.end()), vertices.end());
    for (std::size_t i = 0; i < vertices.size(); ++i)
      for (std::size_t j = 0; j < i; ++j)
        if (const auto it = median.find(Mesh<3>::edge_key(vertices[i], vertices[j])); it != median.end()) interfere(t, it->second);
  }
  for (std::size_t t = 0; t < turns.size(); ++t)
    if (interfering[t]) turns[t].apex = kNoIndex;
}

// Every process at once: turns the split faces both sides can turn, in rounds while some turn; returns
// how many this process turned.
Index turn_split_faces(MeshPart<3>& part, std::vector<SplitFace> faces, CavityOperator<3>& op) {
  Mesh<3>& mesh = part.mesh;
  Index turned = 0;
  for (int round = 0; round < kMostTurnRounds && sum_over_processes(static_cast<Index>(faces.size())) > 0; ++round) {
    std::vector<Turn> turns = planned_turns(part, faces, op);
    drop_interfering(mesh, turns);
    std::vector<TurnSide> own;
    for (std::size_t t = 0; t < faces.size(); ++t) own.push_back({faces[t].key, process_rank(), turns[t].apex != kNoIndex ? 1 : 0});
    const auto across = sides_across<3, TurnSide>(own);
    std::vector<SplitFace> left;
    Index turned_now = 0;
    for (std::size_t t = 0; t < faces.size(); ++t) {
      if (turns[t].apex == kNoIndex || across.at(faces[t].key).turnable == 0) {
        left.push_back(faces[t]);
        continue;
      }
      collect_shell(mesh, turns[t].middle, turns[t].corner, turns[t].shell);
      if (!star_planned(mesh, std::span<const Index>(turns[t].shell), turns[t].middle, turns[t].corner, turns[t].apex, op))
        throw Error("distributed adaptation: an agreed turn of an interface face was refused");
      op.commit(mesh);
      ++turned_now;
    }
    turned += turned_now;
    faces = std::move(left);
    if (sum_over_processes(turned_now) == 0) break;
  }
  return turned;
}

// The interface faces (3D) whose three edges are in `splits`, by their corners' local ids.
template <int D>
std::vector<SplitFace> faces_of_splits(const MeshPart<D>& part, const std::map<EdgeKey, Index>& splits) {
  std::vector<SplitFace> faces;
  if constexpr (D == 3) {
    const Mesh<D>& mesh = part.mesh;
    for (Index f = 0; f < mesh.facet_count(); ++f) {
      if (mesh.facet_removed(f) || mesh.facet_ref(f) != kInterfaceRef) continue;
      const auto& c = mesh.facet(f);
      SplitFace face{global_key<3>(part, {c[0], c[1], c[2]}), {c[0], c[1], c[2]}, {}};
      bool all = true;
      for (int i = 0; i < 3; ++i) all = all && splits.contains(global_edge(part, c[(i + 1) % 3], c[(i + 2) % 3]));
      if (all) faces.push_back(face);
    }
  }
  return faces;
}

// Every interface facet required, and only those of the mesh that were.
template <int D>
void require_interface_facets(Mesh<D>& mesh) {
  std::vector<Index>& required = required_facets(mesh);
  std::erase_if(required, [&](Index f) { return mesh.facet_ref(f) == kInterfaceRef; });
  for (Index f = 0; f < mesh.facet_count(); ++f)
    if (mesh.facet_ref(f) == kInterfaceRef) required.push_back(f);
  std::sort(required.begin(), required.end());
}

}  // namespace

// The agreed splits are made in the order of their keys, the same on every side, so that an
// interface face is cut alike on both; then the 3D faces are turned.
template <int D>
InterfaceRefinement refine_interfaces(MeshPart<D>& part, const AdaptationMetric<D>& metric, const BoundaryGeometry<D>* geometry,
                                      Index& next_global_id) {
  InterfaceRefinement out;
  if (!part.mesh.has_topology() && part.mesh.element_count() > 0) part.mesh.build_topology();
  const std::vector<std::array<Index, 2>> edges = interface_edges(part.mesh);
  CavityOperator<D> op;
  const Index first_id = next_global_id;
  const std::map<EdgeKey, Index> splits = agreed_splits(edge_sides(part, metric, geometry, edges, op), kSplitLength, next_global_id);
  out.edges_split = next_global_id - first_id;
  std::vector<SplitFace> faces = faces_of_splits(part, splits);
  const std::unordered_map<Index, Index> local = local_ids_of(part);
  std::vector<Index> shell;
  std::unordered_map<std::uint64_t, Index> middles;
  for (const auto& [edge, global_id] : splits) {
    const Index a = local.at(edge[0]), b = local.at(edge[1]);
    middles.emplace(Mesh<D>::edge_key(a, b), split_interface_edge(part, a, b, global_id, op, shell));
  }
  if constexpr (D == 3) {
    for (SplitFace& face : faces)
      for (int i = 0; i < 3; ++i) face.middles[i] = middles.at(Mesh<D>::edge_key(face.corners[(i + 1) % 3], face.corners[(i + 2) % 3]));
    out.faces_turned = sum_over_processes(turn_split_faces(part, std::move(faces), op)) / 2;
  }
  part.mesh.compact();
  require_interface_facets(part.mesh);
  return out;
}

template InterfaceRefinement refine_interfaces(MeshPart<2>&, const AdaptationMetric<2>&, const BoundaryGeometry<2>*, Index&);
template InterfaceRefinement refine_interfaces(MeshPart<3>&, const AdaptationMetric<3>&, const BoundaryGeometry<3>*, Index&);

}  // namespace hocav
