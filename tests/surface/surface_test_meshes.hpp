// Boundary-only meshes for the surface tests (no gmsh): triangulated spheres and polygonal circles
// with outward facets, optionally with vertices moved along the surface to make them irregular.
#pragma once

#include <array>
#include <cmath>
#include <map>
#include <numbers>
#include <random>
#include <utility>

#include "mesh/mesh.hpp"
#include "surface/cubic_patch.hpp"

namespace hocav::testing {

// Moves every vertex along the sphere/circle by up to `jitter` × (the mean edge length), at random.
template <int D>
void jitter_on_sphere(Mesh<D>& mesh, double radius, double jitter, unsigned seed) {
  if (jitter == 0) return;
  double mean_edge = 0;
  for (Index f = 0; f < mesh.facet_count(); ++f) mean_edge += norm(mesh.vertex(mesh.facet(f)[1]) - mesh.vertex(mesh.facet(f)[0]));
  mean_edge /= mesh.facet_count();
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> offset(-jitter * mean_edge, jitter * mean_edge);
  for (Index v = 0; v < mesh.vertex_count(); ++v) {
    Vec<D> moved = mesh.vertex(v);
    for (int i = 0; i < D; ++i) moved[i] += offset(random);
    mesh.vertex(v) = moved * (radius / norm(moved));
  }
}

// The icosahedron subdivided `levels` times (4 triangles per triangle), vertices on the sphere of
// the given radius centred at the origin; facets outward, ref 1.
inline Mesh<3> icosphere(int levels, double radius = 1.0, double jitter = 0.0, unsigned seed = 1) {
  const double g = (1 + std::sqrt(5.0)) / 2;
  Mesh<3> mesh;
  for (const Vec3& p : {Vec3{{-1, g, 0}}, Vec3{{1, g, 0}}, Vec3{{-1, -g, 0}}, Vec3{{1, -g, 0}}, Vec3{{0, -1, g}}, Vec3{{0, 1, g}},
                        Vec3{{0, -1, -g}}, Vec3{{0, 1, -g}}, Vec3{{g, 0, -1}}, Vec3{{g, 0, 1}}, Vec3{{-g, 0, -1}}, Vec3{{-g, 0, 1}}})
    mesh.add_vertex(p * (radius / norm(p)));
  std::vector<std::array<Index, 3>> faces{{0, 11, 5},  {0, 5, 1},  {0, 1, 7},  {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
                                          {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
                                          {3, 8, 9},   {4, 9, 5},  {2, 4, 11}, {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
  for (int level = 0; level < levels; ++level) {
    std::map<std::pair<Index, Index>, Index> middles;
    auto middle = [&](Index a, Index b) {
      auto key = std::minmax(a, b);
      auto found = middles.find(key);
      if (found != middles.end()) return found->second;
      Vec3 m = 0.5 * (mesh.vertex(a) + mesh.vertex(b));
      return middles[key] = mesh.add_vertex(m * (radius / norm(m)));
    };
    std::vector<std::array<Index, 3>> finer;
    for (const auto& [a, b, c] : faces) {
      Index ab = middle(a, b), bc = middle(b, c), ca = middle(c, a);
      finer.insert(finer.end(), {{a, ab, ca}, {b, bc, ab}, {c, ca, bc}, {ab, bc, ca}});
    }
    faces = std::move(finer);
  }
  for (auto face : faces) {
    const Vec3 &a = mesh.vertex(face[0]), &b = mesh.vertex(face[1]), &c = mesh.vertex(face[2]);
    if (dot(cross(b - a, c - a), a + b + c) < 0) std::swap(face[1], face[2]);
    mesh.add_facet(face, 1);
  }
  jitter_on_sphere(mesh, radius, jitter, seed);
  return mesh;
}

// A circle of `segments` boundary segments, counter-clockwise (outward normals), ref 1.
inline Mesh<2> circle_polygon(int segments, double radius = 1.0, double jitter = 0.0, unsigned seed = 1) {
  Mesh<2> mesh;
  for (int i = 0; i < segments; ++i) {
    const double angle = 2 * std::numbers::pi * i / segments;
    mesh.add_vertex(Vec2{{radius * std::cos(angle), radius * std::sin(angle)}});
  }
  for (Index i = 0; i < segments; ++i) mesh.add_facet({i, (i + 1) % segments}, 1);
  jitter_on_sphere(mesh, radius, jitter, seed);
  return mesh;
}

// The closed cylinder of radius 1 and height 1 around the z axis from z = 0: `segments` around,
// rings about as far apart along the side and on the caps. Refs 1 side, 2 bottom cap (z = 0), 3 top
// cap (z = 1); facets outward.
inline Mesh<3> capped_cylinder(int segments) {
  const double h = 2 * std::numbers::pi / segments;
  const int layers = std::max(1, int(std::lround(1 / h))), rings = std::max(1, int(std::lround(1 / h)));
  Mesh<3> mesh;
  auto ring_vertex = [&](int i, double radius, double z) {
    const double angle = 2 * std::numbers::pi * (i % segments) / segments;
    return mesh.add_vertex(Vec3{{radius * std::cos(angle), radius * std::sin(angle), z}});
  };
  // Side: layer l holds vertices side[l][i].
  std::vector<std::vector<Index>> side(layers + 1);
  for (int l = 0; l <= layers; ++l)
    for (int i = 0; i < segments; ++i) side[l].push_back(ring_vertex(i, 1.0, double(l) / layers));
  auto add_outward = [&mesh](std::array<Index, 3> facet, const Vec3& outward, int ref) {
    const Vec3 normal = cross(mesh.vertex(facet[1]) - mesh.vertex(facet[0]), mesh.vertex(facet[2]) - mesh.vertex(facet[0]));
    if (dot(normal, outward) < 0) std::swap(facet[1], facet[2]);
    mesh.add_facet(facet, ref);
  };
  for (int l = 0; l < layers; ++l)
    for (int i = 0; i < segments; ++i) {
      const int j = (i + 1) % segments;
      const Vec3 centre = mesh.vertex(side[l][i]) + mesh.vertex(side[l + 1][j]);
      const Vec3 outward{{centre[0], centre[1], 0}};
      add_outward({side[l][i], side[l][j], side[l + 1][j]}, outward, 1);
      add_outward({side[l][i], side[l + 1][j], side[l + 1][i]}, outward, 1);
    }
  // Caps: concentric rings, the outer one shared with the side, and a centre vertex.
  for (int cap = 0; cap < 2; ++cap) {
    const double z = cap;
    const Vec3 outward{{0, 0, cap == 0 ? -1.0 : 1.0}};
    std::vector<Index> outer = side[cap == 0 ? 0 : layers];
    for (int r = rings - 1; r >= 1; --r) {
      std::vector<Index> inner;
      for (int i = 0; i < segments; ++i) inner.push_back(ring_vertex(i, double(r) / rings, z));
      for (int i = 0; i < segments; ++i) {
        const int j = (i + 1) % segments;
        add_outward({outer[i], outer[j], inner[j]}, outward, 2 + cap);
        add_outward({outer[i], inner[j], inner[i]}, outward, 2 + cap);
      }
      outer = inner;
    }
    const Index centre = mesh.add_vertex(Vec3{{0, 0, z}});
    for (int i = 0; i < segments; ++i) add_outward({outer[i], outer[(i + 1) % segments], centre}, outward, 2 + cap);
  }
  return mesh;
}

// The point of patch edge e at parameter s ∈ [0, 1] from its first vertex.
template <int D>
PatchParameters<D> patch_edge_parameters(int edge, double s) {
  std::array<double, D> lambda{};
  lambda[kPatchEdges<D>[edge][0]] = 1 - s;
  lambda[kPatchEdges<D>[edge][1]] = s;
  PatchParameters<D> parameters;
  for (int i = 1; i < D; ++i) parameters[i - 1] = lambda[i];
  return parameters;
}

// Samples every patch on a lattice of n intervals per side and returns the largest |‖S‖ − r|
// (distance of the surrogate to the sphere of radius r centred at the origin).
template <int D, class Surrogate>
double max_distance_to_sphere(const Surrogate& surrogate, double radius, int n) {
  double worst = 0;
  for (Index p = 0; p < surrogate.patch_count(); ++p)
    for (int i = 0; i <= n; ++i)
      for (int j = 0; j <= (D == 3 ? n - i : 0); ++j) {
        PatchParameters<D> parameters;
        parameters[0] = double(i) / n;
        if constexpr (D == 3) parameters[1] = double(j) / n;
        worst = std::max(worst, std::abs(norm(evaluate(surrogate.patch(p), parameters)) - radius));
      }
  return worst;
}

}  // namespace hocav::testing
