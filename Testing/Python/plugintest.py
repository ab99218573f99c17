# SPDX-License-Identifier: BSD-3-Clause
"""What the plugin tests share: their command line, a check that records failures, and the
exit status."""
import argparse
import sys

failures = []


def arguments(*extra):
    """--plugin and --data, plus the named optional arguments."""
    parser = argparse.ArgumentParser()
    parser.add_argument("--plugin", required=True)
    parser.add_argument("--data", required=True)
    for name in extra:
        parser.add_argument(name)
    args, _ = parser.parse_known_args()
    return args


def check(condition, message):
    if not condition:
        failures.append(message)
        print("check failed:", message, file=sys.stderr)


def check_error_bound(simplifier, source, input_triangles):
    """Maximum Error mode of a collapse filter: as far as the bound (1 % of the diagonal) lets;
    the field data holds the largest distance reached; a tighter bound keeps more triangles."""
    from paraview import servermanager
    simplifier.TargetMode = "Maximum Error"
    simplifier.MaximumError = 0.01
    output = servermanager.Fetch(simplifier)
    bounds = source.GetDataInformation().GetBounds()
    diagonal = sum((bounds[2 * k + 1] - bounds[2 * k]) ** 2 for k in range(3)) ** 0.5
    reached = output.GetFieldData().GetArray("MaximumPlaneDistance")
    check(reached is not None and 0 < reached.GetValue(0) <= 0.01 * diagonal,
          "largest plane distance within the bound")
    distances = output.GetPointData().GetArray("PlaneDistance")
    check(distances is not None and distances.GetNumberOfTuples() == output.GetNumberOfPoints() and
          distances.GetRange()[1] == reached.GetValue(0),
          "PlaneDistance per point, its largest in the field data")
    simplifier.MaximumError = 0.002
    loose, tight = output.GetNumberOfPolys(), servermanager.Fetch(simplifier).GetNumberOfPolys()
    check(loose < tight < input_triangles,
          "bounds 0.01 and 0.002 give %d and %d triangles" % (loose, tight))


def finish():
    print("%d passed, %d failed" % (1 if not failures else 0, 1 if failures else 0))
    sys.exit(1 if failures else 0)
