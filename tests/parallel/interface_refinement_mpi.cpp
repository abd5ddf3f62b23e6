// The interfaces refined before the parts' loops (docs/distributed.md §Interfaces refined first),
// run by ctest under `mpirun -np N` (N = 2, 3, 4). Every process makes the same Kuhn cube and square
// and keeps its slab of x (on 2 and 3 processes the slabs meet on lattice planes; on 4 the cut is
// jagged), then refines the interfaces in a metric finer than every edge, without a geometry and
// with the P3 surrogate of the cube (whose sides are flat):
// - the parts still meet face to face (each interface face has exactly two sides), a vertex has
//   one point wherever it is held, no global id is given twice, every element is positive and the
//   parts fill the domain, and no line is left where an interface meets a side;
// - every interface edge off the domain's boundary is split once (with the geometry, every
//   interface edge: those on the cube's flat sides too), and on a lattice plane every face with
//   three such edges is turned into the four triangles of a uniform refinement (a quarter of its
//   facets then has three new vertices; with the bisections alone none would);
// - in 2D every interface edge off the boundary is split in two;
// - where the slabs meet on a facet between two materials (x = 0.5, on 2 and 4 processes), its
//   edges are kept (a split would leave one of a face's two facets on no element's face: the
//   refinement then throws), and the material facets stay whole.
// Exit code 0 when all holds on every process, 1 otherwise (with a message).
#include <algorithm>
#include <cmath>
#include <iostream>
#include <string>
#include <unordered_map>
#include <unordered_set>

#include "cases/structured.hpp"
#include "mesh/measure.hpp"
#include "mpi_test_main.hpp"
#include "parallel/communicator.hpp"
#include "parallel/interface_refinement.hpp"
#include "parallel/interface_sides.hpp"
#include "parallel/mesh_parts.hpp"
#include "surface/p3_surrogate.hpp"

namespace hocav {
namespace {

bool fail(const std::string& what) {
  std::cerr << "interface refinement (rank " << process_rank() << "): " << what << '\n';
  return false;
}

int slab(double x) { return std::clamp(static_cast<int>(std::floor(x * process_count())), 0, process_count() - 1); }

// This process's slab of x of the mesh, as a part.
template <int D>
MeshPart<D> own_slab(Mesh<D> mesh) {
  mesh.build_topology();
  std::vector<int> part_of;
  for (const auto& element : mesh.elements()) {
    double x = 0;
    for (Index v : element) x += mesh.vertex(v)[0] / (D + 1);
    part_of.push_back(slab(x));
  }
  return std::move(split_mesh(mesh, part_of, process_count()).at(static_cast<std::size_t>(process_rank())));
}

template <int D>
std::vector<std::array<Index, D>> interface_facets(const MeshPart<D>& part) {
  std::vector<std::array<Index, D>> facets;
  for (Index f = 0; f < part.mesh.facet_count(); ++f)
    if (!part.mesh.facet_removed(f) && part.mesh.facet_ref(f) == kInterfaceRef) facets.push_back(part.mesh.facet(f));
  return facets;
}

// The edges the refinement keeps: without a geometry those of the part's facets on the domain's
// boundary, with one (the cube's sides are flat) those of its feature lines.
template <int D>
std::unordered_set<std::uint64_t> kept_edges(const MeshPart<D>& part, bool with_geometry) {
  std::unordered_set<std::uint64_t> edges;
  if (with_geometry) {
    if constexpr (D == 3)
      for (Index l = 0; l < part.mesh.line_count(); ++l) edges.insert(Mesh<D>::edge_key(part.mesh.line(l)[0], part.mesh.line(l)[1]));
    return edges;
  }
  for (Index f = 0; f < part.mesh.facet_count(); ++f)
    if (part.mesh.facet_ref(f) != kInterfaceRef) {
      const auto& facet = part.mesh.facet(f);
      for (int i = 0; i < D; ++i)
        for (int j = 0; j < i; ++j) edges.insert(Mesh<D>::edge_key(facet[i], facet[j]));
    }
  return edges;
}

// What the refinement should make of the part's interface: its edges but the kept ones (each split
// once), the facets they cut the interface facets into, and the faces whose three edges are split
// (each turned, on a lattice plane).
struct Expected {
  Index edges = 0, facets = 0, faces = 0;
};

template <int D>
Expected expected_refinement(const MeshPart<D>& part, bool with_geometry) {
  const std::unordered_set<std::uint64_t> kept = kept_edges(part, with_geometry);
  std::unordered_set<std::uint64_t> edges;
  Expected expected;
  for (const auto& facet : interface_facets(part)) {
    Index split = 0;
    for (int i = 0; i < D; ++i)
      for (int j = 0; j < i; ++j) {
        const std::uint64_t key = Mesh<D>::edge_key(facet[i], facet[j]);
        if (kept.contains(key)) continue;
        ++split;
        edges.insert(key);
      }
    expected.facets += 1 + split;
    expected.faces += split == 3;
  }
  expected.edges = static_cast<Index>(edges.size());
  return expected;
}

template <int D>
struct FaceSide {
  FaceKey<D> face;
  int process;
};

// Every interface face has exactly two sides (sides_across throws otherwise).
template <int D>
bool faces_conform(const MeshPart<D>& part) {
  std::vector<FaceSide<D>> own;
  for (const auto& facet : interface_facets(part)) own.push_back({global_key<D>(part, facet), process_rank()});
  try {
    sides_across<D, FaceSide<D>>(own);
  } catch (const Error& error) {
    return fail(error.what());
  }
  return true;
}

struct HeldPoint {
  Index id;
  double x[3];
};

// Each vertex's point is the same on every process that holds it, and no part gives an id twice.
template <int D>
bool points_agree(const MeshPart<D>& part) {
  std::unordered_set<Index> ids(part.global_ids.begin(), part.global_ids.end());
  if (ids.size() != part.global_ids.size()) return fail("a global id given to two vertices of a part");
  std::vector<std::vector<HeldPoint>> outgoing(static_cast<std::size_t>(process_count()));
  for (Index v = 0; v < part.mesh.vertex_count(); ++v) {
    HeldPoint held{part.global_ids[v], {0, 0, 0}};
    for (int k = 0; k < D; ++k) held.x[k] = part.mesh.vertex(v)[k];
    outgoing[static_cast<std::size_t>(held.id % process_count())].push_back(held);
  }
  std::unordered_map<Index, HeldPoint> first;
  for (const HeldPoint& held : exchange_values_joined(outgoing)) {
    const auto [it, fresh] = first.emplace(held.id, held);
    if (!fresh && !std::equal(held.x, held.x + 3, it->second.x)) return fail("vertex " + std::to_string(held.id) + " at two points");
  }
  return true;
}

template <int D>
bool positive_and_filling(const MeshPart<D>& part) {
  double volume = 0;
  for (Index k = 0; k < part.mesh.element_count(); ++k) {
    const double measure = element_measure(part.mesh, k);
    if (!(measure > 0)) return fail("element " + std::to_string(k) + " of measure " + std::to_string(measure));
    volume += measure;
  }
  const double total = sum_over_processes(volume);
  return std::abs(total - 1) <= 1e-12 || fail("the parts' measure is " + std::to_string(total));
}

// The facets with every vertex new (numbered from `first_new`).
template <int D>
Index all_new_facets(const MeshPart<D>& part, Index first_new) {
  Index count = 0;
  for (const auto& facet : interface_facets(part))
    count += std::all_of(facet.begin(), facet.end(), [&](Index v) { return part.global_ids[v] >= first_new; });
  return count;
}

template <int D>
Index line_count(const Mesh<D>& mesh) {
  Index count = 0;
  if constexpr (D == 3)
    for (Index l = 0; l < mesh.line_count(); ++l) count += !mesh.line_removed(l);
  return count;
}

// The first global id no process's part uses: the refinement numbers its new vertices from it.
template <int D>
Index first_new_id(const MeshPart<D>& part) {
  Index own_next = 0;
  for (Index id : part.global_ids) own_next = std::max(own_next, id + 1);
  return max_over_processes(own_next);
}

// A uniform metric in which every edge of the 6-cell lattice is longer than √2.
template <int D>
AdaptationMetric<D> finer_than_the_lattice() {
  AnalyticMetricSpec uniform;
  uniform.h = 0.02;
  return AdaptationMetric<D>(uniform, SizeBounds{});
}

template <int D>
bool check(Mesh<D> mesh, bool with_geometry) {
  const std::string name = std::string(D == 3 ? "cube" : "square") + (with_geometry ? " with its geometry" : "");
  const P3Surrogate<D> surrogate(mesh);
  MeshPart<D> part = own_slab(std::move(mesh));
  const Index lines_before = line_count(part.mesh);
  const Index first_new = first_new_id(part);
  const Expected own = expected_refinement(part, with_geometry);  // each edge and face once per side
  const Expected expected{sum_over_processes(own.edges), sum_over_processes(own.facets), sum_over_processes(own.faces)};
  Index next_id = first_new;
  const InterfaceRefinement refined = refine_interfaces(part, finer_than_the_lattice<D>(), with_geometry ? &surrogate : nullptr, next_id);
  const std::vector<Index> next_ids = all_gather_value(next_id);
  bool ok = std::all_of(next_ids.begin(), next_ids.end(), [&](Index each) { return each == next_id; }) ||
            fail(name + ": the processes' next global ids differ");
  ok = faces_conform(part) && points_agree(part) && positive_and_filling(part) && ok;
  if (line_count(part.mesh) != lines_before) ok = fail(name + ": the refinement left lines");
  if (next_id - first_new != refined.edges_split)
    ok = fail(name + ": " + std::to_string(refined.edges_split) + " edges split, ids for " + std::to_string(next_id - first_new));
  // On 2 processes every interface edge lies between exactly two parts; more may share one.
  if (process_count() == 2 && 2 * refined.edges_split != expected.edges)
    ok = fail(name + ": " + std::to_string(refined.edges_split) + " interface edges split of " + std::to_string(expected.edges / 2));
  const Index facets_after = sum_over_processes(static_cast<Index>(interface_facets(part).size()));
  if (process_count() <= 3 && facets_after != expected.facets)
    ok = fail(name + ": " + std::to_string(facets_after) + " interface facets after, " + std::to_string(expected.facets) + " expected");
  if (D == 3 && process_count() <= 3) {
    const Index middles = sum_over_processes(all_new_facets(part, first_new));
    if (refined.faces_turned != expected.faces / 2 || middles != expected.faces)
      ok = fail(name + ": " + std::to_string(refined.faces_turned) + " faces turned, " + std::to_string(middles) +
                " middle triangles, of " + std::to_string(expected.faces / 2) + " faces");
  }
  if (D == 3 && refined.faces_turned == 0) ok = fail(name + ": no face turned");
  return ok;
}

// The mesh with two materials, x < 0.5 and x > 0.5, and facets of ref 9 between them: on 2 and 4
// processes the slabs meet on that plane, so each interface face there holds a material facet too.
template <int D>
Mesh<D> two_materials(Mesh<D> mesh) {
  const auto left = [&](Index k) {
    double x = 0;
    for (Index v : mesh.element(k)) x += mesh.vertex(v)[0] / (D + 1);
    return x < 0.5;
  };
  for (Index k = 0; k < mesh.element_count(); ++k) mesh.set_element(k, mesh.element(k), left(k) ? 1 : 2);
  mesh.build_topology();
  for (Index k = 0; k < mesh.element_count(); ++k)
    for (int face = 0; face <= D; ++face)
      if (const Index other = mesh.neighbor(k, face); other != kNoIndex && left(k) && !left(other)) {
        typename Mesh<D>::Facet facet{};
        for (int i = 0; i < D; ++i) facet[i] = mesh.element(k)[face_vertices<D>(face)[i]];
        mesh.add_facet(facet, 9);
      }
  mesh.build_topology();
  return mesh;
}

// The measure of the part's facets of `ref` (their length or area), over every process.
template <int D>
double facets_measure(const MeshPart<D>& part, int ref) {
  double measure = 0;
  for (Index f = 0; f < part.mesh.facet_count(); ++f) {
    if (part.mesh.facet_removed(f) || part.mesh.facet_ref(f) != ref) continue;
    const auto& facet = part.mesh.facet(f);
    const Vec<D> u = part.mesh.vertex(facet[1]) - part.mesh.vertex(facet[0]);
    if constexpr (D == 2)
      measure += norm(u);
    else
      measure += 0.5 * norm(cross(u, part.mesh.vertex(facet[2]) - part.mesh.vertex(facet[0])));
  }
  return sum_over_processes(measure);
}

// An interface face that holds a material's facet keeps its edges (no new vertex on x = 0.5;
// splitting one would leave one of the face's two facets on no element's face, and the refinement
// throws), and the refinement of the other interfaces leaves the part consistent with its material
// facets whole (their measure 1, each a face of an element).
template <int D>
bool check_material_interface(Mesh<D> mesh) {
  const std::string name = std::string(D == 3 ? "cube" : "square") + " of two materials";
  mesh = two_materials(std::move(mesh));
  const P3Surrogate<D> surrogate(mesh);
  MeshPart<D> part = own_slab(std::move(mesh));
  const double material_before = facets_measure(part, 9);
  const Index first_new = first_new_id(part);
  Index next_id = first_new;
  refine_interfaces(part, finer_than_the_lattice<D>(), &surrogate, next_id);
  bool ok = true;
  for (Index v = 0; v < part.mesh.vertex_count(); ++v)
    if (part.global_ids[v] >= first_new && part.mesh.vertex(v)[0] == 0.5) ok = fail(name + ": an edge on the material facets split");
  try {
    Mesh<D>(part.mesh).build_topology();  // each facet a face of an element
  } catch (const Error& error) {
    ok = fail(name + ": " + error.what());
  }
  ok = faces_conform(part) && points_agree(part) && positive_and_filling(part) && ok;
  const double material_after = facets_measure(part, 9);
  if (std::abs(material_after - material_before) > 1e-12)
    ok = fail(name + ": the material facets' measure became " + std::to_string(material_after));
  return ok;
}

}  // namespace
}  // namespace hocav

int main(int argc, char** argv) {
  return hocav::run_mpi_test(argc, argv, "interface refinement", [] {
    bool ok = true;
    for (const bool with_geometry : {false, true})
      ok = hocav::check<3>(hocav::generate_cube(6), with_geometry) & hocav::check<2>(hocav::generate_square(6), with_geometry) & ok;
    return hocav::check_material_interface<3>(hocav::generate_cube(6)) & hocav::check_material_interface<2>(hocav::generate_square(6)) & ok;
  });
}
