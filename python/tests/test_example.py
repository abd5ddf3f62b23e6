"""docs/python.md's example runs as it stands, on a .msh mesh made by `hocav generate` (gmsh's when built with it)."""
import os
import re

from conftest import built_with_gmsh, run_cli


def test_the_documented_example_runs(tmp_path, monkeypatch):
    page = open(os.path.join(os.environ["HOCAV_SOURCE_DIR"], "docs", "python.md"), encoding="utf-8").read()
    example = re.search(r"## Example.*?```python\n(.*?)```", page, re.S).group(1)
    # gmsh's annulus, as the page says; built without gmsh, the structured one written as .msh.
    case = ["annulus", "--h", "0.05"] if built_with_gmsh() else ["polar-annulus", "--target-triangles", "2000"]
    run_cli("generate", *case, "-o", tmp_path / "annulus.msh")
    monkeypatch.chdir(tmp_path)
    exec(compile(example, "docs/python.md", "exec"), {})
    for output in ("annulus-p2.meshb", "annulus-p2.vtu", "annulus-report.png"):
        assert (tmp_path / output).stat().st_size > 0, output
    _, out, _ = run_cli("stats", tmp_path / "annulus-p2.meshb", "--json")  # a valid curved mesh (else exit 2)
    assert '"order": 2' in out
