"""Reading and writing every format of the command line, metrics with their meshes, and errors with
the command line's messages."""
import meshio
import numpy as np
import pytest

import hocav
from conftest import run_cli


@pytest.mark.parametrize("extension", [".mesh", ".meshb", ".msh"])
def test_every_mesh_format_round_trips(tmp_path, cube, extension):
    mesh = hocav.read(cube)
    path = tmp_path / ("again" + extension)
    hocav.write(path, mesh)
    again = hocav.read(path)
    for name in ("points", "elements", "element_refs"):
        np.testing.assert_array_equal(getattr(again, name), getattr(mesh, name), err_msg=name)
    assert _facet_set(again) == _facet_set(mesh)  # .msh lists the facets by their entity


def _facet_set(mesh):
    return {(tuple(sorted(facet)), ref) for facet, ref in zip(mesh.facets.tolist(), mesh.facet_refs.tolist())}


def test_write_gives_the_files_the_command_writes(tmp_path, cube):
    for extension in (".meshb", ".msh", ".vtu"):
        run_cli("convert", cube, tmp_path / ("cli" + extension))
        hocav.write(tmp_path / ("module" + extension), hocav.read(cube))
        assert (tmp_path / ("cli" + extension)).read_bytes() == (tmp_path / ("module" + extension)).read_bytes(), extension


def test_a_metric_round_trips_and_goes_into_the_vtu(tmp_path, cube):
    mesh = hocav.read(cube)
    metric = hocav.analytic_metric(mesh, "linear")
    hocav.write_metric(tmp_path / "m.solb", mesh, metric)
    np.testing.assert_array_equal(hocav.read_metric(tmp_path / "m.solb", mesh), metric)
    hocav.write(tmp_path / "m.vtu", mesh, metric=metric)
    tensors = meshio.read(tmp_path / "m.vtu").point_data["metric"]
    np.testing.assert_allclose(tensors[:, 0], metric[:, 0])  # m00
    np.testing.assert_allclose(tensors[:, 8], metric[:, 5])  # m22


def test_read_metric_maps_the_file_numbering(tmp_path, annulus):
    # The .msh numbers its nodes as gmsh did; the metric comes back in the mesh's vertex order.
    mesh = hocav.read(annulus)
    run_cli("metric", annulus, "-o", tmp_path / "m.sol", "--analytic", "linear")
    np.testing.assert_allclose(hocav.read_metric(tmp_path / "m.sol", mesh), hocav.analytic_metric(mesh, "linear"))


@pytest.mark.parametrize("content", ["MeshVersionFormatted 2\nDimension 3\nVertices\n2\n0 0 0 0\n", None])
def test_errors_carry_the_command_lines_messages(tmp_path, content):
    path = tmp_path / "bad.mesh"
    if content is not None:  # else missing
        path.write_text(content)
    code, _, err = run_cli("stats", path, check=False)
    assert code == 2
    with pytest.raises(hocav.Error) as error:
        hocav.read(path)
    assert err.strip() == "hocav: " + str(error.value)


def test_a_metric_of_the_wrong_shape_is_refused(cube):
    mesh = hocav.read(cube)
    with pytest.raises(hocav.Error, match=r"metric: an array of shape \(\d+, 6\)"):
        hocav.stats(mesh, np.ones((3, 6)))
