"""docs/python.md's example runs as it stands, on a gmsh mesh made by `hocav generate`."""
import os
import re

from conftest import run_cli


def test_the_documented_example_runs(tmp_path, monkeypatch):
    page = open(os.path.join(os.environ["HOCAV_SOURCE_DIR"], "docs", "python.md"), encoding="utf-8").read()
    example = re.search(r"## Example.*?```python\n(.*?)```", page, re.S).group(1)
    run_cli("generate", "annulus", "--h", "0.05", "-o", tmp_path / "annulus.msh")
    monkeypatch.chdir(tmp_path)
    exec(compile(example, "docs/python.md", "exec"), {})
    for output in ("annulus-p2.meshb", "annulus-p2.vtu", "annulus-report.png"):
        assert (tmp_path / output).stat().st_size > 0, output
    _, out, _ = run_cli("stats", tmp_path / "annulus-p2.meshb", "--json")  # a valid curved mesh (else exit 2)
    assert '"order": 2' in out
