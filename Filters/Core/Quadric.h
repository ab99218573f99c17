// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file Quadric.h
 * @brief Symmetric 4x4 error quadrics (Garland–Heckbert) and their robust minimiser.
 *
 * A quadric Q measures a weighted sum of squared distances to planes:
 * Q(v) = vᵀ A v + 2 bᵀ v + c, the expanded form of eq. (1) and (6)–(7) of Zhou, Zhang, Shi and
 * Pan, "A new simplification algorithm for colored or textured polygonal models".
 * It is stored as 10 doubles (upper triangle of A, b, c) so arrays of quadrics stay flat.
 * The collapse- and clustering-based filters of this project share it.
 */
#ifndef MeshSimplification_Quadric_h
#define MeshSimplification_Quadric_h

#include <Eigen/Core>
#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>

#include <cmath>

namespace meshsimp
{

struct Quadric
{
  double A00 = 0, A01 = 0, A02 = 0, A11 = 0, A12 = 0, A22 = 0;
  double B0 = 0, B1 = 0, B2 = 0;
  double C = 0;

  /// w · (nᵀv + d)²: the plane nᵀv + d = 0 with unit normal n, weighted by w (eq. 7).
  static Quadric FromPlane(const Eigen::Vector3d& n, double d, double w)
  {
    Quadric q;
    q.A00 = w * n.x() * n.x();
    q.A01 = w * n.x() * n.y();
    q.A02 = w * n.x() * n.z();
    q.A11 = w * n.y() * n.y();
    q.A12 = w * n.y() * n.z();
    q.A22 = w * n.z() * n.z();
    q.B0 = w * d * n.x();
    q.B1 = w * d * n.y();
    q.B2 = w * d * n.z();
    q.C = w * d * d;
    return q;
  }

  /// Garland and Heckbert's border constraint at an open border edge from a to b: the plane
  /// through the edge perpendicular to its triangle (faceNormal, of any length), weighted by the
  /// squared edge length so that it scales like area-weighted face planes. False, and plane
  /// untouched, where the edge is degenerate or along the normal.
  static bool FromBorderEdge(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& faceNormal,
    Quadric& plane)
  {
    const Eigen::Vector3d edge = b - a;
    const Eigen::Vector3d side = edge.cross(faceNormal);
    const double length = side.norm();
    if (!(length > 0.0))
    {
      return false;
    }
    const Eigen::Vector3d n = side / length;
    plane = FromPlane(n, -n.dot(a), edge.squaredNorm());
    return true;
  }

  /// Adds the 3x3 part w · n nᵀ of a plane with unit normal n (eq. 7) when every plane of the
  /// quadric passes through one point: ThroughPoint then gives b and c. Half the work of FromPlane.
  void AddNormal(const Eigen::Vector3d& n, double w)
  {
    const Eigen::Vector3d wn = w * n;
    A00 += wn.x() * n.x();
    A01 += wn.x() * n.y();
    A02 += wn.x() * n.z();
    A11 += wn.y() * n.y();
    A12 += wn.y() * n.z();
    A22 += wn.z() * n.z();
  }

  /// Completes a quadric built by AddNormal with planes through p: d = −nᵀp for each, so
  /// b = Σ w d n = −A p and c = Σ w d² = pᵀ A p.
  void ThroughPoint(const Eigen::Vector3d& p)
  {
    const Eigen::Vector3d ap = this->A() * p;
    B0 = -ap.x();
    B1 = -ap.y();
    B2 = -ap.z();
    C = p.dot(ap);
  }

  Quadric& operator+=(const Quadric& o)
  {
    A00 += o.A00;
    A01 += o.A01;
    A02 += o.A02;
    A11 += o.A11;
    A12 += o.A12;
    A22 += o.A22;
    B0 += o.B0;
    B1 += o.B1;
    B2 += o.B2;
    C += o.C;
    return *this;
  }

  Quadric& operator-=(const Quadric& o)
  {
    A00 -= o.A00;
    A01 -= o.A01;
    A02 -= o.A02;
    A11 -= o.A11;
    A12 -= o.A12;
    A22 -= o.A22;
    B0 -= o.B0;
    B1 -= o.B1;
    B2 -= o.B2;
    C -= o.C;
    return *this;
  }

  Eigen::Matrix3d A() const
  {
    Eigen::Matrix3d a;
    a << A00, A01, A02, A01, A11, A12, A02, A12, A22;
    return a;
  }
  Eigen::Vector3d B() const { return { B0, B1, B2 }; }

  /// Q(v), eq. (1). Clamped at zero against round-off.
  double Evaluate(const Eigen::Vector3d& v) const
  {
    const double x = v.x(), y = v.y(), z = v.z();
    const double value = x * (A00 * x + 2.0 * (A01 * y + A02 * z + B0)) +
      y * (A11 * y + 2.0 * (A12 * z + B1)) + z * (A22 * z + 2.0 * B2) + C;
    return value > 0.0 ? value : 0.0;
  }
};

/**
 * Minimise Q (eq. 2–3) when its 3x3 block is well conditioned, judged without eigenvalues:
 * with the cofactors of A, det(A) / (tr(A) · Σ principal 2x2 minors) lies within
 * [λmin / 9λmax, λmin / λmax] (det / Σ minors ∈ [λmin / 3, λmin], tr ∈ [λmax, 3λmax]). The solve
 * is accepted only when that ratio exceeds relativeTolerance, so a nearly planar or nearly
 * cylindrical set of planes (rank 1 or 2) is reported as singular instead of producing a
 * far-away point; the adjugate then solves it.
 */
inline bool MinimizeQuadric(const Quadric& q, Eigen::Vector3d& x, double relativeTolerance = 1e-6)
{
  const double trace = q.A00 + q.A11 + q.A22;
  const double c00 = q.A11 * q.A22 - q.A12 * q.A12;
  const double c01 = q.A02 * q.A12 - q.A01 * q.A22;
  const double c02 = q.A01 * q.A12 - q.A02 * q.A11;
  const double c11 = q.A00 * q.A22 - q.A02 * q.A02;
  const double c12 = q.A01 * q.A02 - q.A00 * q.A12;
  const double c22 = q.A00 * q.A11 - q.A01 * q.A01;
  const double det = q.A00 * c00 + q.A01 * c01 + q.A02 * c02;
  if (!(trace > 0.0) || !(det > relativeTolerance * trace * (c00 + c11 + c22)))
  {
    return false;
  }
  const double s = -1.0 / det;
  x = Eigen::Vector3d(s * (c00 * q.B0 + c01 * q.B1 + c02 * q.B2),
    s * (c01 * q.B0 + c11 * q.B1 + c12 * q.B2), s * (c02 * q.B0 + c12 * q.B1 + c22 * q.B2));
  return x.allFinite();
}

/**
 * The point of least Q closest to a fallback point x0: Q's minimum along the directions in which
 * it is well conditioned (eigenvalues above relativeTolerance · λmax), x0's coordinate along the
 * others. With a full-rank Q this is MinimizeQuadric's point; with planes of one direction (a
 * flat region) it is x0 moved onto them; with two (a crease) x0 moved onto the crease line; with
 * none, x0. Returns the number of directions Q determined (0–3).
 */
inline int MinimizeQuadricNear(const Quadric& q, const Eigen::Vector3d& x0, Eigen::Vector3d& x,
  double relativeTolerance = 1e-6)
{
  if (!(q.A00 + q.A11 + q.A22 > 0.0))
  {
    x = x0; // no planes at all
    return 0;
  }
  if (MinimizeQuadric(q, x, relativeTolerance))
  {
    return 3;
  }
  // Rank-deficient: closed-form eigenvectors are accurate enough for the directions kept.
  const Eigen::Matrix3d a = q.A();
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig;
  eig.computeDirect(a);
  const Eigen::Vector3d lambda = eig.eigenvalues(); // ascending
  const Eigen::Vector3d gradient = a * x0 + q.B();
  x = x0;
  int rank = 0;
  for (int i = 2; i >= 0; --i)
  {
    if (!(lambda(i) > 0.0) || !(lambda(i) > relativeTolerance * lambda(2)))
    {
      break;
    }
    const Eigen::Vector3d u = eig.eigenvectors().col(i);
    x -= u * (u.dot(gradient) / lambda(i));
    ++rank;
  }
  if (!x.allFinite())
  {
    x = x0;
    return 0;
  }
  return rank;
}

/**
 * The point of least Q within radius of x0 (a trust-region step, as in Levenberg-Marquardt):
 * x0 - (A + mu I)^-1 (A x0 + b) with the smallest mu >= 0 that keeps it within the radius, along
 * the directions in which Q is well conditioned (as MinimizeQuadricNear: eigenvalues above
 * relativeTolerance · λmax; x0 keeps its coordinate along the others, so rounding in a flat
 * region's quadric moves nothing sideways). Where the minimiser lies farther (a survivor whose
 * planes meet far away, at a corner of faces it only touches), the step bends towards the
 * directions Q determines best instead of heading straight for that point, so a point on a flat
 * face stays on it. Assumes radius > 0.
 */
inline Eigen::Vector3d MinimizeQuadricWithin(
  const Quadric& q, const Eigen::Vector3d& x0, double radius, double relativeTolerance = 1e-6)
{
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig;
  eig.computeDirect(q.A());
  const Eigen::Vector3d lambda = eig.eigenvalues(); // ascending
  Eigen::Vector3d c = eig.eigenvectors().transpose() * (q.A() * x0 + q.B()); // the gradient / 2
  for (int i = 0; i < 3; ++i)
  {
    c(i) = lambda(i) > relativeTolerance * lambda(2) && lambda(i) > 0.0 ? c(i) : 0.0;
  }
  const auto step = [&](double mu) {
    Eigen::Vector3d d = Eigen::Vector3d::Zero();
    for (int i = 0; i < 3; ++i)
    {
      d(i) = c(i) != 0.0 ? -c(i) / (lambda(i) + mu) : 0.0;
    }
    return d;
  };
  if (!c.allFinite() || !(step(0.0).norm() > radius))
  {
    const Eigen::Vector3d x = x0 + eig.eigenvectors() * step(0.0);
    return x.allFinite() ? x : x0; // the minimiser is within reach (or nothing moves)
  }
  // |step(mu)| falls with mu and is at most |c| / mu: bisect on [0, |c| / radius].
  double low = 0.0, high = c.norm() / radius;
  for (int i = 0; i < 60; ++i)
  {
    const double mu = 0.5 * (low + high);
    (step(mu).norm() > radius ? low : high) = mu;
  }
  const Eigen::Vector3d x = x0 + eig.eigenvectors() * step(high);
  return x.allFinite() ? x : x0;
}

} // namespace meshsimp

#endif
