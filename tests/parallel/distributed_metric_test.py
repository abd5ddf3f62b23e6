#!/usr/bin/python3
"""`mpirun -np N hocav metric MESH SOURCE -o M.solb` (docs/distributed.md §Reading in pieces):
every process reads its piece of the mesh file, computes the metric of its run of the file's
vertices and writes it in place. On a cube, a layered shell (a text .mesh) and a 2D annulus, and
gmsh's unstructured shell and annulus when hocav has gmsh, with 2, 3 and 4 processes
(oversubscribed): --implied, --input (a metric file's runs) and --analytic write the serial
command's file byte for byte, with the same printed complexity; --gradation (after --surface, and
after --implied) grades across the pieces to a fixed point of the serial grading, at least as fine
as the metric it grades; the Lp metric of a field's Hessian (--hessian, a field file each process
reads its run of, or an analytic field): the serial file's metrics to round-off, on a small mesh
whose corners need the 3-ring too; --surface on the cube with two materials and with a baffle: the
serial file to round-off. Refused under
mpirun, with exit 2, a one-line error and no output: interpolation (--from), a .sol output, an input that is no Gamma mesh, a field file of
another mesh, and a mesh whose Hessians no 3-ring fits (as the serial command refuses it).

Usage: /usr/bin/python3 distributed_metric_test.py <path-to-hocav>
Exits 77 (skipped) when hocav was built without MPI.
"""
import os
import re
import subprocess
import sys

from mpi_test_support import distributed_test, pieces_cases, refused, run, same_bytes, with_materials, write_field


def complexity(output):
    return re.search(r"complexity (\S+)", output).group(1)


def metric_entries(hocav, work, mesh, solb):
    run([hocav, "metric", mesh, "--input", solb, "-o", "entries.sol"], work)
    words = open(os.path.join(work, "entries.sol")).read().split()
    start = words.index("SolAtVertices")
    return [float(w) for w in words[start + 4:words.index("End")]]


def check_near_serial(hocav, mpirun, work, mesh, source):
    """The metric from pieces against the serial file: the same to round-off, and its printed
    complexity (the Hessian's Lp metric sums its complexity's integral over the processes; the
    surface metric's normals come from facets turned by the pieces, where the serial metric negates
    them)."""
    command = ["metric", mesh] + source
    serial = run([hocav] + command + ["-o", "serial.solb"], work)
    expected = metric_entries(hocav, work, mesh, "serial.solb")
    scale = max(abs(e) for e in expected)
    for processes in (2, 3, 4):
        pieces = run(mpirun + ["-np", str(processes), hocav] + command + ["-o", "pieces.solb"], work)
        got = metric_entries(hocav, work, mesh, "pieces.solb")
        worst = max(abs(g - e) for g, e in zip(got, expected)) / scale
        assert len(got) == len(expected) and worst < 1e-12, f"{mesh} {source} on {processes} processes: {worst} off the serial file"
        assert abs(float(complexity(pieces)) - float(complexity(serial))) < 1e-9 * float(complexity(serial)), \
            f"{mesh} {source}: {complexity(pieces)} vs {complexity(serial)}"
        assert f"read in {processes} pieces" in pieces, pieces
        os.remove(os.path.join(work, "pieces.solb"))


def check_same_file(hocav, mpirun, work, mesh, source):
    """The serial command's file byte for byte, and its complexity."""
    serial = run([hocav, "metric", mesh] + source + ["-o", "serial.solb"], work)
    for processes in (2, 3, 4):
        pieces = run(mpirun + ["-np", str(processes), hocav, "metric", mesh] + source + ["-o", "pieces.solb"], work)
        assert same_bytes(work, "serial.solb", "pieces.solb"), f"{mesh} {source} on {processes} processes: not the serial file"
        assert complexity(pieces) == complexity(serial), f"{mesh} {source}: complexity {complexity(pieces)} vs {complexity(serial)}"
        assert f"read in {processes} pieces" in pieces, pieces
        os.remove(os.path.join(work, "pieces.solb"))


def check_graded(hocav, mpirun, work, mesh, source, growth):
    """--gradation across the pieces: a fixed point of the serial grading (which, given the pieces'
    file, changes no byte of it), and at least as fine as the metric it grades (its complexity). Not the
    serial file: the grading's fixed point depends on the order it meets the edges (renumbering the
    2D layered annulus's vertices moves the serial one's complexity from 3,053 to 4,082-4,095 with
    --implied --gradation 1.2), so its complexity is printed beside the serial one's, not compared."""
    given = run([hocav, "metric", mesh] + source + (["--gradation", "1e9"] if "--surface" in source else []) + ["-o", "given.solb"], work)
    graded = source + ["--gradation", growth]
    serial = run([hocav, "metric", mesh] + graded + ["-o", "serial.solb"], work)
    for processes in (2, 3):
        pieces = run(mpirun + ["-np", str(processes), hocav, "metric", mesh] + graded + ["-o", "pieces.solb"], work)
        run([hocav, "metric", mesh, "--input", "pieces.solb", "--gradation", growth, "-o", "regraded.solb"], work)
        assert same_bytes(work, "pieces.solb", "regraded.solb"), f"{mesh} {graded} on {processes} processes: not graded"
        print(f"{mesh} {graded} on {processes} processes: complexity {complexity(pieces)} (serial {complexity(serial)}, "
              f"ungraded {complexity(given)})")
        assert float(complexity(pieces)) >= float(complexity(given)), f"{mesh} {graded}: {complexity(pieces)} vs {complexity(given)}"
        os.remove(os.path.join(work, "pieces.solb"))


def check(hocav, mpirun, work):
    for mesh, generate in pieces_cases():
        run([hocav, "generate"] + generate + ["-o", mesh], work)
        check_same_file(hocav, mpirun, work, mesh, ["--implied"])
        run([hocav, "metric", mesh, "--implied", "-o", "given.solb"], work)
        check_same_file(hocav, mpirun, work, mesh, ["--input", "given.solb"])
        check_same_file(hocav, mpirun, work, mesh, ["--analytic", "uniform", "--h", "0.05"])
        check_graded(hocav, mpirun, work, mesh, ["--surface", "0.02,0.1"], "1.5")
        check_graded(hocav, mpirun, work, mesh, ["--implied"], "1.2")
        write_field(work, mesh, hocav, "u.sol")
        check_near_serial(hocav, mpirun, work, mesh, ["--hessian", "u.sol", "--complexity", "3000"])
        check_near_serial(hocav, mpirun, work, mesh, ["--hessian", "analytic:tanh-shock", "--complexity", "3000"])
    refused(mpirun, hocav, work, ["metric", "cube.meshb", "--from", "cube.meshb", "--from-metric", "given.solb", "-o", "m.solb"], "m.solb",
            "does not interpolate")
    run([hocav, "convert", "cube.meshb", "cube.mesh"], work)
    # Facets inside the domain, a material interface and a baffle, their facets oriented across the
    # pieces as the serial metric takes their normals (no gradation: 1e9).
    for baffle in (False, True):
        with_materials(work, "cube.mesh", "materials.mesh", baffle=baffle)
        check_near_serial(hocav, mpirun, work, "materials.mesh", ["--surface", "0.02,0.1", "--gradation", "1e9"])
    # Two strips joined at a corner, whose corners only the 3-ring fits (as
    # HessianRecovery.GrowsTheStencilToTheThirdRing), each piece one triangle on 4 processes.
    cross = ["0 0 0", "1 0 0", "2 0 0", "0 1 0", "0 2 0", "2 2 0"]
    triangles = ["1 2 4 1", "2 3 4 1", "4 3 5 1", "3 6 5 1"]
    with open(os.path.join(work, "cross.mesh"), "w") as file:
        file.write("\n".join(["MeshVersionFormatted 2", "Dimension 2", "Vertices", "6"] + cross + ["Triangles", "4"] + triangles + ["End", ""]))
    write_field(work, "cross.mesh", hocav, "cross.sol")
    check_near_serial(hocav, mpirun, work, "cross.mesh", ["--hessian", "cross.sol", "--complexity", "3000"])
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
    refused(mpirun, hocav, work, ["metric", "cube.meshb", "--implied", "-o", "m.sol"], "m.sol", "written as .solb")
    run([hocav, "convert", "cube.meshb", "cube.msh"], work)
    refused(mpirun, hocav, work, ["metric", "cube.msh", "--implied", "-o", "m.solb"], "m.solb", "reads Gamma meshes")


if __name__ == "__main__":
    sys.exit(distributed_test(check))
