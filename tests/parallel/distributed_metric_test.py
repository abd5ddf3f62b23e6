#!/usr/bin/python3
"""`mpirun -np N hocav metric MESH --implied -o M.solb` (docs/distributed.md §Reading in pieces):
every process reads its piece of the mesh file, computes the implied metric of its run of the file's
vertices and writes it in place. On a cube, a layered shell (a text .mesh) and a 2D annulus, and
gmsh's unstructured shell and annulus when hocav has gmsh, with 2, 3 and 4 processes (oversubscribed), the file must be the serial command's byte
for byte, and the printed complexity the same. Refused under mpirun, with exit 2, a one-line error
and no output: another metric source, --gradation, a .sol output, an input that is no Gamma mesh. The
Lp metric of a field's Hessian (--hessian, a field file each process reads its run of, or an
analytic field) on the same meshes: the serial file's metrics to round-off; a field file of another
mesh refused, and a mesh whose Hessians no 3-ring fits, as the serial command refuses it.

Usage: /usr/bin/python3 distributed_metric_test.py <path-to-hocav>
Exits 77 (skipped) when hocav was built without MPI.
"""
import os
import re
import subprocess
import sys

from mpi_test_support import distributed_test, pieces_cases, refused, run, same_bytes, write_field


def complexity(output):
    return re.search(r"complexity (\S+)", output).group(1)


def metric_entries(hocav, work, mesh, solb):
    run([hocav, "metric", mesh, "--input", solb, "-o", "entries.sol"], work)
    words = open(os.path.join(work, "entries.sol")).read().split()
    start = words.index("SolAtVertices")
    return [float(w) for w in words[start + 4:words.index("End")]]


def check_hessian(hocav, mpirun, work, mesh, source):
    """The Hessian's Lp metric from pieces against the serial file: the same to round-off (the
    complexity's integral summed over the processes), and its printed complexity."""
    command = ["metric", mesh, "--hessian", source, "--complexity", "3000"]
    serial = run([hocav] + command + ["-o", "serial.solb"], work)
    expected = metric_entries(hocav, work, mesh, "serial.solb")
    scale = max(abs(e) for e in expected)
    for processes in (2, 3, 4):
        pieces = run(mpirun + ["-np", str(processes), hocav] + command + ["-o", "pieces.solb"], work)
        got = metric_entries(hocav, work, mesh, "pieces.solb")
        worst = max(abs(g - e) for g, e in zip(got, expected)) / scale
        assert len(got) == len(expected) and worst < 1e-12, f"{mesh} --hessian {source} on {processes} processes: {worst} off the serial file"
        assert abs(float(complexity(pieces)) - float(complexity(serial))) < 1e-9 * 3000, f"{mesh}: {complexity(pieces)} vs {complexity(serial)}"
        assert f"read in {processes} pieces" in pieces, pieces
        os.remove(os.path.join(work, "pieces.solb"))


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
        write_field(work, mesh, hocav, "u.sol")
        check_hessian(hocav, mpirun, work, mesh, "u.sol")
        check_hessian(hocav, mpirun, work, mesh, "analytic:tanh-shock")
    refused(mpirun, hocav, work, ["metric", "cube.meshb", "--analytic", "linear", "-o", "m.solb"], "m.solb", "--implied or --hessian only")
    run([hocav, "generate", "cube", "--h", "0.25", "-o", "coarse.meshb"], work)
    write_field(work, "coarse.meshb", hocav, "coarse.sol")
    refused(mpirun, hocav, work, ["metric", "cube.meshb", "--hessian", "coarse.sol", "--complexity", "100", "-o", "m.solb"], "m.solb",
            "coarse.sol: SolAtVertices: 125 values for a mesh of")
    # A coarse layered shell whose wall vertices no 3-ring fits (refused by the serial command too).
    run([hocav, "generate", "cubed-shell-bl-both", "--target-tets", "500", "-o", "thin.meshb"], work)
    write_field(work, "thin.meshb", hocav, "thin.sol")
    unfit = "within 3 edges do not determine a quadratic"
    serial = subprocess.run([hocav, "metric", "thin.meshb", "--hessian", "thin.sol", "--complexity", "100", "-o", "m.solb"], cwd=work,
                            capture_output=True, text=True, check=False)
    assert serial.returncode == 2 and unfit in serial.stderr, serial.stderr
    refused(mpirun, hocav, work, ["metric", "thin.meshb", "--hessian", "thin.sol", "--complexity", "100", "-o", "m.solb"], "m.solb", unfit)
    refused(mpirun, hocav, work, ["metric", "cube.meshb", "--implied", "--gradation", "1.5", "-o", "m.solb"], "m.solb", "without --gradation")
    refused(mpirun, hocav, work, ["metric", "cube.meshb", "--implied", "-o", "m.sol"], "m.sol", "written as .solb")
    run([hocav, "convert", "cube.meshb", "cube.msh"], work)
    refused(mpirun, hocav, work, ["metric", "cube.msh", "--implied", "-o", "m.solb"], "m.solb", "reads Gamma meshes")


if __name__ == "__main__":
    sys.exit(distributed_test(check))
