"""Side by side with what a user would pick instead: gmsh's high-order optimizer.

The same sphere-shell mesh (gmsh, OpenCASCADE, radii 0.5 and 1, isotropic size h) is made P2 two
ways, on the same machine in the same run:
  gmsh   setOrder(2) (mid nodes of boundary edges placed on the CAD spheres), then
         optimize("HighOrder") (gmsh's direct high-order optimizer, its default thresholds);
  hocav  `hocav metric --surface 0.01,0.1 --gradation 1.5` then `hocav curve` (P3 surrogate of the
         boundary, every volume vertex reinserted by the P2 cavity operator, one thread).
Both outputs are measured by the same tool, gmsh's AnalyseMeshQuality plugin (JacobianDeterminant:
min J / max J per element, the scaled Jacobian); hocav's own certified figures are printed beside.
Times: gmsh's setOrder and optimize calls (wall clock); hocav's curving time without I/O from its
report, and the wall time of the whole `hocav curve` process (reading and writing included).

Usage: /usr/bin/python3 bench/gmsh_compare.py PATH_TO_HOCAV [h ...]   (default h: 0.1 0.05)
"""
import json
import os
import subprocess
import sys
import tempfile
import time

import gmsh

R_IN, R_OUT = 0.5, 1.0


def start_gmsh():
    gmsh.initialize(readConfigFiles=False)
    gmsh.option.setNumber("General.Terminal", 0)
    gmsh.option.setNumber("General.NumThreads", 1)
    gmsh.option.setNumber("Mesh.RandomSeed", 1)


def min_scaled_jacobian(dimension=3):
    """Smallest min J / max J over the elements of the current model, by AnalyseMeshQuality."""
    gmsh.plugin.setNumber("AnalyseMeshQuality", "JacobianDeterminant", 1)
    gmsh.plugin.setNumber("AnalyseMeshQuality", "CreateView", 1)
    gmsh.plugin.setNumber("AnalyseMeshQuality", "DimensionOfElements", dimension)
    gmsh.plugin.run("AnalyseMeshQuality")
    view = gmsh.view.getTags()[-1]
    _, _, data, _, _ = gmsh.view.getModelData(view, 0)
    return min(d[0] for d in data), len(data)


def gmsh_side(h, p1_path):
    """Meshes the shell, writes the P1 mesh for hocav, then curves it with gmsh and measures."""
    start_gmsh()
    occ = gmsh.model.occ
    outer, inner = occ.addSphere(0, 0, 0, R_OUT), occ.addSphere(0, 0, 0, R_IN)
    occ.cut([(3, outer)], [(3, inner)])
    occ.synchronize()
    gmsh.model.addPhysicalGroup(3, [tag for _, tag in gmsh.model.getEntities(3)], 1)
    for _, tag in gmsh.model.getEntities(2):
        box = gmsh.model.getBoundingBox(2, tag)
        gmsh.model.addPhysicalGroup(2, [tag], 1 if abs(box[3] - R_IN) < abs(box[3] - R_OUT) else 2)
    gmsh.option.setNumber("Mesh.MeshSizeMin", h)
    gmsh.option.setNumber("Mesh.MeshSizeMax", h)
    gmsh.model.mesh.generate(3)
    gmsh.write(p1_path)
    start = time.perf_counter()
    gmsh.model.mesh.setOrder(2)
    set_order_seconds = time.perf_counter() - start
    before, _ = min_scaled_jacobian()
    start = time.perf_counter()
    gmsh.model.mesh.optimize("HighOrder")
    optimize_seconds = time.perf_counter() - start
    after, elements = min_scaled_jacobian()
    gmsh.finalize()
    return {"elements": elements, "set_order_seconds": set_order_seconds, "optimize_seconds": optimize_seconds,
            "min_scaled_jacobian_after_set_order": before, "min_scaled_jacobian": after}


def hocav_side(hocav, p1_path, work):
    metric, curved, report = (os.path.join(work, name) for name in ("shell.solb", "shell-p2.msh", "report.json"))
    subprocess.run([hocav, "metric", p1_path, "--surface", "0.01,0.1", "--gradation", "1.5", "-o", metric],
                   check=True, stdout=subprocess.DEVNULL)
    start = time.perf_counter()
    subprocess.run([hocav, "curve", p1_path, "--metric", metric, "-o", curved, "--report", report, "-q"], check=True)
    wall_seconds = time.perf_counter() - start
    with open(report) as file:
        figures = json.load(file)
    start_gmsh()
    gmsh.open(curved)
    measured, elements = min_scaled_jacobian()
    gmsh.finalize()
    return {"elements": elements, "seconds_without_io": figures["seconds_without_io"], "process_seconds": wall_seconds,
            "min_scaled_jacobian": measured, "certified_min_scaled_jacobian": figures["scaled_jacobian"]["min"],
            "certified_min_normalized_jacobian": figures["normalized_jacobian"]["min"],
            "average_gain": figures["average_gain"], "max_gain": figures["max_gain"]}


def main():
    hocav = sys.argv[1]
    sizes = [float(h) for h in sys.argv[2:]] or [0.1, 0.05]
    print("| h | tets | gmsh setOrder(2) | gmsh optimize(\"HighOrder\") | gmsh min scaled J (after setOrder / after optimize) "
          "| hocav curve, no I/O | hocav curve process | hocav min scaled J (gmsh's measure / hocav's certified) "
          "| hocav min norm. J | hocav avg / max gain |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    for h in sizes:
        with tempfile.TemporaryDirectory() as work:
            p1_path = os.path.join(work, "shell.msh")
            theirs = gmsh_side(h, p1_path)
            ours = hocav_side(hocav, p1_path, work)
            assert theirs["elements"] == ours["elements"], (theirs["elements"], ours["elements"])
            print(f"| {h} | {ours['elements']:,} | {theirs['set_order_seconds']:.2f} s | {theirs['optimize_seconds']:.2f} s "
                  f"| {theirs['min_scaled_jacobian_after_set_order']:.3g} / {theirs['min_scaled_jacobian']:.3g} "
                  f"| {ours['seconds_without_io']:.2f} s | {ours['process_seconds']:.2f} s "
                  f"| {ours['min_scaled_jacobian']:.3g} / {ours['certified_min_scaled_jacobian']:.3g} "
                  f"| {ours['certified_min_normalized_jacobian']:.3g} "
                  f"| {100 * ours['average_gain']:.2f}% / {100 * ours['max_gain']:.0f}% |", flush=True)


main()
