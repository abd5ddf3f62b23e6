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
import sys

from mpi_test_support import distributed_test, pieces_cases, refused, run, same_bytes


def complexity(output):
    return re.search(r"complexity (\S+)", output).group(1)


def check(hocav, mpirun, work):
    for mesh, generate in pieces_cases():
        run([hocav, "generate"] + generate + ["-o", mesh], work)
        serial = run([hocav, "metric", mesh, "--implied", "-o", "serial.solb"], work)
        for processes in (2, 3, 4):
            pieces = run(mpirun + ["-np", str(processes), hocav, "metric", mesh, "--implied", "-o", "pieces.solb"], work)
            assert same_bytes(work, "serial.solb", "pieces.solb"), f"{mesh} on {processes} processes: not the serial file"
            assert complexity(pieces) == complexity(serial), f"{mesh}: complexity {complexity(pieces)} vs {complexity(serial)}"
            assert f"read in {processes} pieces" in pieces, pieces
            os.remove(os.path.join(work, "pieces.solb"))
    refused(mpirun, hocav, work, ["metric", "cube.meshb", "--analytic", "linear", "-o", "m.solb"], "m.solb", "--implied only")
    refused(mpirun, hocav, work, ["metric", "cube.meshb", "--implied", "--gradation", "1.5", "-o", "m.solb"], "m.solb", "without --gradation")
    refused(mpirun, hocav, work, ["metric", "cube.meshb", "--implied", "-o", "m.sol"], "m.sol", "written as .solb")
    run([hocav, "convert", "cube.meshb", "cube.msh"], work)
    refused(mpirun, hocav, work, ["metric", "cube.msh", "--implied", "-o", "m.solb"], "m.solb", "reads Gamma meshes")


if __name__ == "__main__":
    sys.exit(distributed_test(check))
