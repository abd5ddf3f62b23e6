"""`hocav adapt` (the P1 loop, then curving) against `hocav adapt --curved` (the same, then curved
passes) on the same inputs, one run each (docs/benchmarks.md §Curved adaptation). Figures from each
run's --report: the share of edges unit in their curved length and the curved mean ratio (min,
mean; docs/curving.md §Curved quality), the min/avg normalized Jacobian, the average and largest
gain (the relative shortening of the edges' Riemannian length by their curving, Table 1's), corrections and cavities
rejected by the curving (the reinsertion's and the curved passes'), the curved passes' operations (collapses, splits, swaps, moves, and the passes;
the operations made on the boundary),
the command's wall time; and, for the cases bounded by circles or spheres centred at the origin,
the distance of the output's boundary from the true circle or sphere (its P2 nodes' max and mean, and
the mean over the curved boundary's length or area).

Usage (from the repository root, with Debian's Python):
  /usr/bin/python3 bench/curved_adapt_compare.py build/release/hocav [--threads N] [--cases NAME,...]
"""
import argparse
import json
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import meshio
import numpy as np

# name: (dimension, setup commands writing start.meshb (and start.solb), adapt's metric arguments,
#        radii of the true boundary or None)
CASES = {
    "annulus": (2, [["generate", "annulus", "--h", "0.05", "-o", "start.meshb"],
                    ["metric", "start.meshb", "--surface", "0.005,0.05", "--gradation", "1.5", "-o", "start.solb"]],
                ["--metric", "start.solb"], (0.5, 1.0)),
    "shear-circle": (2, [["generate", "annulus", "--h", "0.05", "-o", "start.meshb"]],
                     ["--analytic", "shear-circle", "--hmin", "0.01"], (0.5, 1.0)),
    "sphere-shell": (3, [["generate", "sphere-shell", "--h", "0.2", "-o", "start.meshb"],
                         ["metric", "start.meshb", "--surface", "0.02,0.2", "--gradation", "1.5", "-o", "start.solb"]],
                     ["--metric", "start.solb"], (0.5, 1.0)),
    "cubed-shell-bl-inner": (3, [["generate", "cubed-shell-bl-inner", "--target-tets", "5000", "-o", "start.meshb"],
                                 ["metric", "start.meshb", "--implied", "-o", "start.solb"]],
                             ["--metric", "start.solb"], (0.5, 1.0)),
    "cubed-shell-bl-both": (3, [["generate", "cubed-shell-bl-both", "--target-tets", "5000", "-o", "start.meshb"],
                                ["metric", "start.meshb", "--implied", "-o", "start.solb"]],
                            ["--metric", "start.solb"], (0.5, 1.0)),
    # Issue 13's wall with its sag bounded by half the first layer (docs/adaptation.md §The Hausdorff bound).
    "cubed-shell-bl-inner-relative": (3, [["generate", "cubed-shell-bl-inner", "--target-tets", "5000", "-o", "start.meshb"],
                                          ["metric", "start.meshb", "--implied", "-o", "start.solb"]],
                                      ["--metric", "start.solb", "--hausd-relative", "0.5"], (0.5, 1.0)),
    "ugawg-linear": (3, [["generate", "cube", "--h", "0.1", "-o", "start.meshb"]], ["--analytic", "linear"], None),
}


def run(hocav, args, folder):
    subprocess.run([hocav, *args], cwd=folder, check=True, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)


def boundary_faces(path, dimension):
    """The output's points and its boundary P2 faces (faces of one element): corner and node indices,
    in the order of the P2 map below (corners, then the nodes of (0,1), (1,2), (2,0); in 2D the ends,
    then the node)."""
    mesh = meshio.read(path)
    cells = mesh.cells[0].data
    if dimension == 2:  # VTK quadratic triangle: corners 0-2, nodes of (0,1), (1,2), (2,0)
        faces = [((0, 1), (3,)), ((1, 2), (4,)), ((2, 0), (5,))]
    else:  # VTK quadratic tetrahedron: nodes of (0,1), (1,2), (0,2), (0,3), (1,3), (2,3) at 4-9
        faces = [((0, 1, 2), (4, 5, 6)), ((0, 1, 3), (4, 8, 7)), ((1, 2, 3), (5, 9, 8)), ((0, 2, 3), (6, 9, 7))]
    found = {}
    for cell in cells:
        for corners, nodes in faces:
            found.setdefault(tuple(sorted(cell[list(corners)])), []).append(cell[list(corners) + list(nodes)])
    return mesh.points[:, :dimension], np.array([f[0] for f in found.values() if len(f) == 1])


def sphere_distance(points, radii):
    r = np.linalg.norm(points, axis=-1)
    return np.min(np.abs(r[..., None] - np.array(radii)), axis=-1)


def p2_face_samples(points, faces, dimension):
    """Points and weights (length or area, from the P2 map's Jacobian) of a Gauss rule on each face:
    5 points on a segment, 7 (degree 5) on a triangle."""
    if dimension == 2:
        t, w = np.polynomial.legendre.leggauss(5)
        t, w = (t + 1) / 2, w / 2
        shapes = np.stack([(1 - t) * (1 - 2 * t), t * (2 * t - 1), 4 * t * (1 - t)], axis=1)
        derivatives = np.stack([4 * t - 3, 4 * t - 1, 4 - 8 * t], axis=1)[:, :, None]
    else:
        a, b, c, d = 0.059715871789770, 0.470142064105115, 0.797426985353087, 0.101286507323456
        bary = np.array([[1 / 3] * 3, [a, b, b], [b, a, b], [b, b, a], [c, d, d], [d, c, d], [d, d, c]])
        w = np.array([0.225] + [0.132394152788506] * 3 + [0.125939180544827] * 3) / 2
        l0, l1, l2 = bary.T
        shapes = np.stack([l0 * (2 * l0 - 1), l1 * (2 * l1 - 1), l2 * (2 * l2 - 1), 4 * l0 * l1, 4 * l1 * l2, 4 * l2 * l0], axis=1)
        # Derivatives along u = l1, v = l2 (l0 = 1 - u - v).
        du = np.stack([1 - 4 * l0, 4 * l1 - 1, 0 * l0, 4 * (l0 - l1), 4 * l2, -4 * l2], axis=1)
        dv = np.stack([1 - 4 * l0, 0 * l0, 4 * l2 - 1, -4 * l1, 4 * l1, 4 * (l0 - l2)], axis=1)
        derivatives = np.stack([du, dv], axis=2)
    corners = points[faces]                               # faces x nodes x dimension
    samples = np.einsum("qn,fnd->fqd", shapes, corners)
    jacobian = np.einsum("qnk,fnd->fqdk", derivatives, corners)
    if dimension == 2:
        measure = np.linalg.norm(jacobian[..., 0], axis=-1)
    else:
        measure = np.linalg.norm(np.cross(jacobian[..., 0], jacobian[..., 1]), axis=-1)
    return samples, measure * w


def boundary_errors(path, dimension, radii):
    """The distance | |x| - R | to the true circles or spheres (R the nearer radius): the largest and
    the mean over the boundary faces' P2 nodes, and the mean over the curved boundary itself (its
    length or area; the node mean weighs a region by how many nodes it holds, so a coarser boundary
    moves it even where no point of the surface moved)."""
    points, faces = boundary_faces(path, dimension)
    nodes = np.unique(faces[:, dimension:])
    node_error = sphere_distance(points[nodes], radii)
    samples, weights = p2_face_samples(points, faces, dimension)
    surface_mean = np.sum(sphere_distance(samples, radii) * weights) / np.sum(weights)
    return node_error.max(), node_error.mean(), surface_mean


def measure(hocav, case, curved, threads, folder):
    dimension, _, metric, radii = CASES[case]
    output = "curved.meshb" if curved else "plain.meshb"
    report = output.replace(".meshb", ".json")
    start = time.perf_counter()
    run(hocav, ["adapt", "start.meshb", *metric, "-o", output, "--report", report, "--threads", str(threads), "-q",
                *(["--curved"] if curved else [])], folder)
    seconds = time.perf_counter() - start
    r = json.loads((folder / report).read_text())
    curving, measures = r["curving"], r["curved_measures"]
    passes = r.get("curved_passes")
    row = {
        "case": case, "run": "adapt --curved" if curved else "adapt", "elements": r["output_elements"],
        "unit": measures["unit_share"], "q_mean": measures["quality_mean"], "q_min": measures["quality_min"],
        "j_min": curving["normalized_jacobian"]["min"], "j_avg": curving["normalized_jacobian"]["avg"],
        "gain_avg": curving["average_gain"], "gain_max": curving["max_gain"],
        "corrections": curving["cavities"]["corrections"], "rejected": curving["cavities"]["rejected_curving"],
        "seconds": seconds, "boundary": None,
        "curved_ops": None,
    }
    if passes:
        row["corrections"] += passes["corrections"]
        row["rejected"] += passes["rejected_by_curving"]
        row["curved_ops"] = (*(sum(p[op]["done"] for p in passes["passes"]) for op in ("collapses", "splits", "swaps", "moves")),
                             len(passes["passes"]),
                             sum(p[op].get("boundary_done", 0) for p in passes["passes"] for op in ("collapses", "splits", "swaps", "moves")))
    if radii:
        run(hocav, ["convert", output, output.replace(".meshb", ".vtu")], folder)
        row["boundary"] = boundary_errors(folder / output.replace(".meshb", ".vtu"), dimension, radii)
    return row


def markdown(rows):
    lines = ["| case | run | elements | unit (curved length) | curved q mean / min | norm. Jacobian min / avg | gain avg / max | boundary error: nodes max / mean, surface mean "
             "| corrections | rejected | curved collapses / splits / swaps / moves (passes; on the boundary) | time s |",
             "|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for r in rows:
        boundary = " / ".join(f"{e:.2e}" for e in r["boundary"]) if r["boundary"] else "n/a"
        ops = " / ".join(f"{n:,}" for n in r["curved_ops"][:4]) + f" ({r['curved_ops'][4]}; {r['curved_ops'][5]:,})" if r["curved_ops"] else ""
        lines.append(f"| {r['case']} | {r['run']} | {r['elements']:,} | {100 * r['unit']:.1f}% | {r['q_mean']:.3f} / {r['q_min']:.3f} "
                     f"| {r['j_min']:.4f} / {r['j_avg']:.3f} | {100 * r['gain_avg']:.2f}% / {100 * r['gain_max']:.1f}% | {boundary} | {r['corrections']:,} | {r['rejected']:,} | {ops} "
                     f"| {r['seconds']:.1f} |")
    return "\n".join(lines)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("hocav")
    parser.add_argument("--threads", type=int, default=2)
    parser.add_argument("--cases", default=",".join(CASES))
    args = parser.parse_args()
    hocav = str(Path(args.hocav).resolve())
    rows = []
    for case in args.cases.split(","):
        with tempfile.TemporaryDirectory() as work:
            folder = Path(work)
            for command in CASES[case][1]:
                run(hocav, command, folder)
            for curved in (False, True):
                rows.append(measure(hocav, case, curved, args.threads, folder))
                print(markdown(rows[-1:]).splitlines()[-1], file=sys.stderr)
    print(markdown(rows))


main()
