"""Distance of a mesh's boundary mid nodes to the CAD model it was meshed from (issue 17's measure).

Every boundary edge (an edge of a boundary triangle) is measured at its mid node: the P2 node of a
P2 mesh, the straight midpoint of a P1 one. Its error is the largest distance, found by gmsh's
getClosestPoint, from the node to the CAD surfaces named by the refs of the triangles around it: on
a face edge the one surface, on a ridge edge (its triangles carry different refs) both, since the
node belongs on the curve they share. Facet refs are mapped to CAD surfaces by proximity (the
surface nearest a sample of each ref's vertices), as `hocav curve --surface cad:FILE` does.

Prints, for face edges, ridge edges and all: count, mean and max error, and how many are within
1e-9 of the model's size; with --json, the same as one JSON object.

Usage: /usr/bin/python3 bench/part_boundary_error.py MESH.mesh CAD.(step|brep) [--json]
(MESH in Gamma ASCII .mesh: convert a .meshb with `hocav convert`.)
"""
import json
import math
import sys

import gmsh


def read_gamma_mesh(path):
    """Vertices and boundary triangles (vertex ids, mid node ids or None, ref) of a .mesh file."""
    tokens = open(path).read().split()
    vertices, triangles, at = [], [], 0
    while at < len(tokens):
        keyword = tokens[at]
        at += 1
        if keyword == "Dimension":
            at += 1
        elif keyword == "Vertices":
            count = int(tokens[at]); at += 1
            for _ in range(count):
                vertices.append(tuple(float(x) for x in tokens[at:at + 3])); at += 4
        elif keyword in ("Triangles", "TrianglesP2"):
            width = 3 if keyword == "Triangles" else 6
            count = int(tokens[at]); at += 1
            for _ in range(count):
                ids = [int(x) - 1 for x in tokens[at:at + width]]
                ref = int(tokens[at + width]); at += width + 1
                triangles.append((ids[:3], ids[3:] if width == 6 else None, ref))
        elif keyword in ("Tetrahedra", "TetrahedraP2", "Edges", "EdgesP2", "Corners", "Ridges",
                         "RequiredVertices", "RequiredEdges", "RequiredTriangles"):
            widths = {"Tetrahedra": 5, "TetrahedraP2": 11, "Edges": 3, "EdgesP2": 4}
            count = int(tokens[at]); at += 1 + count * widths.get(keyword, 1)
        elif keyword in ("MeshVersionFormatted",):
            at += 1
        elif keyword == "End":
            break
        else:
            raise SystemExit(f"{path}: keyword {keyword} not understood")
    return vertices, triangles


def boundary_edges(vertices, triangles):
    """(mid node, refs of the triangles around) per boundary edge."""
    edges = {}
    for ids, mids, ref in triangles:
        for i in range(3):
            a, b = ids[i], ids[(i + 1) % 3]
            key = (min(a, b), max(a, b))
            if key not in edges:
                node = vertices[mids[i]] if mids else tuple(0.5 * (p + q) for p, q in zip(vertices[a], vertices[b]))
                edges[key] = (node, set())
            edges[key][1].add(ref)
    return edges


def distance_to_surface(tag, point):
    closest, _ = gmsh.model.getClosestPoint(2, tag, list(point))
    return math.dist(closest, point)


def in_box(surface, points, tolerance):
    """Whether the points lie in the surface's bounding box (getClosestPoint ignores trimming)."""
    box = gmsh.model.getBoundingBox(2, surface)
    return all(box[c] - tolerance <= p[c] <= box[c + 3] + tolerance for p in points for c in range(3))


def surfaces_of_refs(vertices, triangles, tolerance):
    """The CAD surface of each facet ref, as `hocav curve` maps them: among the surfaces holding a
    sample of the ref's vertices (within tolerance, and in their bounding box), the one nearest to the facets' centroids (a
    narrow face has all its vertices on its neighbours too)."""
    samples = {}
    for ids, _, ref in triangles:
        centroid = tuple(sum(vertices[i][c] for i in ids) / 3 for c in range(3))
        samples.setdefault(ref, []).append((vertices[ids[0]], centroid))
    surfaces = [tag for _, tag in gmsh.model.getEntities(2)]
    mapping = {}
    for ref, points in samples.items():
        points = points[::max(1, len(points) // 16)]
        holding = [s for s in surfaces if in_box(s, [p for p, _ in points], tolerance)
                   and max(distance_to_surface(s, p) for p, _ in points) <= tolerance]
        mapping[ref] = min(holding, key=lambda s: max(distance_to_surface(s, c) for _, c in points))
    return mapping


def summary(errors, model_size):
    if not errors:
        return {"count": 0}
    return {"count": len(errors), "mean": sum(errors) / len(errors), "max": max(errors),
            "on_cad": sum(e <= 1e-9 * model_size for e in errors)}


def main():
    if len(sys.argv) < 3:
        raise SystemExit(__doc__)
    vertices, triangles = read_gamma_mesh(sys.argv[1])
    gmsh.initialize(readConfigFiles=False)
    gmsh.option.setNumber("General.Terminal", 0)
    gmsh.model.occ.importShapes(sys.argv[2])
    gmsh.model.occ.synchronize()
    box = gmsh.model.getBoundingBox(-1, -1)
    model_size = math.dist(box[:3], box[3:])
    surface_of = surfaces_of_refs(vertices, triangles, 1e-3 * model_size)
    face, ridge = [], []
    for node, refs in boundary_edges(vertices, triangles).values():
        error = max(distance_to_surface(surface_of[ref], node) for ref in refs)
        (ridge if len(refs) > 1 else face).append(error)
    result = {"model_size": model_size, "face": summary(face, model_size), "ridge": summary(ridge, model_size),
              "all": summary(face + ridge, model_size)}
    gmsh.finalize()
    if "--json" in sys.argv:
        print(json.dumps(result))
        return
    print(f"model size {model_size:.4g}")
    for name in ("face", "ridge", "all"):
        s = result[name]
        if s["count"]:
            print(f"{name:6s} edges {s['count']:7d}  mean {s['mean']:.3g}  max {s['max']:.3g}  on the CAD {s['on_cad']}")


if __name__ == "__main__":
    main()
