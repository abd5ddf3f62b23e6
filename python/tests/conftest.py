"""What the module's tests share: the hocav command of the same build (to compare the module with it)
and small generated inputs. Run by ctest (python/CMakeLists.txt) with PYTHONPATH and HOCAV_BINARY set."""
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


@pytest.fixture
def annulus(tmp_path):
    """A small unstructured 2D mesh (gmsh's, written as .msh), its path."""
    path = tmp_path / "annulus.msh"
    run_cli("generate", "annulus", "--h", "0.1", "-o", path)
    return path


@pytest.fixture
def cube(tmp_path):
    """A small 3D mesh, its path."""
    path = tmp_path / "cube.meshb"
    run_cli("generate", "cube", "--h", "0.25", "-o", path)
    return path
