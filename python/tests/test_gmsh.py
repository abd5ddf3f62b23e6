"""gmsh, which takes most of a second to load, is loaded only when a surface names a CAD model:
hocav._gmsh, the one part of the module that links it, is imported then (docs/python.md, "gmsh")."""
import subprocess
import sys

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


# adapt is P1 here: its curving step would open a second CAD boundary while the adaptation's is open,
# which gmsh's one session refuses (the command as well).
@pytest.mark.parametrize("job, options", [("curve", {}), ("adapt", {"order": 1})])
def test_a_cad_surface_gives_the_commands_mesh(tmp_path, job, options):
    skip_without_gmsh("a CAD model")
    mesh_path, model = tmp_path / "annulus.mesh", tmp_path / "annulus.step"
    run_cli("generate", "annulus", "--h", "0.2", "-o", mesh_path, "--cad-out", model)
    run_cli("metric", mesh_path, "-o", tmp_path / "m.sol", "--analytic", "uniform", "--h", "0.15")
    cli_options = [f"--{name}={value}" for name, value in options.items()]
    run_cli(job, mesh_path, "--metric", tmp_path / "m.sol", "--surface", f"cad:{model}", *cli_options, "-o", tmp_path / "cli.meshb",
            "-q")
    mesh = hocav.read(mesh_path)
    result, _ = getattr(hocav, job)(mesh, hocav.read_metric(tmp_path / "m.sol", mesh), surface=f"cad:{model}", **options)
    hocav.write(tmp_path / "module.meshb", result)
    assert (tmp_path / "cli.meshb").read_bytes() == (tmp_path / "module.meshb").read_bytes()
