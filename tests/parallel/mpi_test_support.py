"""What the distributed tests share (docs/distributed.md): running hocav and mpirun, `hocav stats`
as a dict, the validity checks, the refs of a mesh, a .vtu written in runs."""
import contextlib
import io
import math
import os
import re
import subprocess
import sys
import tempfile

SKIP = 77


def completed(args, cwd):
    """A command that must succeed."""
    result = subprocess.run(args, cwd=cwd, capture_output=True, text=True, check=False)
    if result.returncode != 0:
        raise AssertionError(f"{' '.join(args)} failed ({result.returncode}):\n{result.stderr}")
    return result


def run(args, cwd):
    return completed(args, cwd).stdout


def mpirun_or_none():
    """The mpirun command line (oversubscribed, root allowed), or None when hocav has no MPI."""
    if os.environ.get("HOCAV_WITH_MPI", "0") not in ("1", "ON", "TRUE"):
        print("skipped: hocav was built without MPI (HOCAV_WITH_MPI off)")
        return None
    os.environ.update(OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    return [os.environ.get("HOCAV_MPIEXEC") or "mpirun", "--oversubscribe"]


def stats(hocav, mesh, cwd):
    """`hocav stats` as a dict of its lines (name -> rest of the line)."""
    lines = run([hocav, "stats", mesh], cwd).splitlines()
    return {line[:22].strip(): line[22:].strip() for line in lines}


def min_normalized_jacobian(figures):
    return float(re.match(r"min (\S+)", figures["normalized Jacobian"]).group(1))


def check_valid(figures, name):
    assert figures["consistency"] == "ok", f"{name}: consistency {figures['consistency']}"
    assert figures["non-positive P1"] == "0" or figures["order"] == "P2", f"{name}: {figures['non-positive P1']} non-positive elements"
    minimum = min_normalized_jacobian(figures)
    assert minimum > 0, f"{name}: normalized Jacobian down to {minimum}"


def check_same_refs(figures, serial, name):
    for key in ("element refs", "facet refs"):
        assert re.findall(r"(\d+) \(", figures[key]) == re.findall(r"(\d+) \(", serial[key]), \
            f"{name}: {key} {figures[key]} vs {serial[key]}"


def refused(mpirun, hocav, work, args, output, words):
    """`mpirun -np 2 hocav ARGS` must fail with exit 2 and `words` in its message, and leave `output` unwritten."""
    result = subprocess.run(mpirun + ["-np", "2", hocav] + args, cwd=work, capture_output=True, text=True, check=False)
    assert result.returncode == 2, f"{args}: exit {result.returncode}"
    assert words in result.stderr, f"{args}: {result.stderr}"
    assert not os.path.exists(os.path.join(work, output)), f"{args}: {output} was written"


def check_vtu_in_runs(hocav, work, vtu, mesh, what, metric=True, jacobians=True):
    """A .vtu that the parts wrote in runs (docs/distributed.md §A .vtu in runs) against `mesh`, the
    run's Gamma output: meshio reads the same cells as in `hocav convert`'s .vtu of it (each by its
    points' coordinates, with its ref and, with `jacobians`, its min normalized Jacobian), at least as
    many points (a vertex of several parts is a point of each), and with `metric` a metric at every
    point."""
    import meshio  # (only here: the other distributed tests run without it)
    import numpy
    run([hocav, "convert", mesh, "expected-of-runs.vtu"], work)
    with contextlib.redirect_stderr(io.StringIO()):
        expected, got = (meshio.read(os.path.join(work, name)) for name in ("expected-of-runs.vtu", vtu))

    def cells(grid):
        (block,) = grid.cells
        values = numpy.round(grid.cell_data["min_normalized_jacobian"][0], 9) if jacobians else [None] * len(block.data)
        return sorted((tuple(grid.points[c].ravel()), int(r), j) for c, r, j in zip(block.data, grid.cell_data["ref"][0], values))

    assert cells(got) == cells(expected), f"{what}: {vtu} holds other cells than {mesh}"
    assert len(got.points) >= len(expected.points), f"{what}: {len(got.points)} points, {mesh} {len(expected.points)}"
    if metric:
        rows = got.point_data["metric"]
        assert rows.shape == (len(got.points), 9) and (rows[:, 0] > 0).all(), f"{what}: no metric at every point of {vtu}"


def same_bytes(work, a, b):
    with open(os.path.join(work, a), "rb") as one, open(os.path.join(work, b), "rb") as other:
        return one.read() == other.read()


# Meshes the tests of reading in pieces generate, as (file, `hocav generate` arguments): a cube, a
# layered shell (a text .mesh) and a 2D annulus, and, when hocav has gmsh, gmsh's unstructured shell
# and annulus (in gmsh's order of elements).
PIECES_CASES = [
    ("cube.meshb", ["cube", "--h", "0.15"]),
    ("layers.mesh", ["cubed-shell-bl-inner", "--target-tets", "6000"]),
    ("annulus.meshb", ["polar-annulus-bl-inner", "--target-triangles", "2000"]),
]
PIECES_GMSH_CASES = [("shell.mesh", ["sphere-shell", "--h", "0.15"]), ("gmsh-annulus.meshb", ["annulus", "--h", "0.08"])]


def pieces_cases():
    with_gmsh = os.environ.get("HOCAV_WITH_GMSH", "0") in ("1", "ON", "TRUE")
    return PIECES_CASES + (PIECES_GMSH_CASES if with_gmsh else [])


def keywords(path):
    """A text .mesh as {keyword: [record, ...]}, each record a tuple of its words."""
    words = open(path).read().split()
    dimension = int(words[words.index("Dimension") + 1])
    widths = {"Vertices": dimension + 1, "Edges": 3, "Triangles": 4, "Tetrahedra": 5, "EdgesP2": 4, "TrianglesP2": 7,
              "TetrahedraP2": 11}  # the tag lists: 1
    out, i = {}, 0
    while words[i] != "End":
        name = words[i]
        if name in ("MeshVersionFormatted", "Dimension"):
            i += 2
            continue
        count, width = int(words[i + 1]), widths.get(name, 1)
        out[name] = [tuple(words[i + 2 + width * k:i + 2 + width * (k + 1)]) for k in range(count)]
        i += 2 + width * count
    return out


def write_field(work, mesh, hocav, name):
    """A smooth step across a sphere (circle) plus a product of coordinates at the mesh's vertices,
    as a text .sol."""
    run([hocav, "convert", mesh, "field_mesh.mesh"], work)
    points = [[float(x) for x in record[:-1]] for record in keywords(os.path.join(work, "field_mesh.mesh"))["Vertices"]]
    values = [math.tanh((math.dist(x, [0.2] * len(x)) - 0.5) / 0.1) + x[0] * x[1] for x in points]
    with open(os.path.join(work, name), "w") as file:
        file.write(f"MeshVersionFormatted 2\nDimension {len(points[0])}\nSolAtVertices\n{len(values)}\n1 1\n")
        file.write("\n".join(repr(v) for v in values) + "\nEnd\n")


def with_materials(work, source, target, baffle=False):
    """`source` (a text 3D .mesh) written to `target` with the elements of x < 0.5 of ref 2 and a
    facet of ref 9 on every face between the two materials; with `baffle`, every element of ref 1:
    the facets between the two halves are then a baffle (one ref on both sides)."""
    mesh = keywords(os.path.join(work, source))
    points = [[float(x) for x in record[:3]] for record in mesh["Vertices"]]
    tetrahedra = [list(record[:4]) + ["2" if sum(points[int(v) - 1][0] for v in record[:4]) < 2 else "1"]
                  for record in mesh["Tetrahedra"]]
    sides = {}
    for tetrahedron in tetrahedra:
        for skip in range(4):
            face = tuple(sorted(int(v) for i, v in enumerate(tetrahedron[:4]) if i != skip))
            sides.setdefault(face, set()).add(tetrahedron[4])
    inner = [face for face, refs in sides.items() if len(refs) == 2]
    assert inner, "no face between the materials"
    if baffle:
        tetrahedra = [t[:4] + ["1"] for t in tetrahedra]
    lines = ["MeshVersionFormatted 2", "Dimension 3", "Vertices", str(len(points))]
    lines += [" ".join(record) for record in mesh["Vertices"]]
    lines += ["Tetrahedra", str(len(tetrahedra))] + [" ".join(t) for t in tetrahedra]
    triangles = [" ".join(record) for record in mesh["Triangles"]] + [f"{a} {b} {c} 9" for a, b, c in inner]
    lines += ["Triangles", str(len(triangles))] + triangles + ["End"]
    open(os.path.join(work, target), "w").write("\n".join(lines) + "\n")


def distributed_test(check):
    """The main of a distributed test: check(hocav, mpirun, work) in a scratch folder, with the hocav
    of the command line; SKIP when hocav has no MPI, else 0 once check returns."""
    hocav = os.path.abspath(sys.argv[1])
    mpirun = mpirun_or_none()
    if mpirun is None:
        return SKIP
    with tempfile.TemporaryDirectory() as work:
        check(hocav, mpirun, work)
    print("ok")
    return 0
