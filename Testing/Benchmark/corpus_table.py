# SPDX-License-Identifier: BSD-3-Clause
"""The filters on the broad corpus: per class of input, geometric means of ours / peer, and
whether each target holds (also in the worst class and the worst case).

  python3 Testing/Benchmark/corpus_table.py --kit KIT --corpus CORPUS \\
      --cli build/bin/meshsimplify --workdir corpus-work \\
      [--filters octree,volume,parallel,progressive] [--repeat 3] [--meshes REGEX] [--no-run] [--out table.md]

KIT is the benchmark kit's folder (run_corpus.py, compare.py, its built metro and peers) and
CORPUS a folder of meshes with the kit's manifest.json (the kit's corpus.py writes one).

Each filter runs through the kit's run_corpus.py (compare.py and metro on every corpus mesh)
against the peer and at the reductions of its targets:
  octree   vs vtk_qclustering at 90 % and 98 %: Hausdorff, RMS, time, count within 3 %;
  volume   vs vtk_quadric at 70 % and 95 %: mean distance, Hausdorff, |volume change| on
           closed inputs, time, slivers (< 10 degrees) against the peer's, closed stays closed;
  parallel vs vtk_quadric at 90 %: RMS, Hausdorff, count within 2 %;
  progressive vs meshopt at 90 % and 98 % (each level from one build, against a meshoptimizer
           run per level): RMS, Hausdorff, count within 1 % (the worst-class goals, 1.25x and
           2x, are ours: the issue sets only the means).
Times are the tools' own in-memory work, medians of --repeat runs in one process. --no-run
summarises the results already in --workdir.
"""
import argparse
import json
import math
import os
import subprocess
import sys

# Per filter: the peer, the reductions, the CLI's tolerance, and the targets as
# (metric, goal for the geometric mean, goal for the worst class or case, whether the goal
# holds in every case rather than per class).
FILTERS = {
    "octree": {"peer": "vtk_qclustering", "reductions": [0.9, 0.98], "tolerance": 0.03,
               "targets": [("hausdorff", 0.7, 1.0, False), ("rms", 0.7, 1.0, False), ("time", 1.5, 1.5, True)]},
    "volume": {"peer": "vtk_quadric", "reductions": [0.7, 0.95], "tolerance": 0.01,
               "targets": [("mean", 1.0, 1.25, False), ("hausdorff", 1.25, 1.6, False),
                           ("volume", 0.6, 1.0, False), ("time", 0.37, 0.6, True)]},
    "parallel": {"peer": "vtk_quadric", "reductions": [0.9], "tolerance": 0.02,
                 "targets": [("rms", 1.5, 2.0, False), ("hausdorff", 2.0, 3.0, False)]},
    "progressive": {"peer": "meshopt", "reductions": [0.9, 0.98], "tolerance": 0.01,
                    "targets": [("rms", 1.0, 1.25, False), ("hausdorff", 1.5, 2.0, False)]},
}
FLOORS = {"rms": 1e-3, "hausdorff": 1e-3, "mean": 1e-3, "volume": 1e-2, "time": 0.01}


def run(args, name, spec):
    out = os.path.join(args.workdir, name)
    template = "%s --method %s --target-triangles {target} --threads %d --json {in} {out}" % (
        os.path.abspath(args.cli), name, args.threads)
    command = [sys.executable, os.path.join(args.kit, "run_corpus.py"), "--corpus", args.corpus,
               "--method", "ours", "--peers", spec["peer"], "--extra", "ours=" + template,
               "--reduction", *map(str, spec["reductions"]), "--repeat", str(args.repeat), "--out", out]
    if args.bin:
        command += ["--bin", args.bin]
    if args.meshes:
        command += ["--meshes", args.meshes]
    if args.no_run:
        command.append("--no-run")
    subprocess.run(command, check=True, stdout=subprocess.DEVNULL)
    with open(os.path.join(out, "summary.json")) as f:
        return out, json.load(f)


def geomean(values):
    values = [v for v in values if v is not None]
    return math.exp(sum(math.log(v) for v in values) / len(values)) if values else None


def ratio(mine, theirs, key):
    if mine is None or theirs is None:
        return None
    return max(mine, FLOORS[key]) / max(theirs, FLOORS[key])


def metro_rows(out, mesh, reduction):
    """compare.py's rows of one mesh and reduction, by method."""
    with open(os.path.join(out, mesh + ".json")) as f:
        doc = json.load(f)
    for run_ in doc["runs"]:
        if abs(run_["reduction"] - reduction) < 1e-9:
            return {row["method"]: row for row in run_["rows"]}
    return {}


def cases(out, summary, peer):
    """Per (mesh, reduction): class, ratios, count error, slivers and closedness."""
    result = []
    for record in summary["records"]:
        mine, theirs = record["methods"].get("ours"), record["methods"].get(peer)
        case = {"mesh": record["mesh"], "class": record["class"], "reduction": record["reduction"],
                "failed": not mine or mine["status"] == "failed", "peer_failed": not theirs or theirs["status"] == "failed"}
        if not case["failed"]:
            case["off"] = mine["off_target"]
            rows = metro_rows(out, record["mesh"], record["reduction"])
            metro = (rows.get("ours") or {}).get("metro") or {}
            case["slivers"] = metro.get("b", {}).get("min_angle_lt10_pct")
            case["opened"] = bool(metro.get("a", {}).get("closed")) and not metro.get("b", {}).get("closed")
            peer_metro = (rows.get(peer) or {}).get("metro") or {}
            case["peer_slivers"] = peer_metro.get("b", {}).get("min_angle_lt10_pct")
        if not case["failed"] and not case["peer_failed"]:
            case["ratios"] = {k: ratio(mine.get(k), theirs.get(k), k) for k in FLOORS}
        result.append(case)
    return result


def table(name, spec, all_cases):
    targets = spec["targets"]
    classes = list(dict.fromkeys(c["class"] for c in all_cases))
    paired = [c for c in all_cases if "ratios" in c]
    lines = ["## %s against %s at %s" % (name, spec["peer"], ", ".join("%g %%" % (100 * r) for r in spec["reductions"])), "",
             "| class | cases | " + " | ".join(k for k, _, _, _ in targets) + " | worst count error | failed |",
             "|---|---|" + "---|" * len(targets) + "---|---|"]
    per_class = {}
    for group in classes + ["all"]:
        members = [c for c in all_cases if group == "all" or c["class"] == group]
        pairs = [c for c in members if "ratios" in c]
        means = {k: geomean([c["ratios"][k] for c in pairs]) for k, _, _, _ in targets}
        per_class[group] = means
        offs = [abs(c["off"]) for c in members if "off" in c]
        failed = sum(c["failed"] for c in members)
        lines.append("| %s | %d | %s | %s | %d |" % (
            "**all**" if group == "all" else group, len(members),
            " | ".join("–" if means[k] is None else "%.2f" % means[k] for k, _, _, _ in targets),
            "%.1f %%" % (100 * max(offs)) if offs else "–", failed))
    lines += ["", "| target | goal (mean / worst) | geometric mean | worst | met |", "|---|---|---|---|---|"]
    for key, goal, worst_goal, every_case in targets:
        mean = per_class["all"][key]
        values = [c["ratios"][key] for c in paired if c["ratios"][key] is not None] if every_case else \
            [per_class[g][key] for g in classes if per_class[g][key] is not None]
        worst = max(values) if values else None
        met = mean is not None and mean <= goal and worst is not None and worst <= worst_goal
        lines.append("| %s | %.2f / %.2f (%s) | %s | %s | %s |" % (
            key, goal, worst_goal, "every case" if every_case else "every class",
            "–" if mean is None else "%.2f" % mean, "–" if worst is None else "%.2f" % worst, "yes" if met else "**no**"))
    missed = [c for c in all_cases if "off" in c and abs(c["off"]) > spec["tolerance"]]
    lines.append("| count within %g %% | every case | | %d missed | %s |" % (
        100 * spec["tolerance"], len(missed), "yes" if not missed else "**no**"))
    if name == "volume":
        slivers = [c for c in all_cases if c.get("slivers") is not None and c.get("peer_slivers") is not None
                   and c["slivers"] > c["peer_slivers"] + 1.0]
        opened = [c for c in all_cases if c.get("opened")]
        lines.append("| slivers <= peer's + 1 point | every case | | %d over | %s |" % (len(slivers), "yes" if not slivers else "**no**"))
        lines.append("| closed stays closed | every case | | %d opened | %s |" % (len(opened), "yes" if not opened else "**no**"))
    failures = [c for c in all_cases if c["failed"]]
    lines.append("| finishes on every input | every case | | %d failed | %s |" % (len(failures), "yes" if not failures else "**no**"))
    if missed:
        lines += ["", "Count misses: " + "; ".join("%s @ %g: %+.1f %%" % (c["mesh"], c["reduction"], 100 * c["off"]) for c in missed)]
    return lines


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--kit", required=True, help="the benchmark kit's folder (run_corpus.py, compare.py, its built metro and peers)")
    ap.add_argument("--bin", help="folder with the kit's metro and peers (default KIT/build)")
    ap.add_argument("--corpus", required=True, help="the corpus folder (manifest.json)")
    ap.add_argument("--cli", required=True, help="our meshsimplify")
    ap.add_argument("--workdir", required=True)
    ap.add_argument("--filters", default="octree,volume,parallel,progressive")
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--threads", type=int, default=0, help="--threads for our CLI (0: all cores)")
    ap.add_argument("--meshes", help="regex of corpus meshes to run")
    ap.add_argument("--no-run", action="store_true")
    ap.add_argument("--out")
    args = ap.parse_args()
    lines = ["# The filters on the corpus", ""]
    for name in args.filters.split(","):
        spec = FILTERS[name]
        out, summary = run(args, name, spec)
        lines += table(name, spec, cases(out, summary, spec["peer"])) + [""]
    text = "\n".join(lines)
    print(text)
    if args.out:
        with open(args.out, "w") as f:
            f.write(text + "\n")


if __name__ == "__main__":
    sys.exit(main())
