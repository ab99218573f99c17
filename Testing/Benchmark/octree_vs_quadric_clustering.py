#!/usr/bin/python3
# SPDX-License-Identifier: BSD-3-Clause
"""Octree Vertex Clustering against vtkQuadricClustering, side by side in one run.

Runs the shared benchmark kit's compare.py on each input and reduction with our CLI as an extra
method, next to vtkQuadricClustering (its NumberOfDivisions searched for the triangle count
closest to the target; the table checks it lands within +-5 % of ours) and, for reference,
vtkQuadricDecimation and meshoptimizer. Errors are measured by the kit's metro. Prints a
markdown table of per-case ratios (ours / vtkQuadricClustering) and their geometric means.

  /usr/bin/python3 Testing/Benchmark/octree_vs_quadric_clustering.py --kit BENCH_DIR \
      --cli build/bin/meshsimplify [--reduction 0.9 0.98] [--repeat 3] [--threads 0] \
      [--out results.md] MESH [MESH ...]

BENCH_DIR is the benchmark kit (compare.py, and metro built in BENCH_DIR/build or --bin).
"""
import argparse
import json
import math
import os
import subprocess
import sys
import tempfile

PEERS = "vtk_qclustering|^meshopt$|^vtk_quadric$"


def geometric_mean(values):
    values = [v for v in values if v is not None and v > 0]
    return math.exp(sum(math.log(v) for v in values) / len(values)) if values else float("nan")


def rows_by_method(run):
    return {row["method"]: row for row in run["rows"]}


def metric(row, key):
    metro = row.get("metro") or {}
    return (metro.get("symmetric") or {}).get(key)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("meshes", nargs="+")
    ap.add_argument("--kit", required=True, help="the shared benchmark kit folder (compare.py)")
    ap.add_argument("--bin", help="folder with the kit's metro and peers (default KIT/build)")
    ap.add_argument("--cli", required=True, help="our meshsimplify")
    ap.add_argument("--reduction", type=float, nargs="+", default=[0.9, 0.98])
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--threads", type=int, default=0, help="--threads for our CLI (0: all cores)")
    ap.add_argument("--workdir", default=tempfile.mkdtemp(prefix="octree-bench-"))
    ap.add_argument("--peers", default=PEERS, help="regex of the kit's methods to run (default: %(default)s)")
    ap.add_argument("--out", help="also write the markdown here")
    a = ap.parse_args()

    ours = "%s --method octree --target-triangles {target} --threads %d --repeat {repeat} --json {in_vtp} {out_vtp}" % (
        os.path.abspath(a.cli), a.threads)
    cases = []
    for mesh in a.meshes:
        name = os.path.splitext(os.path.basename(mesh))[0]
        result = os.path.join(a.workdir, name + ".json")
        command = ["/usr/bin/python3", os.path.join(a.kit, "compare.py"), mesh,
                   "--reduction", *map(str, a.reduction), "--repeat", str(a.repeat),
                   "--only", a.peers + "|^ours$", "--extra", "ours=" + ours,
                   "--workdir", os.path.join(a.workdir, name), "--json", result]
        if a.bin:
            command += ["--bin", a.bin]
        print("running", name, file=sys.stderr)
        subprocess.run(command, check=True, stdout=subprocess.DEVNULL)
        with open(result) as f:
            document = json.load(f)
        for run in document["runs"]:
            rows = rows_by_method(run)
            cases.append((name, run["reduction"], run["target"], rows))

    lines = ["| mesh | reduction | target | ours tris | qclust tris | ours H % | qclust H % | H ratio "
             "| ours RMS % | qclust RMS % | RMS ratio | ours ms | qclust ms | time ratio | QEM H % | QEM RMS % "
             "| meshopt ms |",
             "|---" * 17 + "|"]
    ratios = {"H": [], "RMS": [], "time": []}
    problems = []
    for name, reduction, target, rows in cases:
        ours_row, qc = rows.get("ours"), rows.get("vtk_qclustering")
        qem, mo = rows.get("vtk_quadric", {}), rows.get("meshopt", {})
        if not ours_row or not qc or ours_row.get("error") or qc.get("error"):
            problems.append("%s %.2f: a method failed" % (name, reduction))
            continue
        ot, qt = ours_row["metro"]["b"]["tris"], qc["metro"]["b"]["tris"]
        if abs(qt - ot) > 0.05 * ot:
            problems.append("%s %.2f: vtkQuadricClustering has %d triangles, not within 5 %% of our %d"
                            % (name, reduction, qt, ot))
        if abs(ot - target) > 0.03 * target:
            problems.append("%s %.2f: %d triangles, more than 3 %% off the target %d" % (name, reduction, ot, target))
        h = metric(ours_row, "max_pct") / metric(qc, "max_pct")
        rms = metric(ours_row, "rms_pct") / metric(qc, "rms_pct")
        t = ours_row["time_ms"] / qc["time_ms"]
        ratios["H"].append(h)
        ratios["RMS"].append(rms)
        ratios["time"].append(t)
        lines.append("| %s | %.2f | %d | %d | %d | %.3f | %.3f | %.2f | %.4f | %.4f | %.2f | %.1f | %.1f | %.2f | %s | %s | %s |" % (
            name, reduction, target, ot, qt, metric(ours_row, "max_pct"), metric(qc, "max_pct"), h,
            metric(ours_row, "rms_pct"), metric(qc, "rms_pct"), rms, ours_row["time_ms"], qc["time_ms"], t,
            "%.3f" % metric(qem, "max_pct") if qem.get("metro") else "-",
            "%.4f" % metric(qem, "rms_pct") if qem.get("metro") else "-",
            "%.1f" % mo["time_ms"] if mo.get("time_ms") else "-"))
    lines.append("")
    for key in ("H", "RMS", "time"):
        values = ratios[key]
        if values:
            lines.append("- %s ratio (ours / vtkQuadricClustering): geometric mean %.2f, max %.2f over %d cases"
                         % (key, geometric_mean(values), max(values), len(values)))
    lines += ["- " + p for p in problems]
    text = "\n".join(lines)
    print(text)
    if a.out:
        with open(a.out, "w") as f:
            f.write(text + "\n")


if __name__ == "__main__":
    main()
