#!/usr/bin/env python3
"""A campaign of hostile mesh files against meshsimplify: what each build does with them.

Generates COUNT files (default 1200) from the fuzz seeds (Testing/Data/Fuzz/MeshFiles: small
sound meshes of every format) by damage of known kinds, runs each binary given on every file
(--method octree, 10 s limit) and counts, per binary:
  crash    ended by a signal
  hang     still running after 10 s
  silent   exit 0, no warning, and a triangle count read that differs from the undamaged
           file's (a count made smaller, data cut off: triangles lost without a word)
  error    exit 1 with one line "meshsimplify: ..."
  other    any other exit (several lines, another status)
  read     exit 0 otherwise (damage that leaves a valid file, such as a changed digit or a
           field-data value, or one the tool warns about)

    hostile_files.py [--count N] [--seed S] [--work DIR] BINARY [BINARY ...]

The seeds are the project's own (Testing/Data/Fuzz/MeshFiles); nothing outside the checkout.

The files are made the same for a given seed, so two builds meet the same files.
"""
import argparse
import json
import os
import random
import re
import subprocess
import sys
import tempfile
from collections import Counter

HERE = os.path.dirname(os.path.abspath(__file__))
SEEDS = os.path.join(HERE, "..", "Data", "Fuzz", "MeshFiles")
EXTENSIONS = ["off", "ply", "stl", "obj", "vtp", "vtk"]
def seeds():
    for name in sorted(os.listdir(SEEDS)):
        if name.endswith(".md") or name.startswith("crashed"):
            continue
        data = open(os.path.join(SEEDS, name), "rb").read()
        yield EXTENSIONS[data[0] % 6], data[1:]


def numbers(data):
    return [m for m in re.finditer(rb"(?<![\w.])\d+(?![\w.])", data)]


def damage(kind, data, rng):
    if kind == "truncate":
        return data[: rng.randrange(max(1, len(data) // 4), len(data))]
    if kind == "bitflip":
        b = bytearray(data)
        for _ in range(rng.randint(1, 8)):
            i = rng.randrange(len(b))
            b[i] ^= 1 << rng.randrange(8)
        return bytes(b)
    if kind == "byte":
        b = bytearray(data)
        b[rng.randrange(len(b))] = rng.choice(b"\x00\xff<>\"0 \n-")
        return bytes(b)
    found = numbers(data)
    if kind in ("smaller_count", "larger_count", "huge_count") and found:
        m = rng.choice(found[:12])  # counts stand in headers, near the start
        value = int(m.group())
        new = {"smaller_count": max(0, value - rng.randint(1, 3)),
               "larger_count": value + rng.randint(1, 1000),
               "huge_count": rng.choice([2**31 - 1, 2**31, 2**32, 2**63 - 1, -1])}[kind]
        if kind == "smaller_count" and new == value:
            return None
        return data[: m.start()] + str(new).encode() + data[m.end():]
    floats = list(re.finditer(rb"(?<![\w.])-?\d+\.\d+(?:e-?\d+)?|(?<=\s)0(?=\s)", data))
    if kind in ("nan", "inf", "huge_coordinate", "tiny_coordinate") and floats:
        m = rng.choice(floats)
        word = {"nan": b"nan", "inf": b"inf", "huge_coordinate": b"1e300",
                "tiny_coordinate": b"1e-300"}[kind]
        return data[: m.start()] + word + data[m.end():]
    if kind == "deep_nesting":
        depth = rng.choice([300, 5000, 30000])
        return data.replace(b"</VTKFile>", b"<a>" * depth + b"</a>" * depth + b"</VTKFile>")
    if kind == "long_token":
        size = rng.choice([1 << 16, 1 << 20, 4 << 20])
        return data.replace(b"</VTKFile>", b'<a b="' + b"x" * size + b'"/></VTKFile>')
    if kind == "long_line":
        at = data.find(b"\n", rng.randrange(len(data))) + 1
        return data[:at] + b"1 " * rng.choice([3000, 200000]) + b"\n" + data[at:]
    if kind == "garbage":
        return bytes(rng.randrange(256) for _ in range(rng.randint(1, 4096)))
    return None


KINDS = ["truncate", "bitflip", "byte", "smaller_count", "larger_count", "huge_count", "nan",
         "inf", "huge_coordinate", "tiny_coordinate", "deep_nesting", "long_token", "long_line",
         "garbage"]


def make_files(count, seed, work):
    rng = random.Random(seed)
    pool = list(seeds())
    files = []
    while len(files) < count:
        extension, data = rng.choice(pool)
        kind = rng.choice(KINDS)
        damaged = damage(kind, data, rng)
        if damaged is None or damaged == data:
            continue
        path = os.path.join(work, "%04d_%s.%s" % (len(files), kind, extension))
        open(path, "wb").write(damaged)
        seed_path = os.path.join(work, "seed_%d.%s" % (pool.index((extension, data)), extension))
        open(seed_path, "wb").write(data)
        files.append((path, seed_path))
    return files


def run(binary, path, work):
    try:
        return subprocess.run([binary, "--method", "octree", "--json", path,
                               os.path.join(work, "out.vtp")], capture_output=True, timeout=10)
    except subprocess.TimeoutExpired:
        return None


def triangles(result):
    try:
        return json.loads(result.stdout)["input_triangles"]
    except (ValueError, KeyError):
        return None


def classify(binary, path, seed_path, work, seed_counts):
    result = run(binary, path, work)
    if result is None:
        return "hang"
    err = result.stderr.decode(errors="replace")
    if result.returncode < 0:
        return "crash"
    if result.returncode == 0:
        if seed_path not in seed_counts:
            seed_counts[seed_path] = triangles(run(binary, seed_path, work))
        lost = triangles(result) != seed_counts[seed_path]
        return "silent" if lost and "warning" not in err else "read"
    if result.returncode == 1 and err.count("\n") == 1 and err.startswith("meshsimplify: "):
        return "error"
    return "other"


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("binaries", nargs="+")
    parser.add_argument("--count", type=int, default=1200)
    parser.add_argument("--seed", type=int, default=50)
    parser.add_argument("--work", default=None, help="folder for the files (default: a new temporary one)")
    args = parser.parse_args()
    args.work = args.work or tempfile.mkdtemp(prefix="hostile_files_")
    os.makedirs(args.work, exist_ok=True)
    files = make_files(args.count, args.seed, args.work)
    columns = ["crash", "hang", "silent", "other", "error", "read"]
    print("| binary | files | " + " | ".join(columns) + " |")
    print("|---" * (len(columns) + 2) + "|")
    for binary in args.binaries:
        seed_counts = {}
        counts = Counter(classify(binary, path, seed, args.work, seed_counts) for path, seed in files)
        print("| %s | %d | %s |" % (binary, len(files), " | ".join(str(counts[c]) for c in columns)))
        sys.stdout.flush()


if __name__ == "__main__":
    main()
