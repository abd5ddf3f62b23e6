#!/usr/bin/python3
"""`mpirun -np N hocav convert IN OUT` (docs/distributed.md §Writing in runs, §A .vtu in runs):
every process reads its piece of a P1 Gamma mesh and writes it back in runs, so that no process
holds the whole mesh.
On a cube, a layered shell (a text .mesh) and a 2D annulus, and gmsh's unstructured shell and
annulus when hocav has gmsh, with 2, 3 and 4 processes (oversubscribed), to .mesh and .meshb: the
output must be the serial command's mesh, every keyword's records in the same order (vertices,
elements, facets, feature lines and tags), and meshio must read it to the same points and cells;
to .msh (§A .msh in runs), the file must be the serial one byte for byte (the facets and lines in
their order), and gmsh must read as many elements as meshio reads in the serial one; to .vtu, meshio must read the serial .vtu's cells (with their refs and
Jacobians). The summary line of a .msh or .vtu gives the serial command's counts (a vertex that
several pieces hold counted once). Refused under mpirun, with exit 2, a one-line error and no output: --metric, --order 2,
an input that is no Gamma mesh, an output of no mesh format.

Usage: /usr/bin/python3 distributed_convert_test.py <path-to-hocav>
Exits 77 (skipped) when hocav was built without MPI.
"""
import contextlib
import io
import os
import sys

import meshio
import numpy

from mpi_test_support import check_vtu_in_runs, distributed_test, keywords, pieces_cases, refused, run, same_bytes

def same_mesh(serial, pieces, what):
    assert list(serial) == list(pieces), f"{what}: keywords {list(pieces)} vs {list(serial)}"
    for keyword in serial:
        assert pieces[keyword] == serial[keyword], f"{what}: not the serial {keyword} in order"


def same_for_meshio(serial, pieces, what):
    with contextlib.redirect_stderr(io.StringIO()):  # its warnings about the tag keywords it skips
        a, b = meshio.read(serial), meshio.read(pieces)
    assert numpy.array_equal(a.points, b.points), f"{what}: meshio reads other points"
    cells_a = {block.type: numpy.sort(block.data, axis=1) for block in a.cells}
    cells_b = {block.type: numpy.sort(block.data, axis=1) for block in b.cells}
    assert cells_a.keys() == cells_b.keys(), f"{what}: meshio reads other cell types"
    for kind in cells_a:
        assert sorted(map(tuple, cells_a[kind])) == sorted(map(tuple, cells_b[kind])), f"{what}: meshio reads other {kind}"


def gmsh_reads(path, elements, what):
    """gmsh (when its Python module is there) reads the .msh with `elements` elements."""
    try:
        import gmsh
    except ImportError:
        return
    gmsh.initialize(["-v", "0"])
    try:
        gmsh.open(path)
        found = sum(len(tags) for tags in gmsh.model.mesh.getElements()[1])
        assert found == elements, f"{what}: gmsh reads {found} elements, not {elements}"
    finally:
        gmsh.finalize()


def check(hocav, mpirun, work):
    for mesh, generate in pieces_cases():
        run([hocav, "generate"] + generate + ["-o", mesh], work)
        run([hocav, "convert", mesh, "serial.mesh"], work)
        serial_summary = run([hocav, "convert", mesh, "serial.msh"], work).split(": ", 1)[1].strip()
        serial = keywords(os.path.join(work, "serial.mesh"))
        for processes in (2, 3, 4):
            for output in ("pieces.mesh", "pieces.meshb"):
                what = f"{mesh} to {output} on {processes} processes"
                printed = run(mpirun + ["-np", str(processes), hocav, "convert", mesh, output], work)
                assert f"(in {processes} pieces)" in printed, printed
                if output.endswith(".meshb"):
                    run([hocav, "convert", output, "pieces-back.mesh"], work)
                    output = "pieces-back.mesh"
                same_mesh(serial, keywords(os.path.join(work, output)), what)
                same_for_meshio(os.path.join(work, "serial.mesh"), os.path.join(work, output), what)
            printed = run(mpirun + ["-np", str(processes), hocav, "convert", mesh, "pieces.msh"], work)
            assert f": {serial_summary} (in {processes} pieces)" in printed, f"{printed} (serially: {serial_summary})"
            assert same_bytes(work, "serial.msh", "pieces.msh"), f"{mesh} to .msh on {processes} processes: not the serial file"
            gmsh_reads(os.path.join(work, "pieces.msh"), sum(len(block.data) for block in meshio.read(os.path.join(work, "serial.msh")).cells),
                       f"{mesh} to .msh on {processes} processes")
            printed = run(mpirun + ["-np", str(processes), hocav, "convert", mesh, "pieces.vtu"], work)
            assert f": {serial_summary} (in {processes} pieces" in printed, f"{printed} (serially: {serial_summary})"
            check_vtu_in_runs(hocav, work, "pieces.vtu", mesh, f"{mesh} to .vtu on {processes} processes", metric=False)
    refused(mpirun, hocav, work, ["convert", "cube.meshb", "out.mesh", "--metric", "m.solb"], "out.mesh", "no --metric")
    refused(mpirun, hocav, work, ["convert", "cube.meshb", "out.mesh", "--order", "2"], "out.mesh", "no --order 2")
    refused(mpirun, hocav, work, ["convert", "cube.meshb", "out.stl"], "out.stl", "writes Gamma meshes (.mesh, .meshb), a .msh or a .vtu")
    run([hocav, "convert", "cube.meshb", "cube.msh"], work)
    refused(mpirun, hocav, work, ["convert", "cube.msh", "out.mesh"], "out.mesh", "reads Gamma meshes")


if __name__ == "__main__":
    sys.exit(distributed_test(check))
