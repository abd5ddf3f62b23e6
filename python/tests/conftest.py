"""What the module's tests share: the hocav command of the same build (to compare the module with it)
and small generated inputs. Run by ctest (python/CMakeLists.txt) with PYTHONPATH, HOCAV_BINARY and
HOCAV_WITH_GMSH set."""
import os
import subprocess

import pytest

import hocav


def run_cli(*arguments, check=True):
    """Runs the hocav command; returns (exit code, stdout, stderr)."""
    done = subprocess.run([os.environ["HOCAV_BINARY"], *map(str, arguments)], capture_output=True, text=True)
    if check and done.returncode != 0:
        raise AssertionError(f"hocav {' '.join(map(str, arguments))} failed: {done.stderr}")
    return done.returncode, done.stdout, done.stderr


def built_with_gmsh():
    return os.environ.get("HOCAV_WITH_GMSH") == "1"


def skip_without_gmsh(what):
    """Skips the test, saying why, when this hocav was built without gmsh (HOCAV_WITH_GMSH=OFF)."""
    if not built_with_gmsh():
        pytest.skip(f"{what} needs gmsh, and this hocav was built without it (HOCAV_WITH_GMSH=OFF)")


@pytest.fixture
def annulus(tmp_path):
    """A small unstructured 2D mesh made by gmsh (hocav generate annulus), as gmsh's .msh, its path."""
    skip_without_gmsh("the gmsh-meshed annulus")
    path = tmp_path / "annulus.msh"
    run_cli("generate", "annulus", "--h", "0.1", "-o", path)
    return path


@pytest.fixture
def ring(tmp_path):
    """A small structured 2D mesh between the circles of radii 0.5 and 1 (no gmsh needed), as .msh,
    its path."""
    path = tmp_path / "ring.msh"
    run_cli("generate", "polar-annulus", "--target-triangles", "800", "-o", path)
    return path


@pytest.fixture
def cube(tmp_path):
    """A small 3D mesh, its path."""
    path = tmp_path / "cube.meshb"
    run_cli("generate", "cube", "--h", "0.25", "-o", path)
    return path
