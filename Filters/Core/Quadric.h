// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file Quadric.h
 * @brief Symmetric 4x4 error quadrics (Garland–Heckbert) and their robust minimiser.
 *
 * A quadric Q measures a weighted sum of squared distances to planes:
 * Q(v) = vᵀ A v + 2 bᵀ v + c, the expanded form of paper 000 eq. (1) and (6)–(7).
 * It is stored as 10 doubles (upper triangle of A, b, c) so arrays of quadrics stay flat.
 * The collapse- and clustering-based filters of this project share it.
 */
#ifndef MeshSimplification_Quadric_h
#define MeshSimplification_Quadric_h

#include <Eigen/Core>
#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>

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
 * Minimise Q (eq. 2–3) when its 3x3 block is well conditioned.
 * Conditioning is judged from the eigenvalues of A, not from det(A): the solve is accepted only
 * when λmin > relativeTolerance · λmax, so a nearly planar or nearly cylindrical set of planes
 * (rank 1 or 2) is reported as singular instead of producing a far-away point.
 */
inline bool MinimizeQuadric(const Quadric& q, Eigen::Vector3d& x, double relativeTolerance = 1e-6)
{
  const Eigen::Matrix3d a = q.A();
  // The closed-form eigenvalues suffice to judge conditioning; the solve itself uses a pivoted
  // LDLT, which is accurate to round-off where the closed-form eigenvectors are not.
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig;
  eig.computeDirect(a, Eigen::EigenvaluesOnly);
  const Eigen::Vector3d lambda = eig.eigenvalues(); // ascending
  if (!(lambda(2) > 0.0) || !(lambda(0) > relativeTolerance * lambda(2)))
  {
    return false;
  }
  x = a.ldlt().solve(-q.B());
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
  const Eigen::Matrix3d a = q.A();
  if (!(a.trace() > 0.0))
  {
    x = x0; // no planes at all
    return 0;
  }
  // Well conditioned: with the cofactors of A, det(A) / (tr(A) · Σ principal 2x2 minors) lies
  // within [λmin / 9λmax, λmin / λmax] (det / Σ minors ∈ [λmin / 3, λmin], tr ∈ [λmax, 3λmax]),
  // so the ratio judges conditioning without any eigenvalue, and the adjugate solves it.
  const double c00 = q.A11 * q.A22 - q.A12 * q.A12;
  const double c01 = q.A02 * q.A12 - q.A01 * q.A22;
  const double c02 = q.A01 * q.A12 - q.A02 * q.A11;
  const double c11 = q.A00 * q.A22 - q.A02 * q.A02;
  const double c12 = q.A01 * q.A02 - q.A00 * q.A12;
  const double c22 = q.A00 * q.A11 - q.A01 * q.A01;
  const double det = q.A00 * c00 + q.A01 * c01 + q.A02 * c02;
  if (det > relativeTolerance * a.trace() * (c00 + c11 + c22))
  {
    const double s = -1.0 / det;
    x = Eigen::Vector3d(s * (c00 * q.B0 + c01 * q.B1 + c02 * q.B2),
      s * (c01 * q.B0 + c11 * q.B1 + c12 * q.B2), s * (c02 * q.B0 + c12 * q.B1 + c22 * q.B2));
    if (x.allFinite())
    {
      return 3;
    }
  }
  // Rank-deficient: closed-form eigenvectors are accurate enough for the directions kept.
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

} // namespace meshsimp

#endif
