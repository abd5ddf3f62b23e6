#include "io/gamma_keywords.hpp"

#include <array>

namespace hocav::gamma {
namespace {

struct KnownKeyword {
  int code;
  std::string_view name;
  bool unsupported_element = false;
};

constexpr KnownKeyword kKnownKeywords[] = {
    {kMeshVersionFormatted, "MeshVersionFormatted"},
    {kDimension, "Dimension"},
    {kVertices, "Vertices"},
    {kEdges, "Edges"},
    {kTriangles, "Triangles"},
    {7, "Quadrilaterals", true},
    {kTetrahedra, "Tetrahedra"},
    {9, "Prisms", true},
    {10, "Hexahedra", true},
    {kCorners, "Corners"},
    {kRidges, "Ridges"},
    {kRequiredVertices, "RequiredVertices"},
    {kRequiredEdges, "RequiredEdges"},
    {kRequiredTriangles, "RequiredTriangles"},
    {19, "TangentAtEdgeVertices"},
    {20, "NormalAtVertices"},
    {21, "NormalAtTriangleVertices"},
    {23, "AngleOfCornerBound"},
    {kTrianglesP2, "TrianglesP2"},
    {kEdgesP2, "EdgesP2"},
    {27, "QuadrilateralsQ2", true},
    {kTetrahedraP2, "TetrahedraP2"},
    {33, "HexahedraQ2", true},
    {49, "Pyramids", true},
    {50, "BoundingBox"},
    {kEnd, "End"},
    {59, "Tangents"},
    {60, "Normals"},
    {61, "TangentAtVertices"},
    {kSolAtVertices, "SolAtVertices"},
    {63, "SolAtEdges"},
    {64, "SolAtTriangles"},
    {66, "SolAtTetrahedra"},
    {77, "Iterations"},
    {78, "Time"},
    {86, "PrismsP2", true},
    {87, "PyramidsP2", true},
    {90, "TrianglesP3", true},
    {91, "TrianglesP4", true},
    {92, "EdgesP3", true},
    {93, "EdgesP4", true},
    {96, "TetrahedraP3", true},
    {97, "TetrahedraP4", true},
    {126, "ByteFlow"},
    {kEdgesP2Ordering, "EdgesP2Ordering"},
    {kTrianglesP2Ordering, "TrianglesP2Ordering"},
    {kTetrahedraP2Ordering, "TetrahedraP2Ordering"},
};

constexpr std::array<SimplexKeyword, 6> kSimplexKeywords{{
    {kEdges, 1, 1, 2, kUnknown},
    {kTriangles, 2, 1, 3, kUnknown},
    {kTetrahedra, 3, 1, 4, kUnknown},
    {kEdgesP2, 1, 2, 3, kEdgesP2Ordering},
    {kTrianglesP2, 2, 2, 6, kTrianglesP2Ordering},
    {kTetrahedraP2, 3, 2, 10, kTetrahedraP2Ordering},
}};

const KnownKeyword* known_keyword(int code) {
  for (const auto& keyword : kKnownKeywords)
    if (keyword.code == code) return &keyword;
  return nullptr;
}

}  // namespace

int keyword_code(std::string_view name) {
  for (const auto& keyword : kKnownKeywords)
    if (keyword.name == name) return keyword.code;
  return kUnknown;
}

std::string keyword_name(int code) {
  const KnownKeyword* keyword = known_keyword(code);
  return keyword ? std::string(keyword->name) : "code " + std::to_string(code);
}

bool is_unsupported_element(int code) {
  const KnownKeyword* keyword = known_keyword(code);
  return keyword && keyword->unsupported_element;
}

const SimplexKeyword* simplex_keyword(int code) {
  for (const auto& keyword : kSimplexKeywords)
    if (keyword.code == code) return &keyword;
  return nullptr;
}

const SimplexKeyword& simplex_keyword(int simplex_dimension, int order) {
  return kSimplexKeywords[static_cast<std::size_t>(3 * (order - 1) + simplex_dimension - 1)];
}

const SimplexKeyword* ordered_keyword(int ordering_code) {
  for (const auto& keyword : kSimplexKeywords)
    if (keyword.ordering_code != kUnknown && keyword.ordering_code == ordering_code) return &keyword;
  return nullptr;
}

}  // namespace hocav::gamma
