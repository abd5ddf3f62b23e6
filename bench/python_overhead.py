"""The Python module against the command on the same job, and what its array exchange copies
(docs/benchmarks.md, "The Python module"). Run from the repository after a release build:

    /usr/bin/python3 bench/python_overhead.py [--rounds 3] [--triangles 200000] [--threads 2]

Job: curve a generated polar annulus in the uniform analytic metric, read from and written to .meshb.
Prints the best wall time of each way over the rounds, alternating them."""
import argparse
import os
import subprocess
import sys
import tempfile
import time

import numpy as np

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
BUILD = os.path.join(ROOT, "build", "release")
sys.path.insert(0, os.path.join(BUILD, "python"))
import hocav  # noqa: E402

HOCAV = os.path.join(BUILD, "hocav")
SCRIPT = """import sys, hocav
mesh = hocav.read(sys.argv[1])
curved, report = hocav.curve(mesh, hocav.read_metric(sys.argv[2], mesh), threads=int(sys.argv[4]))
hocav.write(sys.argv[3], curved)
"""


def wall(command, env=None):
    start = time.perf_counter()
    subprocess.run(command, check=True, capture_output=True, env=env)
    return time.perf_counter() - start


def best_of(rounds, function):
    return min(function() for _ in range(rounds))


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--rounds", type=int, default=3)
    parser.add_argument("--triangles", type=int, default=200000)
    parser.add_argument("--threads", type=int, default=2)
    args = parser.parse_args()
    work = tempfile.mkdtemp()
    mesh_path, metric_path = os.path.join(work, "in.meshb"), os.path.join(work, "in.solb")
    subprocess.run([HOCAV, "generate", "polar-annulus", "--target-triangles", str(args.triangles), "-o", mesh_path], check=True,
                   capture_output=True)
    subprocess.run([HOCAV, "metric", mesh_path, "--analytic", "uniform", "--h", "0.01", "-o", metric_path], check=True,
                   capture_output=True)
    env = dict(os.environ, PYTHONPATH=os.path.join(BUILD, "python"))
    cli, script = [], []
    for _ in range(args.rounds):  # alternated, so that the machine's state weighs on both alike
        cli.append(wall([HOCAV, "curve", mesh_path, "--metric", metric_path, "-o", os.path.join(work, "cli.meshb"),
                         "--threads", str(args.threads), "-q"]))
        script.append(wall([sys.executable, "-c", SCRIPT, mesh_path, metric_path, os.path.join(work, "py.meshb"),
                            str(args.threads)], env))
    same = open(os.path.join(work, "cli.meshb"), "rb").read() == open(os.path.join(work, "py.meshb"), "rb").read()
    start_up = best_of(args.rounds, lambda: wall([sys.executable, "-c", "import hocav"], env))
    print(f"job: curve {args.triangles} triangles, {args.threads} threads; outputs identical: {same}")
    print(f"hocav curve (process):            best {min(cli):.3f} s  (all: {', '.join(f'{t:.3f}' for t in cli)})")
    print(f"python script (process):          best {min(script):.3f} s  (all: {', '.join(f'{t:.3f}' for t in script)})")
    print(f"python3 -c 'import hocav':        best {start_up:.3f} s")

    mesh = hocav.read(mesh_path)
    metric = hocav.read_metric(metric_path, mesh)
    start = time.perf_counter()
    _, report = hocav.curve(mesh, metric, threads=args.threads)
    call = time.perf_counter() - start
    print(f"hocav.curve call: {call:.3f} s, of which the library's curving {report['seconds_without_io']:.3f} s")

    timings = {
        "mesh.points (view)": lambda: mesh.points,
        "Mesh(points, elements, facets) (copy in)": lambda: hocav.Mesh(mesh.points, mesh.elements, mesh.facets),
        "metric array to the library (copy in), via metric_complexity": lambda: hocav.metric_complexity(mesh, metric),
        "mesh.to_meshio() (P1: views)": lambda: mesh.to_meshio(),
    }
    for name, function in timings.items():
        print(f"{name}: {best_of(5, lambda: _timed(function)) * 1e3:.3f} ms")
    print(f"points shares the mesh's storage: {np.shares_memory(mesh.points, mesh.points)}; "
          f"{mesh.points.nbytes + mesh.elements.nbytes + mesh.facets.nbytes} bytes of arrays, "
          f"{metric.nbytes} bytes of metric")


def _timed(function):
    start = time.perf_counter()
    function()
    return time.perf_counter() - start


if __name__ == "__main__":
    main()
