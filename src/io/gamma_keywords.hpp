// The keywords of the Gamma/Medit formats (.mesh/.meshb/.sol/.solb) that hocav reads, writes or
// recognizes: codes as in the public libMeshb header (docs/formats.md lists them), names as written in
// ASCII files. One table serves the ASCII and binary readers and writers of meshes and solutions.
#pragma once

#include <string>
#include <string_view>

namespace hocav::gamma {

enum Keyword : int {
  kUnknown = 0,
  kMeshVersionFormatted = 1,
  kDimension = 3,
  kVertices = 4,
  kEdges = 5,
  kTriangles = 6,
  kTetrahedra = 8,
  kCorners = 13,
  kRidges = 14,
  kRequiredVertices = 15,
  kRequiredEdges = 16,
  kRequiredTriangles = 17,
  kTrianglesP2 = 24,
  kEdgesP2 = 25,
  kTetrahedraP2 = 30,
  kEnd = 54,
  kSolAtVertices = 62,
  kEdgesP2Ordering = 127,
  kTrianglesP2Ordering = 129,
  kTetrahedraP2Ordering = 133,
};

// The code of a keyword name, or kUnknown. Besides the keywords above, knows a few that hocav
// skips (Normals, Tangents, Quadrilaterals...) so that binary warnings can name them.
int keyword_code(std::string_view name);

// The name of a keyword code; "code <code>" when the table does not know it.
std::string keyword_name(int code);

// Element kinds hocav cannot represent (quadrilaterals, hexahedra, prisms, pyramids, orders above
// 2): a reader refuses them rather than drop part of the mesh.
bool is_unsupported_element(int code);

// The simplicial node lists: Edges, Triangles, Tetrahedra and their P2 versions.
struct SimplexKeyword {
  int code;
  int simplex_dimension;  // 1 edge, 2 triangle, 3 tetrahedron
  int order;              // 1 or 2
  int node_count;         // ids per entity (a ref follows)
  int ordering_code;      // the *P2Ordering keyword that may permute the nodes, or kUnknown
};

// The simplex keyword with this code, or nullptr.
const SimplexKeyword* simplex_keyword(int code);
// The simplex keyword of a dimension and order.
const SimplexKeyword& simplex_keyword(int simplex_dimension, int order);
// The simplex keyword an ordering keyword applies to, or nullptr when `code` is no ordering.
const SimplexKeyword* ordered_keyword(int ordering_code);

}  // namespace hocav::gamma
