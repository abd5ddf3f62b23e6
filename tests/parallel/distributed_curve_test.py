#!/usr/bin/python3
"""`mpirun -np N hocav curve` and `mpirun -np N hocav adapt --order 2` (docs/distributed.md §Curving)
against the serial commands on two small shells (curved boundary, P3 surrogate, implied metric): one
with a boundary layer, which the partitions cut between layers, and one without, which they cut
across the spheres (interfaces meet the boundary); and on a 2D annulus with a boundary layer.

With one process the output must be the serial one byte for byte. With 2 and 3 processes
(oversubscribed) every process reads its piece of the .meshb input and of its metric, and the parts
curve themselves and write the file in runs (§Curving from pieces, §Curving in the parts); from a
.msh input rank 0 reads the whole and scatters it (on 2 processes); a .msh output is written in runs
too (§A .msh in runs; once per case, on 2 processes); on 3 processes a .vtu is written in runs
beside the output and holds its cells, and so is a .vtu output alone (§A .vtu in runs). The output is
consistent, P2, certified (every element's min normalized Jacobian above the floor, as `hocav stats`
measures it), has the serial run's P1 mesh (its vertices, elements, facets and feature lines in their order) and
refs (a .msh's facets and lines in any order: it groups them by ref); its gain and mean normalized
Jacobian lie near the serial run's; the second round
curved the first round's interfaces, and the two rounds together reinserted each volume vertex once
(the serial run's count of cavities); no more boundary edges are left straight than in the serial
run (an interface edge on the boundary gets its proposal in a later round). The merge and the
writing in runs refuse parts that give an interface edge two different nodes, so a finished run has
every interface edge's node from the one rank that curved it.

`mpirun -np N hocav adapt --curved` curves the adapted mesh in its parts and runs the curved passes
there (§Curved passes in the parts): on 2 and 3 processes every part runs them with its interfaces
frozen, then the interfaces' regions move to one of their processes and run again (and on 3, the
regions' seams on rank 0); the output is valid, P2, certified, keeps the input's refs, and its
curved unit share and mean curved quality are within 1% of the serial run's. With one process it is
the serial output byte for byte.

Bad input read in pieces is refused as the serial command refuses it (exit 2, its message, no
output), though another process than rank 0 read the bad entity: an inverted element, a metric row
that is not positive definite; a missing metric file, which every process fails to read, is said
once.

Usage: /usr/bin/python3 distributed_curve_test.py <path-to-hocav>
Exits 77 (skipped) when hocav was built without MPI.
"""
import json
import os
import re
import subprocess
import sys

from mpi_test_support import (check_same_refs, check_valid, check_vtu_in_runs, completed, distributed_test, keywords, min_normalized_jacobian,
                              refused, run, same_bytes, stats)

FLOOR = 0.01
GAIN_TOLERANCE = 0.1  # relative, of the average gain
JACOBIAN_TOLERANCE = 0.05  # relative, of the mean normalized Jacobian


def report(work, name):
    with open(os.path.join(work, name)) as file:
        return json.load(file)


def straight_boundary_edges(hocav, work, name):
    """The boundary edges of a P2 .meshb whose node is the straight midpoint."""
    run([hocav, "convert", name + ".meshb", name + ".mesh"], work)
    with open(os.path.join(work, name + ".mesh")) as file:
        tokens = file.read().split()
    dimension = int(tokens[tokens.index("Dimension") + 1])
    at = tokens.index("Vertices")
    width = dimension + 1
    points = [[float(x) for x in tokens[at + 2 + width * k:at + 2 + width * k + dimension]] for k in range(int(tokens[at + 1]))]
    # Boundary facets: P2 edges (a, b, node, ref) in 2D, P2 triangles (a, b, c, ab, bc, ca, ref) in 3D.
    keyword, width = ("EdgesP2", 4) if dimension == 2 else ("TrianglesP2", 7)
    at = tokens.index(keyword)
    edges = {}
    for k in range(int(tokens[at + 1])):
        ids = [int(v) - 1 for v in tokens[at + 2 + width * k:at + 1 + width * (k + 1)]]
        sides = [(ids[0], ids[1], ids[2])] if dimension == 2 else [(ids[0], ids[1], ids[3]), (ids[1], ids[2], ids[4]), (ids[2], ids[0], ids[5])]
        for p, q, node in sides:
            edges[(min(p, q), max(p, q))] = max(abs(points[node][d] - (points[p][d] + points[q][d]) / 2) for d in range(dimension))
    return sum(1 for gap in edges.values() if gap < 1e-12)


def p1_mesh(hocav, work, name):
    """A P2 .meshb's P1 mesh: its vertices, and its elements, facets and (3D) feature lines (vertex ids
    as a set, ref), in order."""
    run([hocav, "convert", name + ".meshb", name + ".p1.mesh", "--order", "1"], work)
    mesh = keywords(os.path.join(work, name + ".p1.mesh"))
    out = {"Vertices": mesh["Vertices"]}
    for key in ("Tetrahedra", "Triangles", "Edges"):
        out[key] = [(tuple(sorted(r[:-1])), r[-1]) for r in mesh.get(key, [])]
    return out


def boundary_in_any_order(p1):
    """A P1 mesh of p1_mesh with its facets and lines sorted (its vertices and elements stay in order)."""
    elements = "Tetrahedra" if p1["Tetrahedra"] else "Triangles"
    return {key: rows if key in ("Vertices", elements) else sorted(rows) for key, rows in p1.items()}


def rounds(stderr):
    """(cavities, old interface vertices frozen again) per round, from the `distributed: round` lines."""
    found = re.findall(r"distributed: round (\d) of [23]: .*? (\d+) cavities(?:, (\d+) old interface vertices frozen again)?", stderr)
    return [(int(cavities), int(frozen or 0)) for _, cavities, frozen in found]


def check_against_serial(hocav, work, name, serial, serial_report):
    figures = stats(hocav, name + ".meshb", work)
    check_valid(figures, name)
    assert figures["order"] == "P2", f"{name}: {figures['order']}"
    minimum = min_normalized_jacobian(figures)
    assert minimum >= FLOOR, f"{name}: min normalized Jacobian {minimum} below the floor {FLOOR}"
    for key in ("vertices", "elements", "boundary facets"):
        assert figures[key] == serial[key], f"{name}: {key} {figures[key]}, serial {serial[key]}"
    check_same_refs(figures, serial, name)
    data = report(work, name + ".json")
    gain, serial_gain = data["average_gain"], serial_report["average_gain"]
    mean, serial_mean = data["normalized_jacobian"]["avg"], serial_report["normalized_jacobian"]["avg"]
    print(f"{name}: gain {gain:.4f} (serial {serial_gain:.4f}), mean normalized Jacobian {mean:.4f} (serial {serial_mean:.4f}), "
          f"min {minimum:.4f}")
    assert abs(gain - serial_gain) <= GAIN_TOLERANCE * serial_gain, f"{name}: average gain {gain} vs {serial_gain}"
    assert abs(mean - serial_mean) <= JACOBIAN_TOLERANCE * serial_mean, f"{name}: mean normalized Jacobian {mean} vs {serial_mean}"
    return data


def serial_error(hocav, work, args):
    """The message of a serial command that must fail with exit 2."""
    result = subprocess.run([hocav] + args, cwd=work, capture_output=True, text=True, check=False)
    assert result.returncode == 2, f"{args}: exit {result.returncode}"
    return result.stderr.strip()


def check_vtu_output(hocav, mpirun, work, given, name):
    """The same run to a .vtu alone (`-o`): the parts write it in runs (docs/distributed.md §A .vtu in
    runs), the cells of the Gamma output with their refs, and the report counts the mesh's elements
    and points (each vertex and node once) as the Gamma output's."""
    run(mpirun + ["-np", "3", hocav] + given + ["-o", name + "_alone.vtu", "--report", name + "_alone.json", "-q"], work)
    check_vtu_in_runs(hocav, work, name + "_alone.vtu", name + ".meshb", name + " to a .vtu", metric=False, jacobians=False)
    alone, beside = report(work, name + "_alone.json"), report(work, name + ".json")
    for key in ("elements", "points_before", "points_after"):
        assert alone[key] == beside[key], f"{name} to a .vtu: {key} {alone[key]}, to a Gamma file {beside[key]}"


def check_refusals(hocav, mpirun, work):
    """The last element of the cubed shell inverted, then repeating a vertex, then the last metric row
    made indefinite: each in the last process's run, refused as the serial run refuses it."""
    run([hocav, "convert", "cubed.meshb", "bad.mesh"], work)
    mesh = keywords(os.path.join(work, "bad.mesh"))
    last = mesh["Tetrahedra"][-1]
    with open(os.path.join(work, "bad.mesh")) as file:
        text = file.read()
    with open(os.path.join(work, "bad.mesh"), "w") as file:
        file.write(text.replace(" ".join(last), " ".join((last[1], last[0]) + last[2:])))
    run([hocav, "metric", "cubed.meshb", "--implied", "-o", "bad.sol"], work)
    serial = serial_error(hocav, work, ["curve", "bad.mesh", "--metric", "bad.sol", "-o", "x.meshb"])
    element = re.search(r"element (\d+) has non-positive P1 measure", serial)
    assert element and int(element.group(1)) == len(mesh["Tetrahedra"]), serial
    refused(mpirun, hocav, work, ["curve", "bad.mesh", "--metric", "bad.sol", "-o", "x.meshb"], "x.meshb",
            f"bad.mesh: inconsistent mesh: element {element.group(1)} has non-positive P1 measure")

    with open(os.path.join(work, "bad.mesh"), "w") as file:  # the last element's first vertex repeated
        file.write(text.replace(" ".join(last), " ".join((last[0], last[0]) + last[2:])))
    serial = serial_error(hocav, work, ["curve", "bad.mesh", "--metric", "bad.sol", "-o", "x.meshb"])
    words = serial.removeprefix("hocav: ")
    assert words == f"bad.mesh: Tetrahedra: repeats a vertex in element {len(mesh['Tetrahedra'])}", serial
    refused(mpirun, hocav, work, ["curve", "bad.mesh", "--metric", "bad.sol", "-o", "x.meshb"], "x.meshb", words)

    with open(os.path.join(work, "bad.sol")) as file:
        lines = file.read().rstrip().split("\n")
    row = [i for i, line in enumerate(lines) if len(line.split()) == 6][-1]
    lines[row] = "1 0 1 0 0 -1"
    with open(os.path.join(work, "bad.sol"), "w") as file:
        file.write("\n".join(lines) + "\n")
    serial = serial_error(hocav, work, ["curve", "cubed.meshb", "--metric", "bad.sol", "-o", "x.meshb"])
    words = serial.removeprefix("hocav: ")
    assert "is not positive definite" in words, serial
    refused(mpirun, hocav, work, ["curve", "cubed.meshb", "--metric", "bad.sol", "-o", "x.meshb"], "x.meshb", words)
    print(f"refused in pieces as serially: {words}")

    # A metric file every process fails to read: said once (by rank 0), not once per process.
    result = subprocess.run(mpirun + ["-np", "3", hocav, "curve", "cubed.meshb", "--metric", "missing.solb", "-o", "x.meshb"], cwd=work,
                            capture_output=True, text=True, check=False)
    said = [line for line in result.stderr.splitlines() if "missing.solb" in line]
    assert result.returncode == 2 and len(said) == 1, f"a missing metric: exit {result.returncode}, said {said}"


def check(hocav, mpirun, work):
    run([hocav, "generate", "cubed-shell-bl-inner", "--target-tets", "6000", "-o", "shell.meshb"], work)
    run([hocav, "generate", "cubed-shell", "--target-tets", "6000", "-o", "cubed.meshb"], work)
    run([hocav, "generate", "polar-annulus-bl-inner", "--target-triangles", "3000", "-o", "annulus.meshb"], work)
    seams_rounds = 0  # runs with a third round, the bands' seams on rank 0
    for case in ("shell", "cubed", "annulus"):
        run([hocav, "metric", case + ".meshb", "--implied", "-o", case + ".solb"], work)
        curve = ["curve", case + ".meshb", "--metric", case + ".solb", "--threads", "1", "-q"]
        serial_name = case + "1"
        run([hocav] + curve + ["-o", serial_name + ".meshb", "--report", serial_name + ".json"], work)
        serial = stats(hocav, serial_name + ".meshb", work)
        serial_report = report(work, serial_name + ".json")
        serial_cavities = serial_report["cavities"]["tried"]
        serial_straight = straight_boundary_edges(hocav, work, serial_name)

        run(mpirun + ["-np", "1", hocav] + curve + ["-o", "one.meshb"], work)
        assert same_bytes(work, "one.meshb", serial_name + ".meshb"), f"{case}: curve, mpirun -np 1: not the serial output byte for byte"

        serial_p1 = p1_mesh(hocav, work, serial_name)

        run([hocav, "convert", case + ".meshb", case + ".msh"], work)  # (the same vertices, in the same order)
        for processes, scheme in ((2, ""), (3, ""), (2, "scattered"), (2, "to-msh")):
            name = f"{case}{processes}{scheme}"
            given = curve[:-1] if scheme != "scattered" else ["curve", case + ".msh"] + curve[2:-1]
            output = name + (".msh" if scheme == "to-msh" else ".meshb")
            args = mpirun + ["-np", str(processes), hocav] + given + ["-o", output, "--report", name + ".json"]
            found = rounds(completed(args + (["--vtu", name + ".vtu"] if processes == 3 else []), work).stderr)
            if scheme == "to-msh":
                run([hocav, "convert", output, name + ".meshb"], work)
            if processes == 3:
                check_vtu_in_runs(hocav, work, name + ".vtu", name + ".meshb", name)
                check_vtu_output(hocav, mpirun, work, given, name)
            # (A third round, on rank 0, only where three or more parts met around an interface vertex.)
            assert len(found) in ((2,) if processes == 2 else (2, 3)), f"{name}: rounds {found}"
            seams_rounds += len(found) == 3
            data = check_against_serial(hocav, work, name, serial, serial_report)
            p1, expected = p1_mesh(hocav, work, name), serial_p1
            if scheme == "to-msh":  # (a .msh groups its facets and lines by ref: their order is not the Gamma file's)
                p1, expected = boundary_in_any_order(p1), boundary_in_any_order(serial_p1)
            assert p1 == expected, f"{name}: not the serial run's P1 mesh"
            cavities = [count for count, _ in found]
            frozen_again = [frozen for _, frozen in found[1:]]
            straight = straight_boundary_edges(hocav, work, name)
            print(f"{name}: cavities {' + '.join(map(str, cavities))} (serial {serial_cavities}), old interface vertices frozen "
                  f"again {frozen_again}, {straight} straight boundary edges (serial {serial_straight})")
            assert cavities[1] > 0, f"{name}: the second round curved nothing"
            assert frozen_again[-1] == 0, f"{name}: the last round froze {frozen_again[-1]} vertices again"
            assert sum(cavities) == data["cavities"]["tried"]
            assert sum(cavities) == serial_cavities, f"{name}: {cavities} cavities, serial {serial_cavities}"
            assert straight <= serial_straight, f"{name}: {straight} straight boundary edges, serial {serial_straight}"
    assert seams_rounds > 0, "no 3-process curving met its bands' seams: the third round went untested"

    check_refusals(hocav, mpirun, work)

    adapt = ["adapt", "shell.meshb", "--metric", "shell.solb", "--order", "2", "--threads", "1", "-q"]
    run([hocav] + adapt + ["-o", "adapted.meshb"], work)
    run(mpirun + ["-np", "1", hocav] + adapt + ["-o", "adapted1.meshb"], work)
    assert same_bytes(work, "adapted1.meshb", "adapted.meshb"), "adapt --order 2, mpirun -np 1: not the serial output byte for byte"
    run(mpirun + ["-np", "2", hocav] + adapt + ["-o", "adapted2.meshb"], work)
    figures = stats(hocav, "adapted2.meshb", work)
    check_valid(figures, "adapted2.meshb")
    assert figures["order"] == "P2", figures["order"]
    assert min_normalized_jacobian(figures) >= FLOOR, f"adapted2: min normalized Jacobian {figures['normalized Jacobian']}"
    check_same_refs(figures, stats(hocav, "shell.meshb", work), "adapted2")

    check_curved_passes_in_parts(hocav, mpirun, work, adapt[:-1] + ["--curved"])


def curved_pass_rounds(stderr):
    """(elements, elements moved, passes) per round of the curved passes, from their `distributed:` lines."""
    found = re.findall(r"distributed: curved passes, round (\d) \(.*?\): (\d+) elements, (\d+) moved to another process, (\d+) passes", stderr)
    return {int(number): (int(elements), int(moved), int(passes)) for number, elements, moved, passes in found}


def check_curved_passes_in_parts(hocav, mpirun, work, adapt):
    """`adapt --curved` under mpirun: the parts curve the adapted mesh and run the curved passes
    (docs/distributed.md §Curved passes in the parts); with one process, the serial run."""
    run([hocav] + adapt + ["-q", "-o", "curved1.meshb", "--report", "curved1.json"], work)
    run(mpirun + ["-np", "1", hocav] + adapt + ["-q", "-o", "curved1np.meshb"], work)
    assert same_bytes(work, "curved1np.meshb", "curved1.meshb"), "adapt --curved, mpirun -np 1: not the serial output byte for byte"
    serial = report(work, "curved1.json")["curved_measures"]
    for processes in (2, 3):
        name = f"curved{processes}"
        result = completed(mpirun + ["-np", str(processes), hocav] + adapt + ["-o", name + ".meshb", "--report", name + ".json"], work)
        found = curved_pass_rounds(result.stderr)
        print(f"adapt --curved on {processes} processes: rounds (elements, moved, passes) {found}")
        assert 1 in found and found[1][1] == 0 and found[1][2] > 0, f"{name}: the first round in every part: {found}"
        assert 2 in found and found[2][1] > 0 and found[2][2] > 0, f"{name}: the interfaces' regions moved and ran: {found}"
        assert processes == 3 or 3 not in found, f"{name}: two parts leave no seams, yet a third round ran: {found}"
        figures = stats(hocav, name + ".meshb", work)
        check_valid(figures, name)
        assert figures["order"] == "P2", figures["order"]
        assert min_normalized_jacobian(figures) >= FLOOR, f"{name}: min normalized Jacobian {figures['normalized Jacobian']}"
        check_same_refs(figures, stats(hocav, "shell.meshb", work), name)
        measured = report(work, name + ".json")
        assert measured["curved_passes"]["passes"], f"{name}: the report has no curved passes"
        assert measured["output_elements"] == int(figures["elements"].split()[0]), f"{name}: report {measured['output_elements']}, file {figures['elements']}"
        curved = measured["curved_measures"]
        print(f"{name}: curved unit share {curved['unit_share']:.4f} (serial {serial['unit_share']:.4f}), mean quality "
              f"{curved['quality_mean']:.4f} (serial {serial['quality_mean']:.4f})")
        assert curved["unit_share"] >= serial["unit_share"] - 0.01, f"{name}: curved unit share {curved} against the serial {serial}"
        assert curved["quality_mean"] >= 0.99 * serial["quality_mean"], f"{name}: curved mean quality {curved} against {serial}"

if __name__ == "__main__":
    sys.exit(distributed_test(check))
