"""hocav: curved (P2) metric-based mesh adaptation, from Python (docs/python.md).

A thin layer over the C++ library: Mesh (numpy views of its arrays), read/write of every format of
the command line, the metric sources of `hocav metric`, adapt, curve and stats. Errors raise
hocav.Error with the command line's messages; warnings are Python warnings.
"""
import numpy as np

from ._hocav import (Error, Mesh, __version__, adapt, analytic_field_names, analytic_metric,
                     analytic_metric_names, curve, grade_metric, hessian_metric, implied_metric,
                     interpolate_metric, metric_complexity, read, read_field, read_metric, stats,
                     surface_metric, write, write_metric)

# meshio's cell types of hocav's elements and facets, by dimension and order (hocav's local node
# order is VTK's, which meshio uses).
_ELEMENT_TYPES = {(2, 1): "triangle", (2, 2): "triangle6", (3, 1): "tetra", (3, 2): "tetra10"}
_FACET_TYPES = {(2, 1): "line", (2, 2): "line3", (3, 1): "triangle", (3, 2): "triangle6"}
_REF_KEYS = ("medit:ref", "gmsh:physical")


def _facet_edges(mesh):
    """The edge ids of every facet's edges, in meshio's local order (a segment's one edge; a
    triangle's (0 1), (1 2), (2 0))."""
    vertex_count = len(mesh.points)
    edges = mesh.edges.astype(np.int64)
    keys = np.minimum(edges[:, 0], edges[:, 1]) * vertex_count + np.maximum(edges[:, 0], edges[:, 1])
    order = np.argsort(keys)
    facets = mesh.facets.astype(np.int64)
    pairs = [(0, 1)] if mesh.dimension == 2 else [(0, 1), (1, 2), (2, 0)]
    columns = []
    for a, b in pairs:
        wanted = np.minimum(facets[:, a], facets[:, b]) * vertex_count + np.maximum(facets[:, a], facets[:, b])
        columns.append(order[np.searchsorted(keys, wanted, sorter=order)])
    return np.stack(columns, axis=1)


def _to_meshio(mesh):
    """The mesh as a meshio.Mesh: elements and boundary facets with their refs ("medit:ref"). A P1
    mesh's arrays are passed as they are (views, no copy); a P2 mesh's nodes are its vertices then
    its edge nodes, which takes one copy of the points and of the node lists."""
    import meshio
    key = (mesh.dimension, mesh.order)
    points, elements, facets, point_refs = mesh.points, mesh.elements, mesh.facets, mesh.point_refs
    if mesh.order == 2:
        vertex_count = len(points)
        points = np.concatenate([points, mesh.edge_nodes])
        elements = np.concatenate([elements, vertex_count + mesh.element_edges], axis=1)
        facets = np.concatenate([facets, vertex_count + _facet_edges(mesh)], axis=1)
        point_refs = np.concatenate([point_refs, np.zeros(len(mesh.edge_nodes), point_refs.dtype)])
    cells = [(_ELEMENT_TYPES[key], elements), (_FACET_TYPES[key], facets)]
    return meshio.Mesh(points, cells, point_data={"medit:ref": point_refs},
                       cell_data={"medit:ref": [mesh.element_refs, mesh.facet_refs]})


def _cells_of(meshio_mesh, cell_types):
    """The node lists and refs of the blocks of the given types, as one array each (or None)."""
    blocks, refs = [], []
    for index, block in enumerate(meshio_mesh.cells):
        if block.type not in cell_types:
            continue
        blocks.append(block.data)
        ref_key = next((k for k in _REF_KEYS if k in meshio_mesh.cell_data), None)
        refs.append(meshio_mesh.cell_data[ref_key][index] if ref_key else np.zeros(len(block.data), np.int32))
    if not blocks:
        return None, None
    return np.concatenate(blocks), np.concatenate(refs)


def _from_meshio(meshio_mesh):
    """A Mesh from a meshio.Mesh: its tetrahedra (3D) or else triangles (2D), P1 or P2, with the
    boundary facets and the refs it has ("medit:ref" or "gmsh:physical" cell data). Checked as a file
    is; the arrays are copied once into the library."""
    present = {block.type for block in meshio_mesh.cells}
    dimension = 3 if present & {"tetra", "tetra10"} else 2
    elements, element_refs = _cells_of(meshio_mesh, {_ELEMENT_TYPES[(dimension, 1)], _ELEMENT_TYPES[(dimension, 2)]})
    if elements is None:
        raise Error("Mesh.from_meshio: no triangles or tetrahedra in the meshio mesh")
    facets, facet_refs = _cells_of(meshio_mesh, {_FACET_TYPES[(dimension, 1)], _FACET_TYPES[(dimension, 2)]})
    point_refs = meshio_mesh.point_data.get("medit:ref")
    return Mesh(np.asarray(meshio_mesh.points)[:, :dimension], elements, facets, point_refs=point_refs,
                element_refs=element_refs, facet_refs=facet_refs)


Mesh.to_meshio = _to_meshio
Mesh.from_meshio = staticmethod(_from_meshio)

__all__ = ["Error", "Mesh", "__version__", "adapt", "analytic_field_names", "analytic_metric", "analytic_metric_names",
           "curve", "grade_metric", "hessian_metric", "implied_metric", "interpolate_metric", "metric_complexity",
           "read", "read_field", "read_metric", "stats", "surface_metric", "write", "write_metric"]
