"""Side by side with mmg: `hocav adapt` and mmg (mmg3d_O3, mmg2d_O3) adapt the same inputs to the
same metrics, and every output, ours and mmg's, is measured by the same code, `hocav stats --json`
with the metric at the output's own vertices:
  analytic cases   the analytic field evaluated there (`hocav metric OUT --analytic ...`);
  .sol cases       the input metric interpolated there, log-Euclidean in the input mesh
                   (`hocav metric OUT --from IN.mesh --from-metric IN.sol`).
Figures: unit share (edges of metric length in [1/sqrt 2, sqrt 2], 16-point Gauss rule), the
mean-ratio quality in the metric (mean, min, share below 0.1), wall time (median over --repeat
runs, summed over the iterations of a case), elements written per second, peak resident memory
(/usr/bin/time -v). mmg runs with its defaults (-hgrad 1.3, -hausd 0.01, ...) unless --mmg-args
says otherwise; it is serial. Its gradation changes the metric it adapts to, so on a metric that
varies faster than 1.3 per unit length its output is measured in a metric it did not aim at.

Usage (from the repository root, with Debian's Python):
  /usr/bin/python3 bench/adapt_compare.py --mmg3d PATH --mmg2d PATH [--threads N] [--out DIR]
        [--cases NAME,...] [--repeat N] [--json FILE]
A tool whose binary is not given or absent is skipped with a message, and so are the hocav rows
while `hocav adapt --help` does not show the command's usage (it is not there yet).
"""
import argparse
import json
import re
import shlex
import shutil
import statistics
import subprocess
import sys
import tempfile
import time
from dataclasses import dataclass
from pathlib import Path

TIME = Path("/usr/bin/time")


@dataclass
class Case:
    name: str
    dimension: int
    # hocav commands (argument lists, run in the case folder) that write start.mesh and, for a .sol
    # case, start.sol.
    setup: list
    # The analytic metric's `hocav metric` arguments, evaluated at each iteration's input and at
    # the output; None for a .sol case (start.sol given once, interpolated onto the output).
    analytic: list = None
    # Adaptations in a row, each from the previous output (the UGAWG protocol for analytic fields:
    # the metric is evaluated anew at every input's vertices).
    iterations: int = 1
    # Files of the data folder copied in as they are, (source, destination), before the setup.
    copies: tuple = ()


# mmg's torus and metric as shipped; the UGAWG "linear" field from the 6,000-tet cube; a boundary
# layer on both walls of the sphere shell (README's demo metric: 0.01 across, 0.1 along, graded
# 1.5); an anisotropic layer (10:1) across the sphere r = 0.75 inside the shell; a structured
# boundary-layer shell (layers on both walls, first layer 0.003) in its own implied metric, which
# changes by up to 100 across one element; and the sphere shell's two metrics in the annulus for mmg2d.
def case_list():
    surface = ["--surface", "0.01,0.1", "--gradation", "1.5"]
    surface_2d = ["--surface", "0.005,0.05", "--gradation", "1.5"]
    return [
        Case("mmg-torus", 3, [], copies=(("mmg-torus/torus.mesh", "start.mesh"), ("mmg-torus/torus-met.sol", "start.sol"))),
        Case("ugawg-linear", 3, [["generate", "cube", "--h", "0.1", "-o", "start.mesh"]],
             analytic=["--analytic", "linear"], iterations=6),
        Case("sphere-shell", 3, [["generate", "sphere-shell", "--h", "0.1", "-o", "start.mesh"],
                                 ["metric", "start.mesh", *surface, "-o", "start.sol"]]),
        Case("shear-sphere", 3, [["generate", "sphere-shell", "--h", "0.1", "-o", "start.mesh"]],
             analytic=["--analytic", "shear-sphere", "--h-min", "0.01"], iterations=3),
        Case("bl-shell-implied", 3, [["generate", "cubed-shell-bl-both", "--target-tets", "8000", "--first-layer", "0.003", "-o", "start.mesh"],
                                     ["metric", "start.mesh", "--implied", "-o", "start.sol"]]),
        Case("annulus", 2, [["generate", "annulus", "--h", "0.05", "-o", "start.mesh"],
                            ["metric", "start.mesh", *surface_2d, "-o", "start.sol"]]),
        Case("shear-circle", 2, [["generate", "annulus", "--h", "0.05", "-o", "start.mesh"]],
             analytic=["--analytic", "shear-circle", "--h-min", "0.01"], iterations=3),
    ]


class CommandFailed(Exception):
    pass


def run(command, folder):
    result = subprocess.run([str(c) for c in command], cwd=folder, capture_output=True, text=True)
    if result.returncode != 0:
        raise CommandFailed(f"{shlex.join(map(str, command))} (exit {result.returncode}):\n{result.stderr[-2000:]}")
    return result


def timed_run(command, folder):
    """(wall seconds, peak resident MB or None) of one run."""
    if not TIME.exists():
        start = time.perf_counter()
        run(command, folder)
        return time.perf_counter() - start, None
    report = Path(folder) / "time.txt"
    run([TIME, "-v", "-o", report, *command], folder)
    text = report.read_text()
    wall = re.search(r"Elapsed \(wall clock\) time \(h:mm:ss or m:ss\): (\S+)", text).group(1)
    seconds = sum(float(part) * 60 ** i for i, part in enumerate(reversed(wall.split(":"))))
    peak_kb = int(re.search(r"Maximum resident set size \(kbytes\): (\d+)", text).group(1))
    return seconds, peak_kb / 1024


class Tool:
    def __init__(self, name, threads):
        self.name, self.threads = name, threads

    def adapt_command(self, mesh, metric, output):
        raise NotImplementedError


class Hocav(Tool):
    extension = ".meshb"

    def __init__(self, binary, threads, extra):
        super().__init__("hocav", threads)
        self.binary, self.extra = binary, extra

    def adapt_command(self, mesh, metric, output):
        return [self.binary, "adapt", mesh, "--metric", metric, "-o", output, "--threads", self.threads, *self.extra]


class Mmg(Tool):
    extension = ".mesh"  # mmg writes .mesh/.sol; its output .sol is its graded metric, unused here

    def __init__(self, binary, extra):
        super().__init__(Path(binary).name, 1)
        self.binary, self.extra = binary, extra

    def adapt_command(self, mesh, metric, output):
        return [self.binary, "-in", mesh, "-sol", metric, "-out", output, *self.extra]


def adapt_case(case, tool, hocav, folder, repeat):
    """Runs the tool's iterations from start.mesh; returns (final mesh, seconds, elements/s, peak MB)."""
    mesh, metric = "start.mesh", "start.sol"
    seconds = elements = 0.0
    peak = None
    for iteration in range(1, case.iterations + 1):
        if case.analytic:
            metric = f"{tool.name}-{iteration}-in.sol"  # not -{iteration}.sol, where mmg writes its own
            run([hocav, "metric", mesh, *case.analytic, "-o", metric], folder)
        output = f"{tool.name}-{iteration}{tool.extension}"
        runs = [timed_run(tool.adapt_command(mesh, metric, output), folder) for _ in range(repeat)]
        seconds += statistics.median(r[0] for r in runs)
        if runs[0][1] is not None:
            peak = max(peak or 0.0, max(r[1] for r in runs))
        elements += stats(hocav, folder, output)["counts"]["elements"]
        mesh = output
    return mesh, seconds, elements / seconds if seconds > 0 else None, peak


def stats(hocav, folder, mesh, metric=None):
    command = [hocav, "stats", mesh, "--json"] + (["--metric", metric] if metric else [])
    # An invalid mesh exits with 2 after its report: measure it all the same.
    result = subprocess.run([str(c) for c in command], cwd=folder, capture_output=True, text=True)
    if not result.stdout:
        raise CommandFailed(f"{shlex.join(map(str, command))}: {result.stderr}")
    return json.loads(result.stdout)


def measure(case, hocav, folder, mesh, tool_name):
    """The stats of a final mesh in the case's metric at its own vertices."""
    metric = f"{tool_name}-measured.solb"
    source = case.analytic or ["--from", "start.mesh", "--from-metric", "start.sol"]
    run([hocav, "metric", mesh, *source, "-o", metric], folder)
    return stats(hocav, folder, mesh, metric)


def row(case, tool, figures, seconds, rate, peak):
    metric = figures["metric"]
    return {"case": case.name, "tool": tool.name, "threads": tool.threads,
            "vertices": figures["counts"]["vertices"], "elements": figures["counts"]["elements"],
            "valid": figures["valid"], "unit_share": metric["unit_share"],
            "quality_mean": metric["quality"]["mean"], "quality_min": metric["quality"]["min"],
            "low_quality_share": metric["quality"]["low_share"], "seconds": seconds,
            "elements_per_second": rate, "peak_mb": peak}


def markdown(rows):
    header = ["case", "tool", "threads", "vertices", "elements", "valid", "unit share", "mean q", "min q",
              "q<0.1", "time s", "elements/s", "peak MB"]

    def cells(r):
        def opt(value, form):
            return "-" if value is None else form.format(value)
        return [r["case"], r["tool"], str(r["threads"]), str(r["vertices"]), str(r["elements"]),
                "yes" if r["valid"] else "NO", f"{100 * r['unit_share']:.1f}%", f"{r['quality_mean']:.3f}",
                f"{r['quality_min']:.3f}", f"{100 * r['low_quality_share']:.2f}%", f"{r['seconds']:.2f}",
                opt(r["elements_per_second"], "{:.0f}"), opt(r["peak_mb"], "{:.0f}")]

    lines = ["| " + " | ".join(header) + " |", "|" + "---|" * len(header)]
    lines += ["| " + " | ".join(cells(r)) + " |" for r in rows]
    return "\n".join(lines)


def available_tools(args, hocav):
    """The tools of each dimension, with a message for each one skipped."""
    tools = {2: [], 3: []}
    # Without the command, the parser prints hocav's own help and exits 0 too: look for its usage line.
    adapt_help = subprocess.run([str(hocav), "adapt", "--help"], capture_output=True, text=True)
    if adapt_help.returncode == 0 and "Usage: hocav adapt" in adapt_help.stdout:
        for d in tools:
            tools[d].append(Hocav(hocav, args.threads, shlex.split(args.hocav_args)))
    else:
        print(f"skipping hocav: `{hocav} adapt --help` shows no adapt command (not there yet)")
    for d, binary in ((3, args.mmg3d), (2, args.mmg2d)):
        if binary and Path(binary).is_file():
            tools[d].append(Mmg(Path(binary).resolve(), shlex.split(args.mmg_args)))
        else:
            print(f"skipping mmg in {d}D: no binary given (--mmg{d}d)" if not binary else f"skipping {binary}: not found")
    return tools


def hocav_binary(path, script):
    """The hocav binary, resolved; exits with a message when it is absent (it measures every output)."""
    hocav = Path(path).resolve()
    if not hocav.is_file():
        sys.exit(f"{script}: no hocav binary at {hocav} (it measures every output)")
    return hocav


def parse_arguments():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0], formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--hocav", default="build/release/hocav", help="the hocav binary (build/release/hocav)")
    parser.add_argument("--hocav-args", default="", help="more arguments for `hocav adapt`, e.g. --hocav-args='--order 1'")
    parser.add_argument("--mmg3d", help="mmg3d_O3 binary (3D rows skipped without it)")
    parser.add_argument("--mmg2d", help="mmg2d_O3 binary (2D rows skipped without it)")
    parser.add_argument("--mmg-args", default="", help="more arguments for mmg, e.g. --mmg-args='-hgrad -1' (no gradation)")
    parser.add_argument("--data", default="../shared/data", help="the shared data folder (../shared/data)")
    parser.add_argument("--out", help="working folder for every input and output (a new temporary folder)")
    parser.add_argument("--threads", type=int, default=1, help="threads of `hocav adapt` (1)")
    parser.add_argument("--repeat", type=int, default=1, help="runs per adaptation; the median time is kept (1)")
    parser.add_argument("--cases", help="comma-separated subset of: " + ", ".join(c.name for c in case_list()))
    parser.add_argument("--json", help="also write the rows to this JSON file")
    return parser.parse_args()


def main():
    args = parse_arguments()
    hocav = hocav_binary(args.hocav, "adapt_compare")
    data = Path(args.data).resolve()
    out = Path(args.out).resolve() if args.out else Path(tempfile.mkdtemp(prefix="adapt-compare-"))
    wanted = set(args.cases.split(",")) if args.cases else None
    tools = available_tools(args, hocav)
    rows = []
    for case in case_list():
        if (wanted and case.name not in wanted) or not tools[case.dimension]:
            continue
        folder = out / case.name
        folder.mkdir(parents=True, exist_ok=True)
        for source, destination in case.copies:
            shutil.copyfile(data / source, folder / destination)
        for command in case.setup:
            run([hocav, *command], folder)
        for tool in tools[case.dimension]:
            print(f"{case.name}: {tool.name} ...", flush=True)
            try:
                mesh, seconds, rate, peak = adapt_case(case, tool, hocav, folder, args.repeat)
                rows.append(row(case, tool, measure(case, hocav, folder, mesh, tool.name), seconds, rate, peak))
            except CommandFailed as failure:
                print(f"{case.name}: {tool.name} failed: {failure}")
    print(f"\nfiles in {out}\n")
    print(markdown(rows))
    if args.json:
        Path(args.json).write_text(json.dumps(rows, indent=2) + "\n")


if __name__ == "__main__":
    main()
