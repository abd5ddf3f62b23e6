"""The jobs: the module calls the library's drivers the commands call, so the same job gives the same
mesh, bit for bit; reports as dicts; the GIL released while the library works."""
import json
import threading
import time

import numpy as np
import pytest

import hocav
from conftest import run_cli


def test_curve_gives_the_commands_mesh(tmp_path, ring):
    run_cli("metric", ring, "-o", tmp_path / "m.sol", "--analytic", "shear-circle", "--radius", "0.7")
    run_cli("curve", ring, "--metric", tmp_path / "m.sol", "-o", tmp_path / "cli.meshb", "--report", tmp_path / "cli.json")
    mesh = hocav.read(ring)
    curved, report = hocav.curve(mesh, hocav.read_metric(tmp_path / "m.sol", mesh), threads=1)
    hocav.write(tmp_path / "module.meshb", curved)
    assert (tmp_path / "cli.meshb").read_bytes() == (tmp_path / "module.meshb").read_bytes()
    expected = json.loads((tmp_path / "cli.json").read_text())
    assert report["normalized_jacobian"] == expected["normalized_jacobian"]
    assert report["cavities"]["accepted"] == expected["cavities"]["accepted"] > 0
    assert (curved.order, mesh.order) == (2, 1)  # a new mesh; the input is unchanged


@pytest.mark.parametrize("order", [1, 2])
def test_adapt_gives_the_commands_mesh(tmp_path, ring, order):
    run_cli("metric", ring, "-o", tmp_path / "m.sol", "--analytic", "uniform", "--h", "0.06")
    run_cli("adapt", ring, "--metric", tmp_path / "m.sol", "--order", order, "--hgrad", "1.5", "-o", tmp_path / "cli.meshb",
            "--report", tmp_path / "cli.json")
    mesh = hocav.read(ring)
    adapted, report = hocav.adapt(mesh, hocav.read_metric(tmp_path / "m.sol", mesh), order=order, hgrad=1.5)
    hocav.write(tmp_path / "module.meshb", adapted)
    assert (tmp_path / "cli.meshb").read_bytes() == (tmp_path / "module.meshb").read_bytes()
    expected = json.loads((tmp_path / "cli.json").read_text())
    assert report["output_elements"] == expected["output_elements"] > report["input_elements"]
    assert ("curving" in report) == (order == 2)


def without_seconds(passes):
    """The passes of a report without their times, which differ from run to run."""
    return [{key: value for key, value in done.items() if key != "seconds"} for done in passes]


def test_adapt_curved_gives_the_commands_curved_mesh(tmp_path, ring):
    shear = ["--analytic", "shear-circle", "--hmin", "0.01"]
    run_cli("adapt", ring, *shear, "--curved", "-o", tmp_path / "cli.meshb", "--report", tmp_path / "cli.json")
    mesh = hocav.read(ring)
    adapted, report = hocav.adapt(mesh, analytic="shear-circle", hmin=0.01, curved=True)
    hocav.write(tmp_path / "module.meshb", adapted)
    assert (tmp_path / "cli.meshb").read_bytes() == (tmp_path / "module.meshb").read_bytes()
    passes = report["curved_passes"]["passes"]
    expected = json.loads((tmp_path / "cli.json").read_text())["curved_passes"]["passes"]
    assert without_seconds(passes) == without_seconds(expected)
    assert sum(p[op]["done"] for p in passes for op in ("collapses", "splits", "swaps", "moves")) > 0
    jacobian = report["curving"]["normalized_jacobian"]
    assert jacobian["invalid"] == 0 and jacobian["min"] >= 0.01
    stats = hocav.stats(adapted)  # the output checked again, apart from the report
    assert stats["consistency"]["problems"] == [] and stats["valid"] and stats["jacobian"]["invalid"] == 0
    assert stats["counts"]["elements"] == report["output_elements"]
    assert adapted.order == 2
    assert "curved_passes" not in hocav.adapt(mesh, analytic="shear-circle", hmin=0.01)[1]


def test_adapt_refuses_what_the_command_refuses(ring):
    mesh = hocav.read(ring)
    with pytest.raises(hocav.Error, match="exactly one metric source"):
        hocav.adapt(mesh)
    with pytest.raises(hocav.Error, match="hmin must not exceed hmax"):
        hocav.adapt(mesh, analytic="uniform", hmin=0.2, hmax=0.1)
    with pytest.raises(hocav.Error, match="--surface: 'p3', 'cad:FILE' or 'none'"):
        hocav.adapt(mesh, analytic="uniform", surface="sphere")
    with pytest.raises(hocav.Error, match="curved adapts the curved mesh: it needs order 2"):
        hocav.adapt(mesh, analytic="uniform", order=1, curved=True)
    with pytest.raises(hocav.Error, match="hausd_relative: a finite number >= 0"):
        hocav.adapt(mesh, analytic="uniform", hausd_relative=-1)


def test_adapt_hausd_relative_gives_the_commands_mesh(tmp_path):
    layers = tmp_path / "layers.meshb"
    run_cli("generate", "polar-annulus-bl-inner", "--target-triangles", "400", "-o", layers)
    run_cli("metric", layers, "--implied", "-o", tmp_path / "m.sol")
    run_cli("adapt", layers, "--metric", tmp_path / "m.sol", "--order", "1", "--hausd-relative", "0.5", "-o", tmp_path / "cli.meshb")
    mesh = hocav.read(layers)
    adapted, report = hocav.adapt(mesh, hocav.read_metric(tmp_path / "m.sol", mesh), order=1, hausd_relative=0.5)
    hocav.write(tmp_path / "module.meshb", adapted)
    assert (tmp_path / "cli.meshb").read_bytes() == (tmp_path / "module.meshb").read_bytes()
    assert report["hausdorff_bounded_vertices"] > 0


def test_the_commands_warnings_are_python_warnings(ring):
    mesh = hocav.read(ring)
    with pytest.warns(UserWarning, match="not converged after 1 passes"):
        hocav.adapt(mesh, analytic="uniform", iterations=1, order=1)
    with pytest.warns(UserWarning, match="analytic linear: sizes down to 1e-12 asked, below what the geometry allows"):
        hocav.adapt(mesh, analytic="linear", hmin=1e-12, iterations=1, order=1)


def test_a_mesh_given_all_inverted_is_reoriented_with_a_warning(tmp_path):
    square = ("MeshVersionFormatted 2\nDimension 2\nVertices\n4\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n"
              "Triangles\n2\n1 {} 1\n1 {} 1\nEdges\n4\n1 2 1\n2 3 1\n3 4 1\n4 1 1\nEnd\n")
    (tmp_path / "inverted.mesh").write_text(square.format("3 2", "4 3"))
    (tmp_path / "square.mesh").write_text(square.format("2 3", "3 4"))
    inverted, positive = hocav.read(tmp_path / "inverted.mesh"), hocav.read(tmp_path / "square.mesh")
    with pytest.warns(UserWarning, match="every one of its 2 elements is negatively oriented"):
        adapted = hocav.adapt(inverted, analytic="uniform", order=1)[0]
    hocav.write(tmp_path / "turned.meshb", adapted)
    hocav.write(tmp_path / "straight.meshb", hocav.adapt(positive, analytic="uniform", order=1)[0])
    assert (tmp_path / "turned.meshb").read_bytes() == (tmp_path / "straight.meshb").read_bytes()
    with pytest.warns(UserWarning, match="negatively oriented"):
        hocav.curve(inverted, hocav.analytic_metric(inverted, "uniform"))


@pytest.mark.parametrize("arguments, call", [
    (["--analytic", "linear", "--h-min", "0.01"], lambda m: hocav.analytic_metric(m, "linear", h_min=0.01)),
    (["--implied"], hocav.implied_metric),
    (["--surface", "0.01,0.1", "--gradation", "1.5"], lambda m: hocav.surface_metric(m, 0.01, 0.1, gradation=1.5)),
    (["--hessian", "analytic:tanh-shock", "--complexity", "500"],
     lambda m: hocav.hessian_metric(m, "tanh-shock", complexity=500)),
    (["--analytic", "uniform", "--gradation", "1.2"],
     lambda m: hocav.grade_metric(m, hocav.analytic_metric(m, "uniform"), 1.2)),
])
def test_metric_sources_are_the_commands(tmp_path, ring, arguments, call):
    run_cli("metric", ring, "-o", tmp_path / "m.solb", *arguments)
    mesh = hocav.read(ring)
    np.testing.assert_array_equal(call(mesh), hocav.read_metric(tmp_path / "m.solb", mesh))


def test_a_hessian_metric_of_a_numpy_field_follows_the_field(ring):
    mesh = hocav.read(ring)
    x, y = mesh.points.T
    metric = hocav.hessian_metric(mesh, x * x, complexity=400)  # ∂²/∂x² = 2, the rest 0
    # |H| = diag(2, 0) with its eigenvalues clamped below by 1/h_max², h_max the bounding box's diagonal,
    # then scaled: M is a multiple of diag(2, 1/h_max²).
    diagonal2 = np.sum((mesh.points.max(axis=0) - mesh.points.min(axis=0)) ** 2)
    np.testing.assert_allclose(metric[:, 0] / metric[:, 2], 2 * diagonal2, rtol=1e-9)
    np.testing.assert_allclose(metric[:, 1], 0, atol=1e-9 * metric[:, 0].max())
    assert abs(hocav.metric_complexity(mesh, metric) - 400) < 1e-6 * 400


def test_interpolating_a_metric_on_its_own_mesh_gives_it_back(cube):
    mesh = hocav.read(cube)
    metric = hocav.analytic_metric(mesh, "linear")
    np.testing.assert_allclose(hocav.interpolate_metric(mesh, mesh, metric), metric, rtol=1e-12)


def test_stats_are_the_commands(tmp_path, cube):
    run_cli("metric", cube, "-o", tmp_path / "m.sol", "--analytic", "uniform")
    _, out, _ = run_cli("stats", cube, "--metric", tmp_path / "m.sol", "--json")
    mesh = hocav.read(cube)
    expected, figures = json.loads(out), hocav.stats(mesh, hocav.read_metric(tmp_path / "m.sol", mesh))
    assert figures["metric"]["edges"] > 0
    figures["mesh"], figures["metric"]["file"] = expected["mesh"], expected["metric"]["file"]  # file names
    # The arrays' capacity: the module measures its (tight) copy, the command the mesh as read.
    assert figures.pop("memory_bytes") <= expected.pop("memory_bytes")
    assert figures == expected


def test_the_gil_is_released_while_the_library_works(tmp_path):
    path = tmp_path / "shell.meshb"
    run_cli("generate", "polar-annulus", "--target-triangles", "160000", "-o", path)
    mesh = hocav.read(path)
    metric = hocav.analytic_metric(mesh, "uniform", h=0.02)
    span = {}

    def curve():
        span["start"] = time.perf_counter()
        hocav.curve(mesh, metric, threads=1)
        span["end"] = time.perf_counter()

    worker = threading.Thread(target=curve)
    ticks = []
    worker.start()
    while worker.is_alive():
        ticks.append(time.perf_counter())
    worker.join()
    inside = [t for t in ticks if span["start"] + 0.05 < t < span["end"] - 0.05]
    assert span["end"] - span["start"] > 0.2, "the job is too short to tell"
    assert len(inside) > 1000  # this thread ran Python all along
