/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkTetExactArithmetic.h

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
/**
 * @file   vtkTetExactArithmetic.h
 * @brief  exact sign predicates and floating-point expansions (private, C++ only)
 *
 * The reference renderer decides which tetrahedra a ray crosses with exact predicates, so that
 * rays through vertices, along edges or inside face planes are classified consistently by all
 * the tetrahedra that share that vertex, edge or face. The arithmetic follows the classic
 * error-free transformations (Knuth's TwoSum, Dekker's TwoProduct with Veltkamp's splitting) and
 * nonoverlapping expansions in increasing order of magnitude (Shewchuk, "Adaptive Precision
 * Floating-Point Arithmetic and Fast Robust Geometric Predicates", 1997), written for this
 * project.
 *
 * Requirements: IEEE double arithmetic with round-to-nearest and no fused multiply-add
 * contraction (Rendering/CMakeLists.txt compiles the sources that include this header with
 * -ffp-contract=off), and operands far from overflow and underflow (|x| in [1e-140, 1e140] or
 * zero), which holds for coordinates of rendered meshes.
 */

#ifndef vtkTetExactArithmetic_h
#define vtkTetExactArithmetic_h

#include <cmath>

namespace vtkTetExact
{

/// x + y == a + b exactly, x = fl(a + b).
inline void TwoSum(double a, double b, double& x, double& y)
{
  x = a + b;
  const double bv = x - a;
  const double av = x - bv;
  y = (a - av) + (b - bv);
}

/// Veltkamp splitting: a == hi + lo exactly, each half with at most 26 significant bits.
inline void Split(double a, double& hi, double& lo)
{
  const double c = 134217729.0 * a; // 2^27 + 1
  const double big = c - a;
  hi = c - big;
  lo = a - hi;
}

/// x + y == a * b exactly, x = fl(a * b) (Dekker).
inline void TwoProduct(double a, double b, double& x, double& y)
{
  x = a * b;
  double ahi, alo, bhi, blo;
  Split(a, ahi, alo);
  Split(b, bhi, blo);
  const double err1 = x - ahi * bhi;
  const double err2 = err1 - alo * bhi;
  const double err3 = err2 - ahi * blo;
  y = alo * blo - err3;
}

/**
 * h = e + b for a nonoverlapping expansion e of n components sorted by increasing magnitude.
 * h has the same properties, no zero components, and at most n + 1 components; returns its
 * length (0 means the sum is exactly zero). h may not alias e.
 */
inline int GrowExpansion(int n, const double* e, double b, double* h)
{
  double q = b;
  int hn = 0;
  for (int i = 0; i < n; ++i)
  {
    double sum, err;
    TwoSum(q, e[i], sum, err);
    q = sum;
    if (err != 0.0)
    {
      h[hn++] = err;
    }
  }
  if (q != 0.0)
  {
    h[hn++] = q;
  }
  return hn;
}

/// h = e + f (expansions as above); h needs ne + nf entries and a scratch of the same size.
inline int ExpansionSum(
  int ne, const double* e, int nf, const double* f, double* h, double* scratch)
{
  int hn = ne;
  for (int i = 0; i < ne; ++i)
  {
    h[i] = e[i];
  }
  for (int i = 0; i < nf; ++i)
  {
    const int sn = GrowExpansion(hn, h, f[i], scratch);
    for (int k = 0; k < sn; ++k)
    {
      h[k] = scratch[k];
    }
    hn = sn;
  }
  return hn;
}

/// h = e * b; h needs 2 n entries and a scratch of the same size.
inline int ScaleExpansion(int n, const double* e, double b, double* h, double* scratch)
{
  int hn = 0;
  for (int i = 0; i < n; ++i)
  {
    double p, perr;
    TwoProduct(e[i], b, p, perr);
    const double part[2] = { perr, p };
    // TwoProduct's (perr, p) is itself a nonoverlapping expansion; grow it in.
    int sn = GrowExpansion(hn, h, part[0], scratch);
    hn = GrowExpansion(sn, scratch, part[1], h);
  }
  return hn;
}

/// Sign of an expansion: the sign of its largest (last) component.
inline int ExpansionSign(int n, const double* e)
{
  if (n == 0)
  {
    return 0;
  }
  return e[n - 1] > 0.0 ? 1 : -1;
}

/// Nearest double to an expansion, within a few units in the last place.
inline double ExpansionEstimate(int n, const double* e)
{
  double s = 0.0;
  for (int i = 0; i < n; ++i)
  {
    s += e[i];
  }
  return s;
}

/// The exact value of a*d - b*c as an expansion of at most 4 components; returns its length.
inline int Det2(double a, double b, double c, double d, double* h)
{
  double p, perr, q, qerr;
  TwoProduct(a, d, p, perr);
  TwoProduct(b, c, q, qerr);
  double t1[4], t2[4];
  const double pe[2] = { perr, p };
  int n = GrowExpansion(2, pe, -qerr, t1);
  n = GrowExpansion(n, t1, -q, t2);
  for (int i = 0; i < n; ++i)
  {
    h[i] = t2[i];
  }
  return n;
}

/**
 * Sign of E(a, b) = ax * by - ay * bx, the orientation of the origin O with respect to the
 * directed segment a -> b in the plane (positive: O lies to the left of a -> b), decided
 * exactly, with the ties broken by Simulation of Simplicity: O is perturbed to
 * (eps, eps^2) for an infinitesimal eps > 0, which gives
 * E + eps (ay - by) + eps^2 (bx - ax). The result is exactly antisymmetric in (a, b). It is zero
 * only when a and b coincide (a degenerate projected edge).
 */
inline int OriginOrientation(double ax, double ay, double bx, double by)
{
  const double p = ax * by;
  const double q = ay * bx;
  const double e = p - q;
  // |fl(p) - fl(q) - (p - q)| <= 2u(1+u)(|p| + |q|) with u = 2^-53; 3u leaves a margin.
  const double bound = 3.3306690738754716e-16 * (std::fabs(p) + std::fabs(q));
  if (e > bound)
  {
    return 1;
  }
  if (-e > bound)
  {
    return -1;
  }
  double h[4];
  const int n = Det2(ax, ay, bx, by, h);
  const int s = ExpansionSign(n, h);
  if (s != 0)
  {
    return s;
  }
  if (ay != by)
  {
    return ay > by ? 1 : -1;
  }
  if (bx != ax)
  {
    return bx > ax ? 1 : -1;
  }
  return 0;
}

} // namespace vtkTetExact

#endif
// VTK-HeaderTest-Exclude: vtkTetExactArithmetic.h
