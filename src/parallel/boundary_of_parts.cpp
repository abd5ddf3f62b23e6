#include "parallel/boundary_of_parts.hpp"

#include <algorithm>

#include "parallel/communicator.hpp"
#include "parallel/entity_tags.hpp"
#include "parallel/part_shipment.hpp"

namespace hocav {
namespace {

// A part's boundary as a shipment without elements: its facets but the interfaces', its lines, and
// the vertices of those, its corners and the mesh's required vertices.
template <int D>
Shipment<D> boundary_shipment(const MeshPart<D>& part) {
  const Mesh<D>& mesh = part.mesh;
  const EntityTags<D> tags(mesh);
  Shipment<D> s;
  std::vector<char> taken(static_cast<std::size_t>(mesh.vertex_count()), 0);
  const auto take = [&](Index v) {
    if (taken[v]) return;
    taken[v] = 1;
    s.vertex_ids.push_back(part.global_ids[v]);
    s.points.push_back(mesh.vertex(v));
    s.vertex_refs.push_back(mesh.vertex_ref(v));
    s.vertex_flags.push_back(static_cast<char>((tags.corner[v] ? kShippedCorner : 0) | ((part.pinned[v] & kPinnedByMesh) << 1)));
  };
  const auto global = [&](const auto& ids) {
    auto out = ids;
    for (Index& v : out) take(v), v = part.global_ids[v];
    return out;
  };
  for (Index f = 0; f < mesh.facet_count(); ++f) {
    if (mesh.facet(f)[0] == kNoIndex || mesh.facet_ref(f) == kInterfaceRef) continue;
    s.facets.push_back(global(mesh.facet(f)));
    s.facet_refs.push_back(mesh.facet_ref(f));
    s.facet_flags.push_back(static_cast<char>((tags.required_facet[f] ? kShippedRequired : 0) | (tags.ridge_facet[f] ? kShippedRidge : 0)));
  }
  if constexpr (D == 3)
    for (Index l = 0; l < mesh.line_count(); ++l) {
      s.lines.push_back(global(mesh.line(l)));
      s.line_refs.push_back(mesh.line_ref(l));
      s.line_flags.push_back(static_cast<char>((tags.required_line[l] ? kShippedRequired : 0) | (tags.ridge_line[l] ? kShippedRidge : 0)));
    }
  for (Index v = 0; v < mesh.vertex_count(); ++v)
    if (tags.corner[v] || (part.pinned[v] & kPinnedByMesh)) take(v);
  return s;
}

}  // namespace

template <int D>
MeshPart<D> boundary_of_parts(const MeshPart<D>& part, long long* bytes_sent) {
  const std::vector<std::byte> own = boundary_shipment(part).bytes();
  if (bytes_sent) *bytes_sent += static_cast<long long>(own.size()) * (process_count() - 1);
  std::vector<Shipment<D>> arrived;
  for (const std::vector<std::byte>& bytes : all_gather_bytes(own)) arrived.push_back(Shipment<D>::read(bytes));
  return part_of_shipments(arrived);
}

template <int D>
std::vector<Index> boundary_indices(const MeshPart<D>& part, std::span<const Index> boundary_ids) {
  std::vector<Index> out;
  out.reserve(part.global_ids.size());
  for (Index g : part.global_ids) {
    const auto at = std::lower_bound(boundary_ids.begin(), boundary_ids.end(), g);
    out.push_back(at != boundary_ids.end() && *at == g ? static_cast<Index>(at - boundary_ids.begin()) : kNoIndex);
  }
  return out;
}

template MeshPart<2> boundary_of_parts(const MeshPart<2>&, long long*);
template MeshPart<3> boundary_of_parts(const MeshPart<3>&, long long*);
template std::vector<Index> boundary_indices(const MeshPart<2>&, std::span<const Index>);
template std::vector<Index> boundary_indices(const MeshPart<3>&, std::span<const Index>);

}  // namespace hocav
