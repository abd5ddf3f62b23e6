"""How far a distributed adaptation lands from the serial one, over several partitions.

`mpirun -np N hocav adapt` cuts the mesh with Scotch; the run's figures depend on where the cuts
fall, and a single run says little (docs/distributed.md, "How fragile the figures are"). This script
runs each case serially once, then on each process count with each partitioner seed
(`--partition-seed`), and prints per case and process count the gaps to the serial run: the unit
share and the mean quality (relative, the issue's 1%; the median and the farthest over the seeds),
the minimum quality (median and lowest), the largest share of elements below 0.1, and how many
seeds stay within 1% on both.

Cases (the input is `hocav generate cube --h 0.1`, about 6,000 tetrahedra):
  small  the analytic "linear" metric evaluated at every new vertex (h-min 0.001)
  fine   the same metric as a .solb at the input's vertices (the test's fine case)
  face   the .solb with h-min 0.00025 (about 215,000 tetrahedra; a minute per run)

Without mpirun, or with a hocav built without MPI (its reports then have no distributed
iterations), it says so and exits 0.

    /usr/bin/python3 bench/distributed_draws.py --hocav build/release/hocav --cases small,fine \\
        --processes 2,3,4 --seeds 0,2,4,7,12345
"""
import argparse
import json
import os
import shutil
import statistics
import subprocess
import sys
import tempfile

CASES = {
    "small": {"metric_args": None, "source": ["--analytic", "linear"]},
    "fine": {"metric_args": ["--analytic", "linear"], "source": None},
    "face": {"metric_args": ["--analytic", "linear", "--h-min", "0.00025"], "source": None},
}
TOLERANCE = 0.01


def run(command, folder):
    result = subprocess.run(command, cwd=folder, capture_output=True, text=True)
    if result.returncode != 0:
        sys.exit(f"failed: {' '.join(command)}\n{result.stderr[-2000:]}")


def figures(folder, report):
    with open(os.path.join(folder, report)) as f:
        r = json.load(f)
    return {
        "unit": r["edge_length"]["unit_share"],
        "mean": r["quality"]["mean"],
        "min": r["quality"]["min"],
        "below": r["quality"]["share_below_0_1"],
        "distributed": bool(r.get("distributed_iterations")),
    }


def adapt_args(args, case, folder):
    spec = CASES[case]
    if spec["source"]:
        return spec["source"]
    metric = f"{case}.solb"
    if not os.path.exists(os.path.join(folder, metric)):
        run([args.hocav, "metric", "cube.meshb", *spec["metric_args"], "-o", metric], folder)
    return ["--metric", metric]


def adapt(args, case, folder, tag, processes=None, seed=0):
    command = [args.hocav, "adapt", "cube.meshb", *adapt_args(args, case, folder), "-o", f"{tag}.meshb", "--order", "1",
               "--threads", str(args.threads), "--report", f"{tag}.json", "-q"]
    if processes:
        command = [args.mpirun, "--oversubscribe", "-np", str(processes), *command, "--partition-seed", str(seed)]
    run(command, folder)
    return figures(folder, f"{tag}.json")


def relative_gap(value, serial):
    return (value - serial) / serial


def summary(case, processes, serial, draws):
    unit = [relative_gap(d["unit"], serial["unit"]) for d in draws]
    mean = [relative_gap(d["mean"], serial["mean"]) for d in draws]
    within = sum(abs(u) <= TOLERANCE and abs(m) <= TOLERANCE for u, m in zip(unit, mean))
    worst = lambda values: max(values, key=abs)  # the farthest from the serial run, either way
    return (f"| {case} | {processes} | {statistics.median(unit):+.2%} / {worst(unit):+.2%} | "
            f"{statistics.median(mean):+.2%} / {worst(mean):+.2%} | {statistics.median(d['min'] for d in draws):.3f} / "
            f"{min(d['min'] for d in draws):.3f} | {max(d['below'] for d in draws):.2%} | {within} of {len(draws)} |")


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--hocav", default="build/release/hocav")
    parser.add_argument("--mpirun", default=os.environ.get("HOCAV_MPIEXEC") or "mpirun")
    parser.add_argument("--cases", default="small,fine", help="of: " + ", ".join(CASES))
    parser.add_argument("--processes", default="2,3,4")
    parser.add_argument("--seeds", default="0,2,4,7,12345", help="partitioner seeds (some seeds give the same cuts)")
    parser.add_argument("--threads", type=int, default=1)
    parser.add_argument("--out", help="working folder (a new temporary one by default)")
    args = parser.parse_args()
    args.hocav = os.path.abspath(args.hocav)
    if shutil.which(args.mpirun) is None:
        print(f"skipping: no {args.mpirun}")
        return
    os.environ.setdefault("OMPI_ALLOW_RUN_AS_ROOT", "1")
    os.environ.setdefault("OMPI_ALLOW_RUN_AS_ROOT_CONFIRM", "1")
    folder = args.out or tempfile.mkdtemp(prefix="hocav-draws-")
    os.makedirs(folder, exist_ok=True)
    run([args.hocav, "generate", "cube", "--h", "0.1", "-o", "cube.meshb"], folder)
    rows = []
    for case in args.cases.split(","):
        serial = adapt(args, case, folder, f"{case}-serial")
        print(f"{case}, serial: unit {serial['unit']:.2%}, mean quality {serial['mean']:.3f}, min {serial['min']:.3f}", flush=True)
        for processes in map(int, args.processes.split(",")):
            draws = [adapt(args, case, folder, f"{case}-{processes}-{seed}", processes, int(seed)) for seed in args.seeds.split(",")]
            if not all(d["distributed"] for d in draws):
                print("skipping: hocav was built without MPI (its reports have no distributed iterations)")
                return
            rows.append(summary(case, processes, serial, draws))
            print(rows[-1], flush=True)
    print("\n| case | processes | unit share gap, median / farthest | mean quality gap, median / farthest | min quality, median / "
          "lowest | below 0.1, largest | seeds within 1% |")
    print("|---|---|---|---|---|---|---|")
    print("\n".join(rows))
    print(f"\nfiles in {folder}")


if __name__ == "__main__":
    main()
