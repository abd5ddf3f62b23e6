"""Outside check of hocav's Jacobian figures: gmsh's AnalyseMeshQuality plugin (JacobianDeterminant)
computes minJ/maxJ of every element of the same curved P2 mesh; hocav writes its own per element
in the .vtu. Both are certified lower bounds of the true ratio (bounds of min J over bounds of max J,
refined by subdivision). Element by element they must agree to round-off where gmsh's bound is
already tight, and hocav's, refined further (1e-6), may only be higher (tighter), never lower.

The curved mesh is the mmg torus curved by `hocav curve` in its own metric (third-party input).
Usage: gmsh_jacobian_check_test.py PATH_TO_HOCAV
"""
import os
import subprocess
import sys
import tempfile

import gmsh
import meshio
import numpy as np

HOCAV = sys.argv[1]
DATA = os.path.join(os.path.dirname(__file__), "..", "..", "..", "shared", "data", "mmg-torus")


def run(*args):
    subprocess.run([HOCAV, *args], check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)


def gmsh_scaled_jacobians(path):
    """Element corner coordinates (sorted, rounded) -> gmsh's minJ/maxJ."""
    gmsh.initialize(readConfigFiles=False)
    gmsh.option.setNumber("General.Terminal", 0)
    gmsh.open(path)
    gmsh.plugin.setNumber("AnalyseMeshQuality", "JacobianDeterminant", 1)
    gmsh.plugin.setNumber("AnalyseMeshQuality", "CreateView", 1)
    gmsh.plugin.setNumber("AnalyseMeshQuality", "DimensionOfElements", 3)
    gmsh.plugin.run("AnalyseMeshQuality")
    view = gmsh.view.getTags()[-1]
    _, tags, data, _, _ = gmsh.view.getModelData(view, 0)
    value_of_tag = {int(t): d[0] for t, d in zip(tags, data)}
    result = {}
    for tag, value in value_of_tag.items():
        _, nodes = gmsh.model.mesh.getElement(tag)[:2]
        corners = [tuple(np.round(gmsh.model.mesh.getNode(n)[0], 9)) for n in nodes[:4]]
        result[tuple(sorted(corners))] = value
    gmsh.finalize()
    return result


def main():
    with tempfile.TemporaryDirectory() as work:
        curved = os.path.join(work, "torus.meshb")
        run("curve", os.path.join(DATA, "torus.mesh"), "--metric", os.path.join(DATA, "torus-met.sol"), "-o", curved, "-q")
        run("convert", curved, os.path.join(work, "torus.msh"))
        run("convert", curved, os.path.join(work, "torus.vtu"))
        theirs = gmsh_scaled_jacobians(os.path.join(work, "torus.msh"))
        mesh = meshio.read(os.path.join(work, "torus.vtu"))
        ours = mesh.cell_data["scaled_jacobian"][0]
        cells = mesh.cells[0].data
        assert len(cells) == len(theirs), (len(cells), len(theirs))
        differences = []  # hocav − gmsh
        curved_elements = 0
        for cell, value in zip(cells, ours):
            corners = tuple(sorted(tuple(np.round(mesh.points[n], 9)) for n in cell[:4]))
            differences.append(value - theirs[corners])
            curved_elements += value < 1 - 1e-9
        d = np.array(differences)
        same = np.mean(np.abs(d) < 1e-12)
        print(f"{len(cells)} elements ({curved_elements} curved): equal to 1e-12: {100 * same:.2f}%; "
              f"hocav - gmsh in [{d.min():.3g}, {d.max():.3g}]; min hocav {min(ours):.12g}, "
              f"min gmsh {min(theirs.values()):.12g}")
        assert curved_elements > len(cells) // 10, "the test mesh should be curved"
        assert d.min() > -1e-12, "hocav's bound is looser than gmsh's somewhere"
        assert same > 0.95, same
        assert d.max() < 5e-3, d.max()
        assert abs(min(ours) - min(theirs.values())) < 1e-12
        print("1 passed, 0 failed")


main()
