# SPDX-License-Identifier: BSD-3-Clause
"""The error-bound table of Filters/Core/ErrorBounds.md: each filter under a relative bound, its triangle count, the
largest error it reports (which must not pass the bound) and the symmetric Hausdorff distance the
kit's metro measures (% of the diagonal).

  python3 Testing/Benchmark/error_bound_table.py MESH... --kit KIT --cli build/bin/meshsimplify
      --workdir bound-work [--bin KIT/build] [--bound 0.002 0.01] [--out table.md]

KIT is the benchmark kit's folder (benchlib.py, and metro built in KIT/build unless --bin says
where).

Any input the kit reads (a DEM .npz too) is written as PLY in the workdir, named after the
input's position in the list and its name.
"""
import argparse
import json
import os
import subprocess
import sys

METHODS = ["octree", "volume", "parallel"]


def as_ply(index, mesh, kit, workdir):
    """The mesh as a PLY our CLI and metro read (the kit's loader, unused points dropped)."""
    sys.path.insert(0, kit)
    import benchlib  # noqa: E402

    name = os.path.splitext(os.path.basename(mesh))[0]
    path = os.path.join(workdir, "%d_%s.ply" % (index, name))
    points, triangles, _ = benchlib.load(mesh)
    benchlib.write_ply(path, points, triangles)
    return name, path


def last_json_line(command):
    """Runs the command; the JSON object on the last line it prints (its errors shown if it fails)."""
    done = subprocess.run(command, capture_output=True, text=True)
    lines = done.stdout.strip().splitlines()
    if done.returncode != 0 or not lines:
        sys.exit("%s failed (%d): %s" % (" ".join(command), done.returncode, done.stderr.strip()))
    return json.loads(lines[-1])


def run(cli, method, bound, source, output):
    """Our CLI under a relative bound; its JSON line."""
    return last_json_line([cli, "--method", method, "--max-error", str(bound), "--relative-error",
                           "--json", source, output])


def hausdorff(metro, source, output):
    """metro's symmetric Hausdorff distance, % of the diagonal."""
    return last_json_line([metro, source, output])["symmetric"]["max_pct"]


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("meshes", nargs="+")
    ap.add_argument("--kit", required=True, help="the shared benchmark kit folder (benchlib.py)")
    ap.add_argument("--bin", help="folder with the kit's metro (default KIT/build)")
    ap.add_argument("--cli", required=True, help="our meshsimplify")
    ap.add_argument("--bound", type=float, nargs="+", default=[0.002, 0.01],
                    help="relative bounds (put the meshes first, or end the list with --)")
    ap.add_argument("--workdir", required=True)
    ap.add_argument("--out", help="also write the markdown here")
    args = ap.parse_args()
    os.makedirs(args.workdir, exist_ok=True)
    metro = os.path.join(args.bin or os.path.join(args.kit, "build"), "metro")
    lines = ["| mesh | bound | " + " | ".join(m + " tris" for m in METHODS) + " | " +
             " | ".join(m + " H" for m in METHODS) + " | largest reported error |",
             "|---" * (3 + 2 * len(METHODS)) + "|"]
    inputs = [as_ply(index, mesh, args.kit, args.workdir) for index, mesh in enumerate(args.meshes)]
    for bound in args.bound:
        for name, source in inputs:
            counts, distances, largest = [], [], 0.0
            for method in METHODS:
                output = os.path.join(args.workdir, "%s_%s_%g.ply" % (name, method, bound))
                report = run(args.cli, method, bound, source, output)
                counts.append("{:,}".format(report["output_triangles"]).replace(",", " "))
                distances.append("%.2f" % hausdorff(metro, source, output))
                largest = max(largest, report["max_error"] / bound)
            lines.append("| %s | %g %% | %s | %s | %.3f of the bound |" % (
                name, 100 * bound, " | ".join(counts), " | ".join(distances), largest))
            print(lines[-1], file=sys.stderr)
    text = "\n".join(lines) + "\n"
    print(text)
    if args.out:
        with open(args.out, "w") as f:
            f.write(text)


if __name__ == "__main__":
    main()
