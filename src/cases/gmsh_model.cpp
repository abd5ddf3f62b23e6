#include "cases/gmsh_model.hpp"

#include <gmsh.h>

#include <algorithm>
#include <array>
#include <clocale>
#include <cmath>
#include <map>
#include <tuple>

#include "mesh/measure.hpp"

// gmsh 4.8.4 leaks a few small blocks in its surface mesher (meshGFace) for every meshed surface,
// and OpenCASCADE's STEP writer keeps never-freed statics (its libTK* libraries); LeakSanitizer is
// told to ignore allocations made inside those, and still reports hocav's own.
#if defined(__SANITIZE_ADDRESS__)
extern "C" const char* __lsan_default_suppressions() { return "leak:libgmsh.so\nleak:libTK\n"; }
#endif

namespace hocav {
namespace {

std::mutex gmsh_mutex;
// A second session in the thread that holds the mutex would wait for itself forever: refuse it.
thread_local bool thread_holds_gmsh = false;

std::unique_lock<std::mutex> lock_gmsh() {
  if (thread_holds_gmsh) throw Error("gmsh is already in use in this thread (a gmsh session or CAD boundary is open)");
  std::unique_lock<std::mutex> lock(gmsh_mutex);
  thread_holds_gmsh = true;
  return lock;
}

// gmsh element types: 2-node line, 3-node triangle, 4-node tetrahedron.
constexpr int kGmshLine = 1, kGmshTriangle = 2, kGmshTetrahedron = 4;

template <int D>
constexpr int gmsh_element_type = D == 2 ? kGmshTriangle : kGmshTetrahedron;
template <int D>
constexpr int gmsh_facet_type = D == 2 ? kGmshLine : kGmshTriangle;

template <int D>
double signed_measure_of(const Mesh<D>& mesh, const typename Mesh<D>::Element& element) {
  return std::apply([&mesh](auto... v) { return signed_measure(mesh.vertex(v)...); }, element);
}

template <std::size_t N>
std::array<Index, N> sorted(std::array<Index, N> ids) {
  std::sort(ids.begin(), ids.end());
  return ids;
}

// Adds a vertex for every node the elements use, in node-tag order; returns the vertex of each tag.
template <int D>
std::vector<Index> add_used_nodes(Mesh<D>& mesh, const std::vector<std::size_t>& element_node_tags) {
  std::vector<std::size_t> tags;
  std::vector<double> coordinates, parametric_coordinates;
  gmsh::model::mesh::getNodes(tags, coordinates, parametric_coordinates, -1, -1, true, false);
  std::size_t max_tag = tags.empty() ? 0 : *std::max_element(tags.begin(), tags.end());
  constexpr std::size_t kAbsent = static_cast<std::size_t>(-1);
  std::vector<std::size_t> position_of_tag(max_tag + 1, kAbsent);
  for (std::size_t i = 0; i < tags.size(); ++i) position_of_tag[tags[i]] = i;

  std::vector<bool> used(max_tag + 1, false);
  for (std::size_t tag : element_node_tags) {
    if (tag > max_tag || position_of_tag[tag] == kAbsent) throw Error("gmsh: an element uses unknown node " + std::to_string(tag));
    used[tag] = true;
  }
  std::vector<Index> vertex_of_tag(max_tag + 1, kNoIndex);
  for (std::size_t tag = 0; tag <= max_tag; ++tag) {
    if (!used[tag]) continue;
    const double* xyz = &coordinates[3 * position_of_tag[tag]];
    Vec<D> point;
    for (int i = 0; i < D; ++i) point[i] = xyz[i];
    if (D == 2 && xyz[2] != 0.0) throw Error("gmsh: node " + std::to_string(tag) + " of a planar mesh is off the plane z = 0");
    vertex_of_tag[tag] = mesh.add_vertex(point);
  }
  return vertex_of_tag;
}

// The ref of every boundary facet gmsh meshed on the listed entities, keyed by sorted vertices.
template <int D>
std::map<std::array<Index, D>, int> boundary_facet_refs(const std::vector<GmshBoundaryEntity>& boundary,
                                                        const std::vector<Index>& vertex_of_tag) {
  std::map<std::array<Index, D>, int> refs;
  for (const GmshBoundaryEntity& entity : boundary) {
    std::vector<std::size_t> facet_tags, facet_node_tags;
    gmsh::model::mesh::getElementsByType(gmsh_facet_type<D>, facet_tags, facet_node_tags, entity.tag);
    for (std::size_t first = 0; first < facet_node_tags.size(); first += D) {
      std::array<Index, D> facet;
      for (int i = 0; i < D; ++i) {
        std::size_t tag = facet_node_tags[first + i];
        facet[i] = tag < vertex_of_tag.size() ? vertex_of_tag[tag] : kNoIndex;
      }
      refs[sorted(facet)] = entity.ref;
    }
  }
  return refs;
}

template <int D>
Mesh<D> extract(const std::vector<GmshBoundaryEntity>& boundary, int element_ref) {
  Mesh<D> mesh;
  std::vector<std::size_t> element_tags, element_node_tags;
  gmsh::model::mesh::getElementsByType(gmsh_element_type<D>, element_tags, element_node_tags, -1);
  if (element_tags.empty()) throw Error("gmsh: the mesh has no elements (is the size too large?)");
  std::vector<Index> vertex_of_tag = add_used_nodes(mesh, element_node_tags);

  for (std::size_t first = 0; first < element_node_tags.size(); first += D + 1) {
    typename Mesh<D>::Element element;
    for (int i = 0; i <= D; ++i) element[i] = vertex_of_tag[element_node_tags[first + i]];
    double measure = signed_measure_of(mesh, element);
    if (measure == 0.0 || !std::isfinite(measure)) throw Error("gmsh: element " + one_based(mesh.element_count()) + " is flat");
    if (measure < 0) std::swap(element[D - 1], element[D]);
    mesh.add_element(element, element_ref);
  }
  mesh.build_topology();

  // Facets from the element faces without a neighbour: complete, and outward by construction.
  auto refs = boundary_facet_refs<D>(boundary, vertex_of_tag);
  for (Index k = 0; k < mesh.element_count(); ++k)
    for (int face = 0; face <= D; ++face) {
      if (mesh.neighbor(k, face) != kNoIndex) continue;
      typename Mesh<D>::Facet facet;
      for (int i = 0; i < D; ++i) facet[i] = mesh.element(k)[face_vertices<D>(face)[i]];
      auto found = refs.find(sorted(facet));
      if (found == refs.end())
        throw Error("gmsh: boundary face " + one_based(face) + " of element " + one_based(k) + " lies on no boundary entity");
      mesh.add_facet(facet, found->second);
    }
  mesh.build_topology();
  return mesh;
}

}  // namespace

bool gmsh_available() { return true; }

GmshSession::GmshSession(const std::string& model_name) : lock_(lock_gmsh()), saved_locale_(std::setlocale(LC_ALL, nullptr)) {
  bool initialized = false;
  try {
    call_gmsh([] { gmsh::initialize(0, nullptr, /*readConfigFiles=*/false); });
    initialized = true;
    call_gmsh([&model_name] {
      gmsh::option::setNumber("General.Terminal", 0);
      gmsh::option::setNumber("General.Verbosity", 0);
      gmsh::option::setNumber("General.AbortOnError", 3);  // throw on every error
      gmsh::option::setNumber("General.NumThreads", 1);
      gmsh::option::setNumber("Mesh.RandomSeed", 1);
      gmsh::model::add(model_name);
    });
  } catch (...) {
    if (initialized) gmsh::finalize();
    std::setlocale(LC_ALL, saved_locale_.c_str());
    thread_holds_gmsh = false;
    throw;
  }
}

GmshSession::~GmshSession() {
  try {
    gmsh::finalize();
  } catch (...) {
    // Nothing useful to do about a failing cleanup in a destructor.
  }
  std::setlocale(LC_ALL, saved_locale_.c_str());
  thread_holds_gmsh = false;
}

template <int D>
Mesh<D> extract_gmsh_mesh(const std::vector<GmshBoundaryEntity>& boundary, int element_ref) {
  return call_gmsh([&] { return extract<D>(boundary, element_ref); });
}

template Mesh<2> extract_gmsh_mesh(const std::vector<GmshBoundaryEntity>&, int);
template Mesh<3> extract_gmsh_mesh(const std::vector<GmshBoundaryEntity>&, int);

}  // namespace hocav
