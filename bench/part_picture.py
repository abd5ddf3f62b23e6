"""A picture of a curved P2 mesh of the machined part: its boundary surface, and its cut by a plane.

Left, the boundary: every P2 triangle drawn as its quadratic patch (sampled on a lattice), shaded
by a light. Right, the cut by the plane y = Y: each tetrahedron's P2 faces sampled on a lattice and
cut by marching triangles, so curved edges show as curves; the boundary's cut drawn thicker, and an
enlarged detail beside it.

Usage: /usr/bin/python3 bench/part_picture.py CURVED.mesh OUT.png [Y (0.31)] [x0,x1,z0,z1 of the detail (0.6,0.8,0.08,0.42)]
(CURVED in Gamma ASCII .mesh, as `hocav curve -o curved.mesh` writes it.)
"""
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np
from matplotlib.collections import LineCollection
from mpl_toolkits.mplot3d.art3d import Poly3DCollection

# Mid node of edge (i, j) of a P2 tetrahedron in the default .mesh order v0 v1 v2 v3 m01 m12 m20 m03 m13 m23.
TET_MID = {(0, 1): 4, (1, 2): 5, (0, 2): 6, (0, 3): 7, (1, 3): 8, (2, 3): 9}


def read_p2_mesh(path):
    tokens = open(path).read().split()
    at, blocks = 0, {}
    widths = {"Vertices": 4, "TrianglesP2": 7, "TetrahedraP2": 11, "EdgesP2": 4, "Corners": 1, "Ridges": 1,
              "RequiredVertices": 1, "RequiredEdges": 1, "RequiredTriangles": 1}
    while at < len(tokens):
        keyword = tokens[at]
        at += 1
        if keyword in ("MeshVersionFormatted", "Dimension"):
            at += 1
        elif keyword == "End":
            break
        elif keyword in widths:
            count, width = int(tokens[at]), widths[keyword]
            blocks[keyword] = np.array(tokens[at + 1:at + 1 + count * width], dtype=float).reshape(count, width)
            at += 1 + count * width
        else:
            raise SystemExit(f"{path}: keyword {keyword} not understood (a P2 mesh is expected)")
    return blocks["Vertices"][:, :3], blocks["TrianglesP2"][:, :6].astype(int) - 1, blocks["TetrahedraP2"][:, :10].astype(int) - 1


def lattice(n):
    """Barycentric points of the order-n lattice and its sub-triangles."""
    index, points = {}, []
    for i in range(n + 1):
        for j in range(n + 1 - i):
            index[i, j] = len(points)
            points.append((1 - (i + j) / n, i / n, j / n))
    triangles = []
    for i in range(n):
        for j in range(n - i):
            triangles.append((index[i, j], index[i + 1, j], index[i, j + 1]))
            if i + j < n - 1:
                triangles.append((index[i + 1, j], index[i + 1, j + 1], index[i, j + 1]))
    return np.array(points), np.array(triangles)


def evaluate(nodes, bary):
    """Points of quadratic triangles (nodes: count x 6 x 3, v0 v1 v2 m01 m12 m20) at barycentrics."""
    l0, l1, l2 = bary[:, 0], bary[:, 1], bary[:, 2]
    shape = np.stack([l0 * (2 * l0 - 1), l1 * (2 * l1 - 1), l2 * (2 * l2 - 1), 4 * l0 * l1, 4 * l1 * l2, 4 * l2 * l0], 1)
    return np.einsum("pk,tkc->tpc", shape, nodes)


def tet_faces(tets):
    faces = []
    for a, b, c in ((1, 2, 3), (0, 2, 3), (0, 1, 3), (0, 1, 2)):
        faces.append(tets[:, [a, b, c, TET_MID[a, b], TET_MID[b, c], TET_MID[tuple(sorted((a, c)))]]])
    return np.concatenate(faces)


def cut_segments(points, triangles, y):
    """Segments (x, z) where the sampled patches cross the plane y."""
    corners = points[:, triangles]  # patches x sub-triangles x 3 x 3
    corners = corners.reshape(-1, 3, 3)
    side = corners[:, :, 1] - y
    crossing = (side.min(1) < 0) & (side.max(1) > 0)
    corners, side = corners[crossing], side[crossing]
    segments = []
    for a, b in ((0, 1), (1, 2), (2, 0)):
        cut = (side[:, a] < 0) != (side[:, b] < 0)
        t = np.where(cut, side[:, a] / np.where(cut, side[:, a] - side[:, b], 1), 0)
        segments.append((corners[:, a] + t[:, None] * (corners[:, b] - corners[:, a]), cut))
    (p0, c0), (p1, c1), (p2, c2) = segments
    first = np.where(c0[:, None], p0, p1)
    second = np.where((c0 & c1)[:, None], p1, p2)
    return np.stack([first[:, [0, 2]], second[:, [0, 2]]], 1)


def main():
    if len(sys.argv) < 3:
        raise SystemExit(__doc__)
    y = float(sys.argv[3]) if len(sys.argv) > 3 else 0.31
    detail = [float(v) for v in sys.argv[4].split(",")] if len(sys.argv) > 4 else [0.6, 0.8, 0.08, 0.42]
    vertices, triangles, tets = read_p2_mesh(sys.argv[1])
    figure = plt.figure(figsize=(15, 5.2))

    surface = figure.add_subplot(1, 3, 1, projection="3d")
    bary, subs = lattice(3)
    patches = evaluate(vertices[triangles], bary)[:, subs].reshape(-1, 3, 3)
    normals = np.cross(patches[:, 1] - patches[:, 0], patches[:, 2] - patches[:, 0])
    normals /= np.linalg.norm(normals, axis=1, keepdims=True)
    light = np.clip(normals @ np.array([0.3, -0.5, 0.8]) / np.linalg.norm([0.3, -0.5, 0.8]), 0, 1)
    surface.add_collection3d(Poly3DCollection(patches, facecolors=plt.cm.Greys_r(0.25 + 0.7 * light), linewidths=0))
    surface.set_xlim(0, 1), surface.set_ylim(-0.2, 0.8), surface.set_zlim(-0.3, 0.7)
    surface.view_init(elev=35, azim=-60)
    surface.set_axis_off()
    surface.set_title("boundary (P2 patches)")

    bary, subs = lattice(6)
    faces = tet_faces(tets)
    spans = vertices[faces[:, :3], 1]
    faces = faces[(spans.min(1) < y + 0.05) & (spans.max(1) > y - 0.05)]
    inner = cut_segments(evaluate(vertices[faces], bary), subs, y)
    boundary = cut_segments(evaluate(vertices[triangles], bary), subs, y)
    for position, box in ((2, None), (3, detail)):
        axes = figure.add_subplot(1, 3, position)
        axes.add_collection(LineCollection(inner, colors="0.3", linewidths=0.3 if box is None else 0.6))
        axes.add_collection(LineCollection(boundary, colors="tab:red", linewidths=0.8 if box is None else 1.6))
        axes.set_aspect("equal")
        if box is None:
            axes.set_xlim(-0.02, 1.02), axes.set_ylim(-0.02, 0.42)
            axes.add_patch(plt.Rectangle((detail[0], detail[2]), detail[1] - detail[0], detail[3] - detail[2], fill=False, ls="--"))
            axes.set_title(f"cut y = {y} (curved edges sampled)")
        else:
            axes.set_xlim(box[0], box[1]), axes.set_ylim(box[2], box[3])
            axes.set_title("detail: spherical pocket, floor fillet")
        axes.set_xlabel("x"), axes.set_ylabel("z")
    figure.tight_layout()
    figure.savefig(sys.argv[2], dpi=90)


if __name__ == "__main__":
    main()
