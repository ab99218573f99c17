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
    the field data holds the largest distance reached in the bound's units (a fraction of the
    diagonal), the point array PlaneDistance each point's in input units; a tighter bound keeps
    more triangles."""
    from paraview import servermanager
    simplifier.TargetMode = "Maximum Error"
    simplifier.MaximumError = 0.01
    output = servermanager.Fetch(simplifier)
    bounds = source.GetDataInformation().GetBounds()
    diagonal = sum((bounds[2 * k + 1] - bounds[2 * k]) ** 2 for k in range(3)) ** 0.5
    reached = output.GetFieldData().GetArray("MaximumError")
    check(reached is not None and 0.005 < reached.GetValue(0) <= 0.01,
          "largest plane distance within the bound, in its units")
    distances = output.GetPointData().GetArray("PlaneDistance")
    check(distances is not None and distances.GetNumberOfTuples() == output.GetNumberOfPoints() and
          abs(distances.GetRange()[1] / diagonal - reached.GetValue(0)) < 1e-9,
          "PlaneDistance per point in input units, its largest in the field data")
    simplifier.MaximumError = 0.002
    loose, tight = output.GetNumberOfPolys(), servermanager.Fetch(simplifier).GetNumberOfPolys()
    check(loose < tight < input_triangles,
          "bounds 0.01 and 0.002 give %d and %d triangles" % (loose, tight))


def check_unlocked_after_octree(simplifier_class, octree_class, source, tolerance):
    """No point is locked by default, also after a filter whose output has active point scalars
    (the octree's ClusterError, nonzero nearly everywhere, which ParaView would pick): the
    octree's output is reduced by 90 % within tolerance. The classes are the plugin's proxies."""
    clustered = octree_class(Input=source, TargetReduction=0.5)
    clustered.UpdatePipeline()  # as in the GUI, where the octree is applied first
    chained = simplifier_class(Input=clustered)
    locks = list(chained.LockedPoints)
    check(locks == ["POINTS", "None"], "no locked points by default after the octree, got %s" % locks)
    chained.UpdatePipeline()
    target = 0.1 * clustered.GetDataInformation().GetNumberOfCells()
    got = chained.GetDataInformation().GetNumberOfCells()
    check(abs(got - target) <= tolerance * target + 1,
          "after the octree: %d triangles for 90 %% reduction (%d)" % (got, round(target)))


def finish():
    print("%d passed, %d failed" % (1 if not failures else 0, 1 if failures else 0))
    sys.exit(1 if failures else 0)
