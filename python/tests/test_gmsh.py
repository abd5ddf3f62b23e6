"""gmsh, which takes most of a second to load, is loaded only when a surface names a CAD model:
hocav._gmsh, the one part of the module that links it, is imported then (docs/python.md, "gmsh")."""
import subprocess
import sys

import numpy as np
import pytest

import hocav
from conftest import built_with_gmsh, run_cli, skip_without_gmsh

# Curves a mesh on the P3 surrogate, then asks for a CAD surface; prints, after each, whether hocav._gmsh
# is imported and libgmsh mapped into the process, and the CAD surface's error.
PROBE = """
import sys
import hocav

def loaded():
    with open("/proc/self/maps") as maps:
        print("hocav._gmsh" in sys.modules, "libgmsh" in maps.read())

mesh = hocav.read(sys.argv[1])
metric = hocav.read_metric(sys.argv[2], mesh)
hocav.curve(mesh, metric, threads=1)
loaded()
try:
    hocav.curve(mesh, metric, surface="cad:" + sys.argv[3])
except hocav.Error as error:
    print(error)
loaded()
"""


def test_gmsh_loads_with_the_first_cad_surface_only(tmp_path, ring):
    metric, missing = tmp_path / "m.sol", tmp_path / "missing.step"
    run_cli("metric", ring, "-o", metric, "--analytic", "uniform", "--h", "0.2")
    done = subprocess.run([sys.executable, "-c", PROBE, ring, metric, missing], capture_output=True, text=True, check=True)
    before, error, after = done.stdout.splitlines()
    assert before == "False False"
    _, _, expected = run_cli("curve", ring, "--metric", metric, "--surface", f"cad:{missing}", "-o", tmp_path / "c.meshb",
                             check=False)
    assert "hocav: " + error == expected.strip()  # the command's message, with gmsh or without
    assert after == ("True True" if built_with_gmsh() else "True False")


def boundary_node_radii(mesh):
    """Per facet ref, the distances from the origin of the P2 nodes of the boundary edges."""
    edge_of = {tuple(sorted(vertices)): edge for edge, vertices in enumerate(mesh.edges.tolist())}
    radii = {}
    for facet, ref in zip(mesh.facets.tolist(), mesh.facet_refs.tolist()):
        node = mesh.edge_nodes[edge_of[tuple(sorted(facet))]]
        radii.setdefault(ref, []).append(float(np.hypot(*node)))
    return radii


# Both commands give a P2 mesh whose boundary nodes are on the CAD model: the annulus's circles,
# ref 1 of radius 0.5 and ref 2 of radius 1 (docs/cases.md). adapt splits the boundary edges first,
# with the new vertices on the CAD too (on the straight boundary, the nodes would be up to 0.007 off).
@pytest.mark.parametrize("job", ["curve", "adapt"])
def test_a_cad_surface_gives_the_commands_mesh(tmp_path, job):
    skip_without_gmsh("a CAD model")
    mesh_path, model = tmp_path / "annulus.mesh", tmp_path / "annulus.step"
    run_cli("generate", "annulus", "--h", "0.2", "-o", mesh_path, "--cad-out", model)
    run_cli("metric", mesh_path, "-o", tmp_path / "m.sol", "--analytic", "uniform", "--h", "0.1")
    run_cli(job, mesh_path, "--metric", tmp_path / "m.sol", "--surface", f"cad:{model}", "-o", tmp_path / "cli.meshb", "-q")
    mesh = hocav.read(mesh_path)
    result, _ = getattr(hocav, job)(mesh, hocav.read_metric(tmp_path / "m.sol", mesh), surface=f"cad:{model}")
    hocav.write(tmp_path / "module.meshb", result)
    assert (tmp_path / "cli.meshb").read_bytes() == (tmp_path / "module.meshb").read_bytes()
    assert result.order == 2
    assert (len(result.facets) > len(mesh.facets)) == (job == "adapt")  # the loop refined the boundary
    radii = boundary_node_radii(result)
    assert sorted(radii) == [1, 2]
    for ref, radius in ((1, 0.5), (2, 1.0)):
        assert np.allclose(radii[ref], radius, rtol=0, atol=1e-9), (ref, min(radii[ref]), max(radii[ref]))
