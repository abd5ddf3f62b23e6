#include "parallel/distributed_graph.hpp"

#include <algorithm>
#include <numeric>
#include <string>
#include <unordered_map>
#include <utility>

#include "base/error.hpp"
#include "parallel/communicator.hpp"
#include "parallel/interface_sides.hpp"

namespace hocav {
namespace {

// One side of an interface face, sent to the process where both sides meet: the face by its global
// vertex ids, the group of the element that has it (its global number), whether that element touches
// the last interfaces, and the process it is on. The meeting process sends each side the other's record.
template <int D>
struct FaceSide {
  std::int64_t group;
  FaceKey<D> face;
  std::int32_t process, near_kept_inside;
};

// A face's vertices, in the element's order.
template <int D>
FaceKey<D> face_vertices_of(const typename Mesh<D>::Element& element, int face) {
  FaceKey<D> vertices{};
  for (int i = 0; i < D; ++i) vertices[i] = element[face_vertices<D>(face)[i]];
  return vertices;
}

// A graph row's arcs with their weights, those to the same neighbour summed, by neighbour.
void merge_arcs(std::vector<std::pair<std::int64_t, std::int64_t>>& arcs, WeightedGraph& rows) {
  std::sort(arcs.begin(), arcs.end());
  for (std::size_t i = 0; i < arcs.size(); ++i) {
    if (i > 0 && arcs[i].first == arcs[i - 1].first) {
      rows.edge_weights.back() += arcs[i].second;
      continue;
    }
    rows.neighbours.push_back(arcs[i].first);
    rows.edge_weights.push_back(arcs[i].second);
  }
  rows.offsets.push_back(static_cast<std::int64_t>(rows.neighbours.size()));
}

// Each group's elements: members[start[g] .. start[g + 1]).
struct GroupMembers {
  std::vector<Index> start, members;
};

GroupMembers members_of(const ElementGroups& groups) {
  GroupMembers out;
  out.start.assign(static_cast<std::size_t>(groups.count) + 1, 0);
  for (Index g : groups.group_of) ++out.start[g + 1];
  std::partial_sum(out.start.begin(), out.start.end(), out.start.begin());
  out.members.resize(groups.group_of.size());
  std::vector<Index> next(out.start.begin(), out.start.end() - 1);
  for (std::size_t k = 0; k < groups.group_of.size(); ++k) out.members[next[groups.group_of[k]]++] = static_cast<Index>(k);
  return out;
}

}  // namespace

template <int D>
DistributedGraph distributed_element_graph(const MeshPart<D>& part, std::span<const double> loads, std::span<const char> kept_inside,
                                           const ElementGroups& groups) {
  const Mesh<D>& mesh = part.mesh;
  if (loads.size() != static_cast<std::size_t>(mesh.element_count()) || groups.group_of.size() != loads.size())
    throw Error("distributed graph: one load and one group per element");
  if (mesh.element_count() > 0 && !mesh.has_topology()) throw Error("distributed graph: the part needs its topology");
  DistributedGraph graph;
  const std::vector<Index> counts = all_gather_value(groups.count);
  for (int r = 0; r < process_rank(); ++r) graph.first += counts[r];
  double total = 0;
  for (double sum : all_gather_value(std::accumulate(loads.begin(), loads.end(), 0.0))) total += sum;
  std::vector<double> group_loads(static_cast<std::size_t>(groups.count), 0.0);
  for (Index k = 0; k < mesh.element_count(); ++k) group_loads[groups.group_of[k]] += loads[k];
  graph.rows.vertex_weights = integer_loads(group_loads, total);
  std::vector<char> near(static_cast<std::size_t>(mesh.element_count()));
  for (Index k = 0; k < mesh.element_count(); ++k) near[k] = touches<D>(mesh.element(k), kept_inside);

  // This side of each interface facet, by its element face.
  std::vector<char> interface_face(static_cast<std::size_t>(mesh.element_count()) * (D + 1), 0);
  std::vector<FaceSide<D>> own;
  for (Index f = 0; f < mesh.facet_count(); ++f) {
    if (mesh.facet_ref(f) != kInterfaceRef) continue;
    const Index at = mesh.facet_element_face(f), k = at / (D + 1);
    interface_face[at] = 1;
    own.push_back({graph.first + groups.group_of[k], global_key<D>(part, mesh.facet(f)), process_rank(), near[k]});
  }
  const auto across = sides_across<D>(own);

  const GroupMembers members = members_of(groups);
  std::vector<std::pair<std::int64_t, std::int64_t>> arcs;  // a group's: neighbour, weight
  graph.rows.offsets.push_back(0);
  for (Index g = 0; g < groups.count; ++g) {
    arcs.clear();
    for (Index i = members.start[g]; i < members.start[g + 1]; ++i) {
      const Index k = members.members[i];
      for (int face = 0; face <= D; ++face) {
        if (const Index other = mesh.neighbor(k, face); other != kNoIndex) {
          if (groups.group_of[other] != g)
            arcs.emplace_back(graph.first + groups.group_of[other], near[k] && near[other] ? kKeptInsideFaceWeight : 1);
        } else if (interface_face[static_cast<std::size_t>(k) * (D + 1) + face]) {
          const FaceSide<D>& side = across.at(global_key<D>(part, face_vertices_of<D>(mesh.element(k), face)));
          arcs.emplace_back(side.group, near[k] && side.near_kept_inside ? kKeptInsideFaceWeight : 1);
        }
      }
    }
    merge_arcs(arcs, graph.rows);
  }
  return graph;
}

template <int D>
std::vector<int> partition_distributed_part(const MeshPart<D>& part, std::span<const double> loads, std::span<const char> kept_inside,
                                            std::int64_t seed) {
  const ElementGroups groups = neighbouring_element_groups(part.mesh);
  const std::vector<int> group_parts = partition_distributed_graph(distributed_element_graph(part, loads, kept_inside, groups),
                                                                   process_count(), seed);
  std::vector<int> parts(groups.group_of.size());
  for (std::size_t k = 0; k < parts.size(); ++k) parts[k] = group_parts[static_cast<std::size_t>(groups.group_of[k])];
  return parts;
}

template DistributedGraph distributed_element_graph(const MeshPart<2>&, std::span<const double>, std::span<const char>,
                                                    const ElementGroups&);
template DistributedGraph distributed_element_graph(const MeshPart<3>&, std::span<const double>, std::span<const char>,
                                                    const ElementGroups&);
template std::vector<int> partition_distributed_part(const MeshPart<2>&, std::span<const double>, std::span<const char>, std::int64_t);
template std::vector<int> partition_distributed_part(const MeshPart<3>&, std::span<const double>, std::span<const char>, std::int64_t);

}  // namespace hocav
