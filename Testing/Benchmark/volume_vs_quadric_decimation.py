#!/usr/bin/python3
# SPDX-License-Identifier: BSD-3-Clause
"""Volume Triangle Collapse against vtkQuadricDecimation, side by side in one run.

Runs the shared benchmark kit's compare.py on each input and reduction with our CLI as an extra
method, next to vtkQuadricDecimation and, for reference, meshoptimizer and CGAL's
Garland-Heckbert collapse. Prints a markdown table with, per case, the ratios ours /
vtkQuadricDecimation of the enclosed-volume change (closed inputs; changes under 0.01 % count
as 0.01 %), of metro's mean and Hausdorff distances and of the time, the share of triangles
with a minimum angle under 10 degrees, whether a closed input stays a closed 2-manifold, and
the time ratio to meshoptimizer; then the geometric means.

  /usr/bin/python3 Testing/Benchmark/volume_vs_quadric_decimation.py --kit BENCH_DIR \\
      --cli build/bin/meshsimplify [--reduction 0.7 0.95] [--repeat 3] --workdir DIR \\
      [--out results.md] MESH [MESH ...]
"""
import argparse
import os

from kitrun import add_common_arguments, finish, metric, run_cases

PEERS = "^vtk_quadric$|^meshopt$|^cgal_gh$"


def volume_change(row):
    change = (row.get("metro") or {}).get("volume_change_pct")
    return None if change is None else max(abs(change), 0.01)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    add_common_arguments(ap, [0.7, 0.95])
    a = ap.parse_args()

    ours = "%s --method volume --target-triangles {target} --threads %d --repeat {repeat} --json {in_vtp} {out_vtp}" % (
        os.path.abspath(a.cli), a.threads)
    cases = run_cases(a.meshes, a.kit, a.bin, ours, PEERS, a.reduction, a.repeat, a.workdir)

    lines = ["| mesh | red. | target | ours tris | vol % ours | vol % QD | vol ratio | mean % ours | mean % QD "
             "| mean ratio | H % ours | H % QD | H ratio | <10° % ours | <10° % QD | closed | ms ours | ms QD "
             "| ms meshopt | time / QD | time / meshopt |",
             "|---" * 21 + "|"]
    ratios = {"volume change ratio (ours / vtkQuadricDecimation)": [], "mean ratio (ours / vtkQuadricDecimation)": [],
              "Hausdorff ratio (ours / vtkQuadricDecimation)": [], "time ratio (ours / vtkQuadricDecimation)": [],
              "time ratio (ours / meshoptimizer)": []}
    volume_key, mean_key, h_key, qd_key, mo_key = ratios
    problems = []
    for name, info, reduction, target, rows in cases:
        mine, qd, mo = rows.get("ours"), rows.get("vtk_quadric"), rows.get("meshopt", {})
        if not mine or not qd or mine.get("error") or qd.get("error"):
            problems.append("%s %.2f: a method failed" % (name, reduction))
            continue
        out = mine["metro"]["b"]
        if abs(out["tris"] - target) > 0.01 * target:
            problems.append("%s %.2f: %d triangles, more than 1 %% off the target %d" % (name, reduction, out["tris"], target))
        closed_input = info.get("closed", False)
        volume = None
        if closed_input:
            volume = volume_change(mine) / volume_change(qd)
            ratios[volume_key].append(volume)
            if not out["closed"]:
                problems.append("%s %.2f: the closed input came out open (%d boundary, %d non-manifold edges)"
                                % (name, reduction, out["boundary_edges"], out["nonmanifold_edges"]))
        mean = metric(mine, "mean_pct") / metric(qd, "mean_pct")
        hausdorff = metric(mine, "max_pct") / metric(qd, "max_pct")
        ratios[mean_key].append(mean)
        ratios[h_key].append(hausdorff)
        to_qd = mine["time_ms"] / qd["time_ms"]
        ratios[qd_key].append(to_qd)
        to_mo = mine["time_ms"] / mo["time_ms"] if mo.get("time_ms") else None
        if to_mo:
            ratios[mo_key].append(to_mo)
        angles, angles_qd = out["min_angle_lt10_pct"], qd["metro"]["b"]["min_angle_lt10_pct"]
        if angles > angles_qd + 1.0:
            problems.append("%s %.2f: %.1f %% of triangles under 10 degrees, vtkQuadricDecimation %.1f %%"
                            % (name, reduction, angles, angles_qd))
        lines.append("| %s | %.2f | %d | %d | %s | %s | %s | %.4f | %.4f | %.2f | %.3f | %.3f | %.2f | %.1f | %.1f | %s "
                     "| %.1f | %.1f | %s | %.3f | %s |" % (
                         name, reduction, target, out["tris"],
                         "%.3f" % mine["metro"]["volume_change_pct"] if closed_input else "-",
                         "%.3f" % qd["metro"]["volume_change_pct"] if closed_input else "-",
                         "%.2f" % volume if volume else "-",
                         metric(mine, "mean_pct"), metric(qd, "mean_pct"), mean,
                         metric(mine, "max_pct"), metric(qd, "max_pct"), hausdorff,
                         angles, angles_qd,
                         ("yes" if out["closed"] else "NO") if closed_input else "(open input)",
                         mine["time_ms"], qd["time_ms"],
                         "%.1f" % mo["time_ms"] if mo.get("time_ms") else "-", to_qd,
                         "%.2f" % to_mo if to_mo else "-"))
    finish(lines, ratios, problems, a.out)

if __name__ == "__main__":
    main()
