#!/usr/bin/python3
"""`mpirun -np N hocav metric MESH --implied -o M.solb` (docs/distributed.md §Reading in pieces):
every process reads its piece of the mesh file, computes the implied metric of its run of the file's
vertices and writes it in place. On a cube, a layered shell (a text .mesh) and a 2D annulus, and
gmsh's unstructured shell and annulus when hocav has gmsh, with 2, 3 and 4 processes (oversubscribed), the file must be the serial command's byte
for byte, and the printed complexity the same. Refused under mpirun, with exit 2, a one-line error
and no output: another metric source, --gradation, a .sol output, an input that is no Gamma mesh.

Usage: /usr/bin/python3 distributed_metric_test.py <path-to-hocav>
Exits 77 (skipped) when hocav was built without MPI.
"""
import os
import re
import subprocess
import sys

from mpi_test_support import distributed_test, run, same_bytes

CASES = [
    ("cube.meshb", ["cube", "--h", "0.15"]),
    ("layers.mesh", ["cubed-shell-bl-inner", "--target-tets", "6000"]),
    ("annulus.meshb", ["polar-annulus-bl-inner", "--target-triangles", "2000"]),
]
# Unstructured, in gmsh's order of elements (when hocav has gmsh).
GMSH_CASES = [("shell.mesh", ["sphere-shell", "--h", "0.15"]), ("gmsh-annulus.meshb", ["annulus", "--h", "0.08"])]


def complexity(output):
    return re.search(r"complexity (\S+)", output).group(1)


def refused(mpirun, hocav, work, args, output, words):
    result = subprocess.run(mpirun + ["-np", "2", hocav, "metric"] + args, cwd=work, capture_output=True, text=True, check=False)
    assert result.returncode == 2, f"{args}: exit {result.returncode}"
    assert words in result.stderr, f"{args}: {result.stderr}"
    assert not os.path.exists(os.path.join(work, output)), f"{args}: {output} was written"


def check(hocav, mpirun, work):
    with_gmsh = os.environ.get("HOCAV_WITH_GMSH", "0") in ("1", "ON", "TRUE")
    for mesh, generate in CASES + (GMSH_CASES if with_gmsh else []):
        run([hocav, "generate"] + generate + ["-o", mesh], work)
        serial = run([hocav, "metric", mesh, "--implied", "-o", "serial.solb"], work)
        for processes in (2, 3, 4):
            pieces = run(mpirun + ["-np", str(processes), hocav, "metric", mesh, "--implied", "-o", "pieces.solb"], work)
            assert same_bytes(work, "serial.solb", "pieces.solb"), f"{mesh} on {processes} processes: not the serial file"
            assert complexity(pieces) == complexity(serial), f"{mesh}: complexity {complexity(pieces)} vs {complexity(serial)}"
            assert f"read in {processes} pieces" in pieces, pieces
            os.remove(os.path.join(work, "pieces.solb"))
    refused(mpirun, hocav, work, ["cube.meshb", "--analytic", "linear", "-o", "m.solb"], "m.solb", "--implied only")
    refused(mpirun, hocav, work, ["cube.meshb", "--implied", "--gradation", "1.5", "-o", "m.solb"], "m.solb", "without --gradation")
    refused(mpirun, hocav, work, ["cube.meshb", "--implied", "-o", "m.sol"], "m.sol", "written as .solb")
    run([hocav, "convert", "cube.meshb", "cube.msh"], work)
    refused(mpirun, hocav, work, ["cube.msh", "--implied", "-o", "m.solb"], "m.solb", "reads Gamma meshes")


if __name__ == "__main__":
    sys.exit(distributed_test(check))
