#!/usr/bin/python3
"""Outside checks of hocav's mesh writers with Debian's gmsh (4.8.4) and meshio (5.0).

gmsh generates curved (P2) meshes of a ball and a disk with physical groups and writes them as
.msh 4.1; `hocav convert` turns them into .msh, .mesh and .vtu; gmsh and meshio must read those
back as the same mesh: the same nodes (to 1e-12), the same P2 elements (identified by their corner
nodes, with the right mid node on every edge, so renumbering does not matter but a wrong local
order does), the same counts and the same refs / physical tags.

Usage: /usr/bin/python3 third_party_readers_test.py <path-to-hocav>
"""
import collections
import os
import subprocess
import sys
import tempfile

import gmsh
import meshio
import numpy as np

# Corner count and the corners of each mid node, in Gmsh's and in VTK/meshio's local orders.
CORNERS = {"vertex": 1, "line": 2, "line3": 2, "triangle": 3, "triangle6": 3, "tetra": 4, "tetra10": 4}
GMSH_MID_EDGES = {"line3": [(0, 1)], "triangle6": [(0, 1), (1, 2), (2, 0)],
                  "tetra10": [(0, 1), (1, 2), (2, 0), (3, 0), (3, 2), (3, 1)]}
VTK_MID_EDGES = {"line3": [(0, 1)], "triangle6": [(0, 1), (1, 2), (2, 0)],
                 "tetra10": [(0, 1), (1, 2), (2, 0), (0, 3), (1, 3), (2, 3)]}
STRAIGHT_TYPE = {"tetra10": "tetra", "triangle6": "triangle", "line3": "line"}
GMSH_TYPE_NAMES = {15: "vertex", 1: "line", 8: "line3", 2: "triangle", 9: "triangle6", 4: "tetra", 11: "tetra10"}
TOLERANCE = 1e-12


class CheckFailed(Exception):
    pass


class Mesh:
    """Points (n x 3) and, per cell type, connectivity rows (indices into points) and refs."""

    def __init__(self, points, mid_edges):
        self.points = np.asarray(points, dtype=float).reshape(-1, 3)
        self.mid_edges = mid_edges
        self.cells = collections.defaultdict(lambda: ([], []))

    def add(self, cell_type, rows, refs):
        self.cells[cell_type][0].extend(np.asarray(rows).tolist())
        self.cells[cell_type][1].extend(refs)


class NodeMatcher:
    """Gives every point the id of the reference node at the same place (within TOLERANCE)."""

    def __init__(self, reference_points):
        self.points = reference_points
        self.ids = {self.key(p): i for i, p in enumerate(reference_points)}
        if len(self.ids) != len(reference_points):
            raise CheckFailed("reference nodes closer than the matching grid")

    @staticmethod
    def key(point):
        return tuple(np.round(point, 9))

    def ids_of(self, points):
        ids = []
        for p in points:
            i = self.ids.get(self.key(p))
            if i is None or np.max(np.abs(self.points[i] - p)) > TOLERANCE:
                raise CheckFailed(f"node {p.tolist()} is not a node of the reference mesh")
            ids.append(i)
        return np.array(ids, dtype=int)


def canonical_cells(mesh, cell_type, matcher, with_refs):
    """A multiset of elements: corner ids, and per corner pair the mid node id."""
    ids = matcher.ids_of(mesh.points)
    rows, refs = mesh.cells[cell_type]
    corners = CORNERS[cell_type]
    edges = mesh.mid_edges.get(cell_type, [])
    elements = collections.Counter()
    for row, ref in zip(rows, refs):
        nodes = ids[row]
        mids = frozenset((frozenset((nodes[a], nodes[b])), nodes[corners + i]) for i, (a, b) in enumerate(edges))
        elements[(frozenset(nodes[:corners]), mids, ref if with_refs else None)] += 1
    return elements


def compare(what, reference, candidate, cell_types, with_refs=True, same_node_count=True):
    matcher = NodeMatcher(reference.points)
    if same_node_count and len(candidate.points) != len(reference.points):
        raise CheckFailed(f"{what}: {len(candidate.points)} nodes, expected {len(reference.points)}")
    summary = []
    for cell_type in cell_types:
        expected = canonical_cells(reference, cell_type, matcher, with_refs)
        found = canonical_cells(candidate, cell_type, matcher, with_refs)
        if not expected:
            raise CheckFailed(f"{what}: the reference has no {cell_type} (test setup)")
        if found != expected:
            missing, extra = expected - found, found - expected
            raise CheckFailed(f"{what}: {cell_type} differ: {sum(found.values())} found, {sum(expected.values())} "
                              f"expected, {sum(missing.values())} missing (e.g. {next(iter(missing), None)}), "
                              f"{sum(extra.values())} unexpected")
        refs = sorted({key[2] for key in found}) if with_refs else "not compared"
        summary.append(f"{sum(found.values())} {cell_type} (refs {refs})")
    print(f"ok: {what}: {len(candidate.points)} nodes, " + ", ".join(summary))


def gmsh_model_mesh(use_physical_refs=True):
    """The mesh of the current gmsh model; a cell's ref is its entity's first physical tag."""
    tags, coords, _ = gmsh.model.mesh.getNodes()
    mesh = Mesh(coords, GMSH_MID_EDGES)
    index = {tag: i for i, tag in enumerate(tags)}
    for dim, tag in gmsh.model.getEntities():
        physicals = gmsh.model.getPhysicalGroupsForEntity(dim, tag)
        ref = int(physicals[0]) if use_physical_refs and len(physicals) > 0 else tag
        types, element_tags, node_tags = gmsh.model.mesh.getElements(dim, tag)
        for gmsh_type, elements, nodes in zip(types, element_tags, node_tags):
            cell_type = GMSH_TYPE_NAMES[gmsh_type]
            rows = np.array([index[t] for t in nodes]).reshape(len(elements), -1)
            mesh.add(cell_type, rows, [ref] * len(elements))
    return mesh


def read_with_gmsh(path, use_physical_refs=True, planar=False):
    gmsh.clear()
    gmsh.open(path)
    mesh = gmsh_model_mesh(use_physical_refs)
    if planar:
        mesh.points[:, 2] = 0
    return mesh


def read_with_meshio(path, ref_key):
    data = meshio.read(path)
    mesh = Mesh(data.points, VTK_MID_EDGES)
    for i, block in enumerate(data.cells):
        if ref_key not in data.cell_data:
            raise CheckFailed(f"meshio finds no cell data '{ref_key}' in {path} (it has {list(data.cell_data)})")
        mesh.add(block.type, block.data, [int(r) for r in data.cell_data[ref_key][i]])
    return mesh


def generate(dim, path):
    """A P2 mesh of the unit ball (3D) or disk (2D), every entity in a physical group 10 + dim."""
    gmsh.clear()
    if dim == 3:
        gmsh.model.occ.addSphere(0, 0, 0, 1)
    else:
        gmsh.model.occ.addDisk(0, 0, 0, 1, 1)
    gmsh.model.occ.synchronize()
    for d in range(dim + 1):
        gmsh.model.addPhysicalGroup(d, [tag for _, tag in gmsh.model.getEntities(d)], 10 + d)
    gmsh.option.setNumber("Mesh.MeshSizeMax", 0.4)
    gmsh.model.mesh.generate(dim)
    gmsh.model.mesh.setOrder(2)
    gmsh.option.setNumber("Mesh.MshFileVersion", 4.1)
    gmsh.option.setNumber("Mesh.Binary", 0)
    gmsh.write(path)
    return gmsh_model_mesh()


def run_hocav(hocav, *arguments):
    result = subprocess.run([hocav, *arguments], capture_output=True, text=True)
    if result.returncode != 0:
        raise CheckFailed(f"hocav {' '.join(arguments)} failed ({result.returncode}): {result.stderr.strip()}")


def check_dimension(hocav, directory, dim):
    element, facet = ("tetra10", "triangle6") if dim == 3 else ("triangle6", "line3")
    source = os.path.join(directory, f"in{dim}.msh")
    reference = generate(dim, source)
    outputs = {extension: os.path.join(directory, f"out{dim}{extension}") for extension in (".msh", ".mesh", ".vtu")}
    for output in outputs.values():
        run_hocav(hocav, "convert", source, output)
    lower = [element, facet] + (["line3"] if dim == 3 else []) + ["vertex"]
    compare(f"gmsh reads hocav's {dim}D .msh", reference, read_with_gmsh(outputs[".msh"]), lower)
    compare(f"meshio reads hocav's {dim}D .msh (gmsh:physical)", reference,
            read_with_meshio(outputs[".msh"], "gmsh:physical"), lower)
    compare(f"meshio reads hocav's {dim}D .vtu (ref)", reference, read_with_meshio(outputs[".vtu"], "ref"), [element])
    # The straight (P1) version: `--order 1` drops the mid nodes; the reference keeps the corners.
    straight = {extension: os.path.join(directory, f"out{dim}_p1{extension}") for extension in (".msh", ".vtu")}
    for output in straight.values():
        run_hocav(hocav, "convert", source, output, "--order", "1")
    for p2_type, p1_type in STRAIGHT_TYPE.items():
        rows, refs = reference.cells[p2_type]
        reference.cells[p1_type] = ([row[:CORNERS[p1_type]] for row in rows], refs)
    p1_element, p1_facet = STRAIGHT_TYPE[element], STRAIGHT_TYPE[facet]
    compare(f"gmsh reads hocav's {dim}D P1 .msh", reference, read_with_gmsh(straight[".msh"]),
            [p1_element, p1_facet], same_node_count=False)
    compare(f"meshio reads hocav's {dim}D P1 .msh", reference, read_with_meshio(straight[".msh"], "gmsh:physical"),
            [p1_element, p1_facet], same_node_count=False)
    compare(f"meshio reads hocav's {dim}D P1 .vtu", reference, read_with_meshio(straight[".vtu"], "ref"), [p1_element],
            same_node_count=False)
    # gmsh's .mesh reader makes each ref an elementary entity; it has no physical groups. gmsh 4.8.4
    # reads every Vertices line as "x y z ref", so in 2D a vertex's ref lands in z: drop z.
    compare(f"gmsh reads hocav's {dim}D .mesh", reference,
            read_with_gmsh(outputs[".mesh"], use_physical_refs=False, planar=dim == 2), [element, facet])


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    hocav = os.path.abspath(sys.argv[1])
    gmsh.initialize()
    gmsh.option.setNumber("General.Terminal", 0)
    failures = 0
    with tempfile.TemporaryDirectory(prefix="hocav-third-party-") as directory:
        for dim in (3, 2):
            try:
                check_dimension(hocav, directory, dim)
            except CheckFailed as failure:
                print(f"FAILED: {failure}")
                failures += 1
    gmsh.finalize()
    print(f"{failures} failure(s)" if failures else "all third-party reader checks passed")
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
