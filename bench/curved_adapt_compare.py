"""`hocav adapt` (the P1 loop, then curving) against `hocav adapt --curved` (the same, then curved
passes) on the same inputs, one run each (docs/benchmarks.md §Curved adaptation). Figures from each
run's --report: the share of edges unit in their curved length and the curved mean ratio (min,
mean; docs/curving.md §Curved quality), the min/avg normalized Jacobian, corrections and cavities
rejected by the curving (the reinsertion's and the curved passes'), the curved passes' operations (collapses, splits, swaps, moves, and the passes;
the operations made on the boundary),
the command's wall time; and, for the cases bounded by circles or spheres centred at the origin,
the distance of the output's boundary P2 nodes from the true circle or sphere (max and mean).

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


def boundary_node_errors(path, dimension, radii):
    """| |x| - R | of the P2 nodes of the boundary faces (faces of one element), R the nearer radius."""
    mesh = meshio.read(path)
    cells = mesh.cells[0].data
    if dimension == 2:  # VTK quadratic triangle: corners 0-2, nodes of (0,1), (1,2), (2,0)
        faces = [((0, 1), 3), ((1, 2), 4), ((2, 0), 5)]
    else:  # VTK quadratic tetrahedron: nodes of (0,1), (1,2), (0,2), (0,3), (1,3), (2,3) at 4-9
        faces = [((0, 1, 2), (4, 5, 6)), ((0, 1, 3), (4, 7, 8)), ((1, 2, 3), (5, 8, 9)), ((0, 2, 3), (6, 7, 9))]
    count = {}
    for cell in cells:
        for corners, nodes in faces:
            key = tuple(sorted(cell[list(corners)]))
            count.setdefault(key, []).append(cell[list(np.atleast_1d(nodes))])
    nodes = np.unique(np.concatenate([found[0] for found in count.values() if len(found) == 1]))
    r = np.linalg.norm(mesh.points[nodes, :dimension], axis=1)
    error = np.min(np.abs(r[:, None] - np.array(radii)[None, :]), axis=1)
    return error.max(), error.mean()


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
        row["boundary"] = boundary_node_errors(folder / output.replace(".meshb", ".vtu"), dimension, radii)
    return row


def markdown(rows):
    lines = ["| case | run | elements | unit (curved length) | curved q mean / min | norm. Jacobian min / avg | boundary error max / mean "
             "| corrections | rejected | curved collapses / splits / swaps / moves (passes; on the boundary) | time s |",
             "|---|---|---|---|---|---|---|---|---|---|---|"]
    for r in rows:
        boundary = f"{r['boundary'][0]:.2e} / {r['boundary'][1]:.2e}" if r["boundary"] else "n/a"
        ops = " / ".join(f"{n:,}" for n in r["curved_ops"][:4]) + f" ({r['curved_ops'][4]}; {r['curved_ops'][5]:,})" if r["curved_ops"] else ""
        lines.append(f"| {r['case']} | {r['run']} | {r['elements']:,} | {100 * r['unit']:.1f}% | {r['q_mean']:.3f} / {r['q_min']:.3f} "
                     f"| {r['j_min']:.4f} / {r['j_avg']:.3f} | {boundary} | {r['corrections']:,} | {r['rejected']:,} | {ops} "
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
