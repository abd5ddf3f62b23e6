#include "io/gmsh_msh_text.hpp"

#include "base/error.hpp"

namespace hocav::gmsh_msh {

const ElementType* find_element_type(std::int64_t gmsh_type) {
  for (const ElementType& type : kElementTypes)
    if (type.gmsh_type == gmsh_type) return &type;
  return nullptr;
}

const ElementType& element_type(int dimension, int order) {
  for (const ElementType& type : kElementTypes)
    if (type.dimension == dimension && type.order == order) return type;
  throw Error("no Gmsh element type of dimension " + std::to_string(dimension));
}

void write_nodes_head(TextWriter& out, int dimension, Index node_count) {
  out << "$Nodes\n";
  if (node_count == 0) {
    out << "0 0 0 0\n$EndNodes\n";
    return;
  }
  out << "1 " << node_count << " 1 " << node_count << '\n' << dimension << " 1 0 " << node_count << '\n';
}

void write_elements_head(TextWriter& out, std::size_t blocks, std::size_t elements) {
  out << "$Elements\n" << blocks << ' ' << elements << ' ' << (elements > 0 ? 1 : 0) << ' ' << elements << '\n';
}

void write_block_head(TextWriter& out, std::size_t entity, const ElementType& type, std::size_t count) {
  out << type.dimension << ' ' << entity << ' ' << type.gmsh_type << ' ' << count << '\n';
}

void write_element(TextWriter& out, std::size_t tag, const ElementType& type, const Index* numbers) {
  out << tag;
  for (int position = 0; position < type.node_count; ++position)
    out << ' ' << numbers[static_cast<std::size_t>(type.hocav_position[static_cast<std::size_t>(position)])] + 1;
  out << '\n';
}

}  // namespace hocav::gmsh_msh
