"""The Hausdorff bound side by side with mmg (docs/adaptation.md §The Hausdorff bound): a coarse sphere
shell (and annulus) adapted to a uniform size it is already close to, with a bound D on the distance
from the boundary to the geometry: `hocav adapt --hausd D` and `mmg3d_O3 -hausd D` (mmg2d_O3 in 2D),
both with the gradation 1.3 (mmg's default). Every output is measured by the same code: the distance
of each boundary facet's centroid (3D) or middle (2D) from the true circle or sphere (radius 0.5 or
1, the nearer), max and mean, in units of D; the boundary facet and element counts; the wall time.
(The geometry each tool projects onto is its own model of the coarse input's boundary, whose own
distance to the true spheres adds to these.)

Usage (from the repository root, with Debian's Python, which has meshio):
  /usr/bin/python3 bench/hausdorff_compare.py [--mmg3d PATH] [--mmg2d PATH] [--hausd D,...]
A tool whose binary is not given or absent is skipped with a message.
"""
import argparse
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import meshio
import numpy as np

HOCAV = Path(__file__).resolve().parent.parent / "build" / "release" / "hocav"
SIZE = 0.25


def run(command, folder):
    start = time.monotonic()
    subprocess.run([str(c) for c in command], cwd=folder, check=True, capture_output=True)
    return time.monotonic() - start


def boundary_distance(path, dimension):
    mesh = meshio.read(path)
    facet = "triangle" if dimension == 3 else "line"
    facets = np.concatenate([c.data for c in mesh.cells if c.type == facet])
    middles = mesh.points[facets][:, :, :dimension].mean(axis=1)
    radii = np.linalg.norm(middles, axis=1)
    distance = np.minimum(abs(radii - 0.5), abs(radii - 1.0))
    elements = sum(len(c.data) for c in mesh.cells if c.type == ("tetra" if dimension == 3 else "triangle"))
    return distance.max(), distance.mean(), len(facets), elements


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--hocav", default=str(HOCAV))
    parser.add_argument("--mmg3d")
    parser.add_argument("--mmg2d")
    parser.add_argument("--hausd", default="0.01,0.002")
    args = parser.parse_args()
    hocav = Path(args.hocav).resolve()
    if not hocav.exists():
        sys.exit(f"no hocav binary at {hocav}: build it first (README)")
    print("| case | D | tool | boundary facets | elements | distance max / mean (× D) | time s |")
    print("|---|---|---|---|---|---|---|")
    for dimension, shape, mmg in ((3, "sphere-shell", args.mmg3d), (2, "annulus", args.mmg2d)):
        if not mmg or not Path(mmg).exists():
            print(f"(mmg for {shape}: no binary given or found; its rows are skipped)", file=sys.stderr)
        with tempfile.TemporaryDirectory() as scratch:
            folder = Path(scratch)
            run([hocav, "generate", shape, "--h", SIZE, "-o", "start.mesh"], folder)
            run([hocav, "metric", "start.mesh", "--analytic", "uniform", "--h", SIZE, "-o", "start.sol"], folder)
            for hausd in [float(d) for d in args.hausd.split(",")]:
                rows = [("hocav", [hocav, "adapt", "start.mesh", "--metric", "start.sol", "-o", "h.mesh", "--order", 1,
                                   "--hausd", hausd, "--hgrad", 1.3, "-q"], "h.mesh")]
                if mmg and Path(mmg).exists():
                    rows.append(("mmg", [Path(mmg).resolve(), "-in", "start.mesh", "-sol", "start.sol", "-out", "m.mesh",
                                         "-hausd", hausd, "-hgrad", 1.3], "m.mesh"))
                for tool, command, output in rows:
                    seconds = run(command, folder)
                    largest, mean, facets, elements = boundary_distance(folder / output, dimension)
                    print(f"| {shape} | {hausd:g} | {tool} | {facets:,} | {elements:,} | "
                          f"{largest / hausd:.2f} / {mean / hausd:.2f} | {seconds:.2f} |")


if __name__ == "__main__":
    main()
