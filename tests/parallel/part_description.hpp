// Parts of a distributed mesh compared entity by entity by global ids, whatever their local numbering
// and order: what the MPI tests of the migration and of reading in pieces check parts with.
#pragma once

#include <algorithm>
#include <array>
#include <sstream>
#include <string>
#include <vector>

#include "parallel/mesh_parts.hpp"

namespace hocav {

template <std::size_t N>
std::string ids(const std::array<Index, N>& local, const std::vector<Index>& global) {
  std::string out;
  for (Index v : local) out += std::to_string(global[v]) + ' ';
  return out;
}

template <int D>
std::string point(const Vec<D>& x) {
  std::ostringstream out;
  out << std::hexfloat;
  for (int i = 0; i < D; ++i) out << x[i] << ' ';
  return out.str();
}

// A part as sorted lines of text, entity by entity by global ids, so that two parts compare whatever
// their local numbering and order.
template <int D>
std::vector<std::string> described(const MeshPart<D>& part) {
  const Mesh<D>& mesh = part.mesh;
  const auto flag = [](const std::vector<Index>& list, Index id) { return std::find(list.begin(), list.end(), id) != list.end(); };
  const std::vector<Index>& required_facets = D == 2 ? mesh.required_edges() : mesh.required_triangles();
  std::vector<std::string> lines{"topology " + std::to_string(mesh.has_topology())};
  for (Index v = 0; v < mesh.vertex_count(); ++v)
    lines.push_back("v " + std::to_string(part.global_ids[v]) + ' ' + point<D>(mesh.vertex(v)) + std::to_string(mesh.vertex_ref(v)) +
                    " corner " + std::to_string(flag(mesh.corners(), v)) + " required " +
                    std::to_string(flag(mesh.required_vertices(), v)) + " pinned " + std::to_string(part.pinned.at(v)));
  for (Index k = 0; k < mesh.element_count(); ++k) {
    std::string line = "e " + ids(mesh.element(k), part.global_ids) + std::to_string(mesh.element_ref(k));
    if (mesh.is_p2())
      for (int e = 0; e < Simplex<D>::kEdges; ++e) line += " | " + point<D>(mesh.edge_node(mesh.element_edge(k, e)));
    lines.push_back(line);
  }
  for (Index f = 0; f < mesh.facet_count(); ++f)
    lines.push_back("f " + ids(mesh.facet(f), part.global_ids) + std::to_string(mesh.facet_ref(f)) + " required " +
                    std::to_string(flag(required_facets, f)) + " ridge " + std::to_string(D == 2 && flag(mesh.ridges(), f)));
  for (Index l = 0; l < mesh.line_count(); ++l) {
    auto ends = mesh.line(l);
    if (part.global_ids[ends[0]] > part.global_ids[ends[1]]) std::swap(ends[0], ends[1]);
    lines.push_back("l " + ids(ends, part.global_ids) + std::to_string(mesh.line_ref(l)) + " ridge " +
                    std::to_string(D == 3 && flag(mesh.ridges(), l)) + " required " + std::to_string(flag(mesh.required_edges(), l)));
  }
  std::sort(lines.begin(), lines.end());
  return lines;
}

// Empty when the parts hold the same entities; else their sizes and the first difference.
template <int D>
std::string part_difference(const MeshPart<D>& got, const MeshPart<D>& expected) {
  const std::vector<std::string> a = described(got), b = described(expected);
  if (a == b) return {};
  const auto [first, second] = std::mismatch(a.begin(), a.end(), b.begin(), b.end());
  return std::to_string(a.size()) + " entities against " + std::to_string(b.size()) + "; first difference: '" +
         (first == a.end() ? "(end)" : *first) + "' against '" + (second == b.end() ? "(end)" : *second) + "'";
}

}  // namespace hocav
