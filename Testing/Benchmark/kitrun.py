# SPDX-License-Identifier: BSD-3-Clause
"""What the benchmark scripts share: run the kit's compare.py with our CLI as an extra method,
read its JSON, and summarise ratios."""
import json
import math
import os
import subprocess
import sys


def geometric_mean(values):
    values = [v for v in values if v is not None and v > 0]
    return math.exp(sum(math.log(v) for v in values) / len(values)) if values else float("nan")


def metric(row, key):
    """A symmetric metro figure of a result row (max_pct, mean_pct, rms_pct)."""
    metro = row.get("metro") or {}
    return (metro.get("symmetric") or {}).get(key)


def run_cases(meshes, kit, bin_dir, ours, peers, reductions, repeat, workdir):
    """Runs compare.py on every mesh; returns (name, input info, reduction, target, rows by
    method) per case. `ours` is the kit's --extra template of our CLI (method "ours"), or a
    dict of such templates by method name."""
    extras = ours if isinstance(ours, dict) else {"ours": ours}
    cases = []
    for mesh in meshes:
        name = os.path.splitext(os.path.basename(mesh))[0]
        result = os.path.join(workdir, name + ".json")
        command = ["/usr/bin/python3", os.path.join(kit, "compare.py"), mesh,
                   "--reduction", *map(str, reductions), "--repeat", str(repeat),
                   "--only", peers + "".join("|^%s$" % n for n in extras),
                   "--workdir", os.path.join(workdir, name), "--json", result]
        for method, template in extras.items():
            command += ["--extra", method + "=" + template]
        if bin_dir:
            command += ["--bin", bin_dir]
        print("running", name, file=sys.stderr)
        subprocess.run(command, check=True, stdout=subprocess.DEVNULL)
        with open(result) as f:
            document = json.load(f)
        for run in document["runs"]:
            rows = {row["method"]: row for row in run["rows"]}
            cases.append((name, document["input"], run["reduction"], run["target"], rows))
    return cases


def add_common_arguments(ap, reductions):
    ap.add_argument("meshes", nargs="+")
    ap.add_argument("--kit", required=True, help="the shared benchmark kit folder (compare.py)")
    ap.add_argument("--bin", help="folder with the kit's metro and peers (default KIT/build)")
    ap.add_argument("--cli", required=True, help="our meshsimplify")
    ap.add_argument("--reduction", type=float, nargs="+", default=reductions)
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--threads", type=int, default=0, help="--threads for our CLI (0: all cores)")
    ap.add_argument("--workdir", required=True, help="folder for the kit's inputs and outputs")
    ap.add_argument("--out", help="also write the markdown here")


def finish(lines, ratios, problems, out):
    """Appends the geometric means of the ratios (named by their keys) and the problems to the
    table, prints it and writes it to out (when given)."""
    lines.append("")
    for key, values in ratios.items():
        if values:
            lines.append("- %s: geometric mean %.2f, max %.2f over %d cases"
                         % (key, geometric_mean(values), max(values), len(values)))
    lines += ["- " + p for p in problems]
    text = "\n".join(lines)
    print(text)
    if out:
        with open(out, "w") as f:
            f.write(text + "\n")
