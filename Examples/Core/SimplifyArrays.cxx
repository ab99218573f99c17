// SPDX-License-Identifier: BSD-3-Clause
// The core without VTK: a wavy height field held in two flat arrays (points, triangles) is
// simplified to a tenth of its triangles by Parallel Decimation, and the result read back.
//   SimplifyArrays [grid size, default 100]
#include "ParallelDecimation.h"

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <iostream>
#include <vector>

int main(int argc, char* argv[])
{
  // 1. The input: any program's own arrays, 3 coordinates a point and 3 point ids a triangle.
  const int n = argc > 1 ? std::max(2, std::atoi(argv[1])) : 100;
  std::vector<double> points;
  std::vector<std::int32_t> triangles;
  for (int j = 0; j <= n; ++j)
  {
    for (int i = 0; i <= n; ++i)
    {
      const double x = static_cast<double>(i) / n, y = static_cast<double>(j) / n;
      points.insert(points.end(), { x, y, 0.05 * std::sin(6.0 * x) * std::cos(4.0 * y) });
    }
  }
  for (int j = 0; j < n; ++j)
  {
    for (int i = 0; i < n; ++i)
    {
      const std::int32_t a = j * (n + 1) + i, b = a + 1, c = a + n + 1, d = c + 1;
      triangles.insert(triangles.end(), { a, b, d, a, d, c });
    }
  }

  // 2. A view of them (nothing is copied) and the options: the target, and the border kept.
  meshsimp::TriangleMeshView input;
  input.Points = points.data();
  input.NumberOfPoints = static_cast<std::int64_t>(points.size() / 3);
  input.Triangles = triangles.data();
  input.NumberOfTriangles = static_cast<std::int64_t>(triangles.size() / 3);
  meshsimp::ParallelDecimationOptions options;
  options.Goal.SetReduction(0.9);
  options.PreserveBoundary = true;

  // 3. The run: false only when aborted through an ExecutionContext (none here).
  meshsimp::ParallelDecimationResult result;
  if (!meshsimp::ParallelDecimation(input, options, result))
  {
    return EXIT_FAILURE;
  }

  // 4. The output: flat arrays again, and where each output point comes from.
  std::cout << input.NumberOfTriangles << " triangles -> " << result.NumberOfTriangles() << " ("
            << result.NumberOfPoints() << " points, " << result.Rounds << " rounds)\n";
  std::cout << "output point 0 is input point " << result.Representative(0) << " at (" << result.Points[0]
            << ", " << result.Points[1] << ", " << result.Points[2] << ")\n";
  const bool met = result.Report.Stop == meshsimp::StopReason::TargetMet;
  std::cout << (met ? "target met" : "stopped early: " + result.Report.Reason) << "\n";
  return met ? EXIT_SUCCESS : EXIT_FAILURE;
}
