"""Outside check of hocav's curved .vtu with Debian's ParaView (5.11): ParaView must read the P2 cells
as quadratic cells, with hocav's counts, and draw them curved.

Two small curved meshes made with the CLI (no gmsh needed): the structured sphere shell curved in
its implied metric on the P3 surrogate of its boundary (quadratic tetrahedra), and the shear-circle
case curved in its metric (quadratic triangles); and, when hocav has MPI, the shell curved under
`mpirun -np 3`, whose .vtu the parts write in runs (docs/distributed.md §A .vtu in runs: a vertex of
several parts is a point of each). For each, ParaView's `pvbatch` runs
scripts/paraview_picture.py under a private Xvfb display (Debian's ParaView renders through X only)
and reports what it read; this test checks the cell types and counts against `hocav stats`, that
the shell's boundary drawn with nonlinear subdivision lies on its spheres far closer than the
straight one (curved cells drawn curved), and that the picture is not blank.
Skipped (exit 77, counted by ctest) when pvbatch or Xvfb is missing (Debian: paraview,
python3-paraview, xvfb).
Usage: paraview_vtu_test.py PATH_TO_HOCAV
"""
import contextlib
import json
import os
import shutil
import subprocess
import sys
import tempfile
import zlib

HOCAV = sys.argv[1]
PICTURE_SCRIPT = os.path.join(os.path.dirname(__file__), "..", "..", "scripts", "paraview_picture.py")
QUADRATIC_TRIANGLE, QUADRATIC_TETRA = "22", "24"


def run(*args):
    return subprocess.run([HOCAV, *args], check=True, stdout=subprocess.PIPE, text=True).stdout


@contextlib.contextmanager
def virtual_display():
    """A private Xvfb display; -noreset, since pvbatch connects more than once and a server that
    resets when its last client leaves refuses the next connection meanwhile."""
    xvfb = subprocess.Popen(["Xvfb", "-displayfd", "1", "-screen", "0", "1280x1024x24", "-nolisten", "tcp",
                             "-noreset"], stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True)
    try:
        yield ":" + xvfb.stdout.readline().strip()
    finally:
        xvfb.terminate()
        xvfb.wait()


def paraview_facts(display, vtu, picture, *options):
    result = subprocess.run(["pvbatch", PICTURE_SCRIPT, vtu, picture, *options], env={**os.environ, "DISPLAY": display},
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    assert result.returncode == 0, f"pvbatch failed ({result.returncode}): {result.stderr[-2000:]}"
    return json.loads(result.stdout.strip().splitlines()[-1])


def png_pixel_rows(path):
    """The decompressed scanlines of an 8-bit RGB or RGBA PNG (filter bytes included)."""
    with open(path, "rb") as file:
        data = file.read()
    assert data[:8] == b"\x89PNG\r\n\x1a\n", f"{path} is not a PNG"
    chunks, position = {}, 8
    while position < len(data):
        length = int.from_bytes(data[position:position + 4], "big")
        kind = data[position + 4:position + 8]
        chunks.setdefault(kind, []).append(data[position + 8:position + 8 + length])
        position += 12 + length
    return zlib.decompress(b"".join(chunks[b"IDAT"]))


def expect_not_blank(picture):
    pixels = png_pixel_rows(picture)
    # A picture of one colour compresses to almost nothing; a drawn mesh does not.
    assert len(set(pixels)) > 32, f"{picture} looks blank"
    assert len(zlib.compress(pixels)) > 20000, f"{picture} holds too little to be a drawn mesh"


def expect_counts(facts, mesh, cell_type, in_runs=False):
    """ParaView's cells are the mesh's, and its points too (at least as many when written in runs)."""
    counts = json.loads(run("stats", mesh, "--json"))["counts"]
    assert facts["cell_types"] == {cell_type: counts["elements"]}, (facts["cell_types"], counts)
    points = counts["vertices"] + counts["p2_nodes"]
    assert facts["points"] > points if in_runs else facts["points"] == points, (facts["points"], counts)


def mpirun_or_none():
    """mpirun (oversubscribed, root allowed) when hocav has MPI, else None."""
    if os.environ.get("HOCAV_WITH_MPI", "0") not in ("1", "ON", "TRUE"):
        return None
    os.environ.update(OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    return [os.environ.get("HOCAV_MPIEXEC") or "mpirun", "--oversubscribe", "-np", "3"]


def check_shell(work, display, mpirun=None):
    mesh, metric = os.path.join(work, "shell.meshb"), os.path.join(work, "shell.solb")
    name = "shell-p2" + ("-runs" if mpirun else "")
    curved, vtu = os.path.join(work, name + ".meshb"), os.path.join(work, name + ".vtu")
    run("generate", "cubed-shell", "--target-tets", "3000", "-o", mesh)
    run("metric", mesh, "--implied", "-o", metric)
    subprocess.run((mpirun or []) + [HOCAV, "curve", mesh, "--metric", metric, "-o", curved, "--vtu", vtu, "-q", "--threads", "1"],
                   check=True, stdout=subprocess.DEVNULL)
    picture = os.path.join(work, name + ".png")
    facts = paraview_facts(display, vtu, picture, "--radii", "0.5,1", "--subdivision", "3")
    expect_counts(facts, curved, QUADRATIC_TETRA, in_runs=mpirun is not None)
    straight, subdivided = facts["straight_boundary_median_distance"], facts["curved_boundary_median_distance"]
    # Straight boundary edges cut inside the spheres by about h²/8r; the P2 boundary follows them.
    assert straight > 1e-3, straight
    assert subdivided < straight / 20, (subdivided, straight)
    expect_not_blank(picture)
    print(f"{name}: {facts['cell_types']} quadratic tetrahedra, {facts['points']} points, boundary off the spheres by {straight:.2e} "
          f"straight and {subdivided:.2e} with nonlinear subdivision (medians)")


def check_shear_circle(work, display):
    mesh, metric = os.path.join(work, "circle.meshb"), os.path.join(work, "circle.solb")
    curved, vtu = os.path.join(work, "circle-p2.meshb"), os.path.join(work, "circle-p2.vtu")
    run("generate", "shear-circle", "-o", mesh)
    run("metric", mesh, "--analytic", "shear-circle", "-o", metric)
    run("curve", mesh, "--metric", metric, "-o", curved, "--vtu", vtu, "-q")
    picture = os.path.join(work, "circle.png")
    facts = paraview_facts(display, vtu, picture)
    expect_counts(facts, curved, QUADRATIC_TRIANGLE)
    expect_not_blank(picture)
    print(f"shear circle: {facts['cell_types']} quadratic triangles")


def main():
    missing = [program for program in ("pvbatch", "Xvfb") if shutil.which(program) is None]
    if missing:
        print(f"SKIPPED: {' and '.join(missing)} not found (Debian packages paraview, python3-paraview, xvfb)")
        sys.exit(77)  # ctest: skipped
    with tempfile.TemporaryDirectory() as work, virtual_display() as display:
        check_shell(work, display)
        check_shear_circle(work, display)
        mpirun = mpirun_or_none()
        if mpirun:
            check_shell(work, display, mpirun)
        else:
            print("SKIPPED: the .vtu in runs: hocav was built without MPI (HOCAV_WITH_MPI off)")
    print("1 passed, 0 failed")


main()
