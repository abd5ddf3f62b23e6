"""hocav.Mesh: numpy views of the library's arrays, construction from arrays, meshio both ways."""
import meshio
import numpy as np
import pytest

import hocav
from conftest import run_cli


def test_arrays_are_read_only_views_of_one_storage(ring):
    mesh = hocav.read(ring)
    points, again = mesh.points, mesh.points
    assert points.shape == (len(points), 2) and points.dtype == np.float64
    assert np.shares_memory(points, again)  # the same storage, no copy per access
    assert not points.flags.owndata and not points.flags.writeable
    with pytest.raises(ValueError):
        points[0, 0] = 1.0
    assert mesh.elements.shape[1] == 3 and mesh.elements.dtype == np.int32
    assert len(mesh.element_refs) == len(mesh.elements) and len(mesh.facet_refs) == len(mesh.facets)


def test_a_view_keeps_its_mesh_alive(ring):
    points = hocav.read(ring).points  # the mesh has no other reference
    copy = np.array(points)
    np.testing.assert_array_equal(points, copy)
    assert points.base is not None


def test_mesh_from_its_own_arrays_is_the_same_mesh(cube):
    mesh = hocav.read(cube)
    again = hocav.Mesh(mesh.points, mesh.elements, mesh.facets, point_refs=mesh.point_refs,
                       element_refs=mesh.element_refs, facet_refs=mesh.facet_refs)
    assert (again.dimension, again.order) == (3, 1)
    for name in ("points", "elements", "facets", "point_refs", "element_refs", "facet_refs"):
        np.testing.assert_array_equal(getattr(again, name), getattr(mesh, name), err_msg=name)


def test_p2_nodes_are_views_on_the_edges(tmp_path):
    path = tmp_path / "square-p2.mesh"
    run_cli("generate", "square", "--h", "0.34", "--order", "2", "-o", path)
    mesh = hocav.read(path)
    assert mesh.order == 2
    edges, nodes, element_edges = mesh.edges, mesh.edge_nodes, mesh.element_edges
    assert element_edges.shape == (len(mesh.elements), 3)
    # Straight P2 nodes: each edge's node is its midpoint.
    np.testing.assert_allclose(nodes, 0.5 * (mesh.points[edges[:, 0]] + mesh.points[edges[:, 1]]))
    # Local edge 0 of each element joins its corners 0 and 1.
    first = edges[element_edges[:, 0]]
    np.testing.assert_array_equal(np.sort(first, axis=1), np.sort(mesh.elements[:, :2], axis=1))


def test_bad_arrays_raise_errors_naming_what_is_wrong():
    points = np.array([[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]])
    with pytest.raises(hocav.Error, match="out of range"):
        hocav.Mesh(points, np.array([[0, 1, 7]]))
    with pytest.raises(hocav.Error, match="columns"):
        hocav.Mesh(points, np.array([[0, 1]]))
    with pytest.raises(hocav.Error, match=r"\(n, 2\) or \(n, 3\)"):
        hocav.Mesh(np.zeros(3), np.array([[0, 1, 2]]))


@pytest.mark.parametrize("order", [1, 2])
def test_meshio_round_trip_keeps_the_mesh(tmp_path, order):
    path = tmp_path / "cube.mesh"
    run_cli("generate", "cube", "--h", "0.5", "--order", str(order), "-o", path)
    mesh = hocav.read(path)
    converted = mesh.to_meshio()
    assert isinstance(converted, meshio.Mesh)
    assert converted.cells[0].type == ("tetra" if order == 1 else "tetra10")
    back = hocav.Mesh.from_meshio(converted)
    assert back.order == order
    for name in ("points", "elements", "facets", "element_refs", "facet_refs"):
        np.testing.assert_array_equal(getattr(back, name), getattr(mesh, name), err_msg=name)
    if order == 2:
        np.testing.assert_array_equal(back.edge_nodes, mesh.edge_nodes)


def test_meshio_reads_what_hocav_gives_it(tmp_path, ring):
    mesh = hocav.read(ring)
    path = tmp_path / "through-meshio.vtu"
    mesh.to_meshio().write(path)
    read = meshio.read(path)
    np.testing.assert_allclose(read.points[:, :2], mesh.points)
    np.testing.assert_array_equal(read.cells_dict["triangle"], mesh.elements)
