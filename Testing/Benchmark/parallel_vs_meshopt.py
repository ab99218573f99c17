#!/usr/bin/python3
# SPDX-License-Identifier: BSD-3-Clause
"""Parallel Decimation against meshoptimizer and vtkQuadricDecimation, side by side in one run.

Runs the shared benchmark kit's compare.py on each input with our CLI twice as extra methods
(--threads 1 and --threads 2), next to meshoptimizer's meshopt_simplify and
vtkQuadricDecimation. With --large, also on armadillo Loop-subdivided three times
(vtkLoopSubdivisionFilter, about 3.3 million triangles), and measures the peak resident memory
of meshsimplify on it (/usr/bin/time -v, reading included). Prints a markdown table: per case
the time with 1 and 2 threads and their ratios to meshoptimizer, the speed-up and the parallel
fraction it implies (Amdahl: p = 2 (1 - 1/S) for 2 threads), and metro's RMS and Hausdorff
distances as ratios to vtkQuadricDecimation's; then the geometric means.

  /usr/bin/python3 Testing/Benchmark/parallel_vs_meshopt.py --kit BENCH_DIR \\
      --cli build/bin/meshsimplify [--reduction 0.9] [--repeat 3] --workdir DIR \\
      [--large ARMADILLO] [--out results.md] MESH [MESH ...]
"""
import argparse
import os
import re
import subprocess
import sys

from kitrun import add_common_arguments, finish, metric, run_cases

PEERS = "^vtk_quadric$|^meshopt$"


def loop_subdivided(armadillo, workdir, levels=3):
    """armadillo subdivided `levels` times by vtkLoopSubdivisionFilter, written as PLY."""
    path = os.path.join(workdir, "armadillo_loop%d.ply" % levels)
    if not os.path.exists(path):
        script = (
            "import sys\n"
            "from vtkmodules.vtkFiltersModeling import vtkLoopSubdivisionFilter\n"
            "from vtkmodules.vtkIOPLY import vtkPLYWriter\n"
            "from vtkmodules.vtkCommonDataModel import vtkPolyData, vtkCellArray\n"
            "from vtkmodules.vtkCommonCore import vtkPoints\n"
            "lines = [l for l in open(sys.argv[1]) if l.strip() and not l.startswith('#')]\n"
            "nv, nf = map(int, lines[1].split()[:2])\n"
            "points = vtkPoints()\n"
            "for l in lines[2:2 + nv]: points.InsertNextPoint(*map(float, l.split()[:3]))\n"
            "cells = vtkCellArray()\n"
            "for l in lines[2 + nv:2 + nv + nf]: cells.InsertNextCell(3, [int(x) for x in l.split()[1:4]])\n"
            "mesh = vtkPolyData(); mesh.SetPoints(points); mesh.SetPolys(cells)\n"
            "loop = vtkLoopSubdivisionFilter(); loop.SetInputData(mesh); loop.SetNumberOfSubdivisions(%d)\n"
            "writer = vtkPLYWriter(); writer.SetInputConnection(loop.GetOutputPort())\n"
            "writer.SetFileName(sys.argv[2]); writer.SetFileTypeToBinary(); writer.Write()\n" % levels)
        subprocess.run(["/usr/bin/python3", "-c", script, armadillo, path], check=True)
    return path


def peak_memory(cli, mesh, workdir, reduction, threads):
    """Peak resident memory (bytes) of one meshsimplify run, reading and writing included."""
    out = os.path.join(workdir, "memory_run.ply")
    run = subprocess.run(["/usr/bin/time", "-v", cli, "--method", "parallel", "--reduction", str(reduction),
                          "--threads", str(threads), mesh, out], capture_output=True, text=True, check=True)
    kilobytes = int(re.search(r"Maximum resident set size \(kbytes\): (\d+)", run.stderr).group(1))
    return kilobytes * 1024


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    add_common_arguments(ap, [0.9])
    ap.add_argument("--large", help="armadillo .off to Loop-subdivide into the large mesh")
    a = ap.parse_args()
    os.makedirs(a.workdir, exist_ok=True)

    meshes = list(a.meshes)
    large = loop_subdivided(a.large, a.workdir) if a.large else None
    if large:
        meshes.append(large)
    cli = os.path.abspath(a.cli)
    template = "%s --method parallel --target-triangles {target} --threads %d --repeat {repeat} --json {in_vtp} {out_vtp}"
    ours = {"ours1": template % (cli, 1), "ours2": template % (cli, 2)}
    cases = run_cases(meshes, a.kit, a.bin, ours, PEERS, a.reduction, a.repeat, a.workdir)

    lines = ["| mesh | input tris | target | ours tris | ms 1 thread | ms 2 threads | ms meshopt | 1T / meshopt "
             "| 2T / meshopt | speed-up | parallel fraction | RMS ratio | H ratio | RMS ratio meshopt | closed |",
             "|---" * 15 + "|"]
    ratios = {"1 thread / meshoptimizer time": [], "2 threads / meshoptimizer time": [],
              "RMS ratio (ours / vtkQuadricDecimation)": [], "Hausdorff ratio (ours / vtkQuadricDecimation)": [],
              "RMS ratio (meshoptimizer / vtkQuadricDecimation)": []}
    one_key, two_key, rms_key, h_key, mo_rms_key = ratios
    problems = []
    for name, info, reduction, target, rows in cases:
        one, two, qd, mo = rows.get("ours1"), rows.get("ours2"), rows.get("vtk_quadric"), rows.get("meshopt")
        if not one or not two or one.get("error") or two.get("error"):
            problems.append("%s %.2f: our method failed" % (name, reduction))
            continue
        out = two["metro"]["b"]
        if abs(out["tris"] - target) > 0.02 * target:
            problems.append("%s: %d triangles, more than 2 %% off the target %d" % (name, out["tris"], target))
        if one["metro"]["b"]["tris"] != out["tris"]:
            problems.append("%s: 1 and 2 threads gave different counts" % name)
        speedup = one["time_ms"] / two["time_ms"]
        fraction = 2.0 * (1.0 - 1.0 / speedup)
        to_mo1 = one["time_ms"] / mo["time_ms"] if mo and mo.get("time_ms") else None
        to_mo2 = two["time_ms"] / mo["time_ms"] if mo and mo.get("time_ms") else None
        if to_mo1:
            ratios[one_key].append(to_mo1)
            ratios[two_key].append(to_mo2)
        rms = hausdorff = mo_rms = None
        if qd and not qd.get("error") and metric(qd, "rms_pct"):
            rms = metric(two, "rms_pct") / metric(qd, "rms_pct")
            hausdorff = metric(two, "max_pct") / metric(qd, "max_pct")
            ratios[rms_key].append(rms)
            ratios[h_key].append(hausdorff)
            if mo and metric(mo, "rms_pct"):
                mo_rms = metric(mo, "rms_pct") / metric(qd, "rms_pct")
                ratios[mo_rms_key].append(mo_rms)
        closed_input = info.get("closed", False)
        if closed_input and not out["closed"]:
            problems.append("%s: the closed input came out open" % name)
        f = lambda v, fmt="%.2f": fmt % v if v is not None else "-"
        lines.append("| %s | %d | %d | %d | %.1f | %.1f | %s | %s | %s | %.2f | %.2f | %s | %s | %s | %s |" % (
            name, info.get("tris", 0), target, out["tris"], one["time_ms"], two["time_ms"],
            f(mo.get("time_ms") if mo else None, "%.1f"), f(to_mo1), f(to_mo2), speedup, fraction,
            f(rms), f(hausdorff), f(mo_rms),
            ("yes" if out["closed"] else "NO") if closed_input else "(open input)"))
    if large:
        for threads in (1, 2):
            peak = peak_memory(cli, large, a.workdir, a.reduction[0], threads)
            triangles = next(info.get("tris", 0) for n, info, *_ in cases if n == os.path.splitext(os.path.basename(large))[0])
            problems.append("peak resident memory of meshsimplify on %s, %d thread(s): %.0f MB, %.0f bytes per input triangle"
                            % (os.path.basename(large), threads, peak / 2**20, peak / max(1, triangles)))
    finish(lines, ratios, problems, a.out)


if __name__ == "__main__":
    main()
