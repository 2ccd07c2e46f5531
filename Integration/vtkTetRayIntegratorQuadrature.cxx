/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkTetRayIntegratorQuadrature.cxx

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "vtkTetRayIntegratorQuadrature.h"

#include "vtkTetRayIntegratorFunctions.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace
{
using PieceResult = vtkTetRayIntegratorQuadrature::PieceResult;
constexpr double CutOffDepth = vtkTetRayIntegratorQuadrature::CutOffDepth;
// Closed form: Gauss-Legendre on panels of optical depth <= 2, with as many nodes as the
// panel's depth needs for a relative error of the colour weights below 5e-15 (measured against
// 80-bit quadrature; see the class documentation): most segments of a mesh are thin.
constexpr double ClosedPanelDepth = 2.0;
// Adaptive integration of non-linear pieces.
constexpr int AdaptiveOrder = 16;
constexpr int MaxBisections = 48;
constexpr double AdaptivePanelDepth = 2.0;

// Gauss-Legendre nodes and weights on [-1, 1], computed once in extended precision by Newton's
// iteration on the Legendre polynomial.
template <int N>
struct GaussLegendreRule
{
  double X[N];
  double W[N];
  GaussLegendreRule()
  {
    const long double pi = 3.141592653589793238462643383279502884L;
    for (int i = 0; i < N; ++i)
    {
      long double z = std::cos(pi * (i + 0.75L) / (N + 0.5L));
      long double dp = 1.0L;
      for (int iter = 0; iter < 100; ++iter)
      {
        long double p1 = 1.0L, p2 = 0.0L;
        for (int j = 0; j < N; ++j)
        {
          const long double p3 = p2;
          p2 = p1;
          p1 = ((2 * j + 1) * z * p2 - j * p3) / (j + 1);
        }
        dp = N * (z * p1 - p2) / (z * z - 1.0L);
        const long double step = p1 / dp;
        z -= step;
        if (std::fabs(step) < 1e-19L)
        {
          break;
        }
      }
      this->X[i] = static_cast<double>(-z);
      this->W[i] = static_cast<double>(2.0L / ((1.0L - z * z) * dp * dp));
    }
  }
};

// The 16-point rule plus its integration matrix S[k][j] = Int_{-1}^{x_k} l_j(x) dx (l_j the
// Lagrange basis on the nodes): applied to samples of tau, it gives the optical depth from the
// panel start to each node, exact for polynomials of degree < 16.
// Tail[q][k] gives the Legendre coefficient of degree 14 + q of a function sampled at the
// nodes: the size of the two last coefficients tells whether the samples resolve the function.
struct SpectralRule
{
  GaussLegendreRule<AdaptiveOrder> G;
  double S[AdaptiveOrder][AdaptiveOrder];
  double Tail[2][AdaptiveOrder];
  // Sum of |Tail[q][k]| over q and k: how much the two last coefficients can grow from an
  // error of at most 1 in each sample.
  double TailNorm = 0.0;
  SpectralRule()
  {
    for (int k = 0; k < AdaptiveOrder; ++k)
    {
      long double p0 = 1.0L, p1 = G.X[k];
      for (int n = 2; n <= AdaptiveOrder - 1; ++n)
      {
        const long double p2 = ((2 * n - 1) * G.X[k] * p1 - (n - 1) * p0) / n;
        p0 = p1;
        p1 = p2;
        if (n >= AdaptiveOrder - 2)
        {
          this->Tail[n - (AdaptiveOrder - 2)][k] =
            static_cast<double>((2 * n + 1) / 2.0L * G.W[k] * p1);
        }
      }
    }
    for (int k = 0; k < AdaptiveOrder; ++k)
    {
      this->TailNorm += std::fabs(this->Tail[0][k]) + std::fabs(this->Tail[1][k]);
    }
    for (int k = 0; k < AdaptiveOrder; ++k)
    {
      const long double a = -1.0L, b = G.X[k];
      const long double h = (b - a) / 2, m = (b + a) / 2;
      for (int j = 0; j < AdaptiveOrder; ++j)
      {
        long double sum = 0.0L;
        for (int q = 0; q < AdaptiveOrder; ++q)
        {
          const long double x = m + h * G.X[q];
          long double l = 1.0L;
          for (int r = 0; r < AdaptiveOrder; ++r)
          {
            if (r != j)
            {
              l *= (x - G.X[r]) / (static_cast<long double>(G.X[j]) - G.X[r]);
            }
          }
          sum += G.W[q] * l;
        }
        this->S[k][j] = static_cast<double>(h * sum);
      }
    }
  }
};

// Rules of 4, 5, 6, 8, 10 and 12 nodes, and the largest panel depth each one serves.
struct ClosedRules
{
  GaussLegendreRule<4> R4;
  GaussLegendreRule<5> R5;
  GaussLegendreRule<6> R6;
  GaussLegendreRule<8> R8;
  GaussLegendreRule<10> R10;
  GaussLegendreRule<12> R12;
};

const ClosedRules& ClosedRule()
{
  static const ClosedRules rules;
  return rules;
}

const SpectralRule& AdaptiveRule()
{
  static const SpectralRule rule;
  return rule;
}

// What the adaptive quadrature integrates along a piece of length len: Evaluate gives the
// attenuation and the colour at t in [0, len]; Rounding the relative rounding of the scalars of
// samples on the panel [a, b], against the scalar span of the panel (0 where no scalar varies),
// for EstimateRoundingNoise().
class SingleMedium
{
public:
  vtkTetRayIntegratorFunctions& F;
  double Sa, Sb; // the scalar at t = 0 and t = len

  void Evaluate(double t, double len, double& tau, double c[3])
  {
    const double s = this->Sa + (this->Sb - this->Sa) * (t / len);
    this->F.Evaluate(s, tau, c);
  }

  double Rounding(double len, double a, double b) const
  {
    const double span = std::fabs(this->Sb - this->Sa) * ((b - a) / len);
    return span > 0.0 ? 4.0 * std::numeric_limits<double>::epsilon() *
        std::max(std::fabs(this->Sa), std::fabs(this->Sb)) / span
                      : 0.0;
  }
};

// Several media overlapping along the piece: attenuation sum(tau_i), colour sum(tau_i c_i) /
// sum(tau_i) (so that the emission tau c is sum(tau_i c_i); the colour is the media's mean where
// no medium attenuates, and emits nothing there).
class MixtureMedia
{
public:
  const std::vector<vtkTetRayIntegratorQuadrature::Medium>& Media;

  void Evaluate(double t, double len, double& tau, double c[3])
  {
    double emission[3] = { 0.0, 0.0, 0.0 }, mean[3] = { 0.0, 0.0, 0.0 };
    tau = 0.0;
    for (const vtkTetRayIntegratorQuadrature::Medium& m : this->Media)
    {
      const double s = m.S0 + (m.S1 - m.S0) * (t / len);
      double taui, ci[3];
      m.Functions->Evaluate(s, taui, ci);
      tau += taui;
      for (int i = 0; i < 3; ++i)
      {
        emission[i] += taui * ci[i];
        mean[i] += ci[i] / static_cast<double>(this->Media.size());
      }
    }
    for (int i = 0; i < 3; ++i)
    {
      c[i] = tau > 0.0 ? emission[i] / tau : mean[i];
    }
  }

  // The largest of the media's: the noise floor may then be a little generous for the media
  // whose scalars round less, which only matters on features near the rounding of the scalar.
  double Rounding(double len, double a, double b) const
  {
    double rounding = 0.0;
    for (const vtkTetRayIntegratorQuadrature::Medium& m : this->Media)
    {
      vtkTetRayIntegratorFunctions* f = m.Functions;
      const SingleMedium single{ *f, m.S0, m.S1 };
      rounding = std::max(rounding, single.Rounding(len, a, b));
    }
    return rounding;
  }
};
} // namespace

//------------------------------------------------------------------------------
vtkTetRayIntegratorQuadrature::PieceResult vtkTetRayIntegratorQuadrature::Combine(
  const PieceResult& front, const PieceResult& back)
{
  PieceResult r;
  const double t = std::exp(-front.Depth);
  r.Depth = front.Depth + back.Depth;
  for (int i = 0; i < 3; ++i)
  {
    r.C[i] = front.C[i] + t * back.C[i];
  }
  return r;
}

//------------------------------------------------------------------------------
// Closed form on a piece of length len where tau and c are linear (see the class
// documentation): C = c0 w0 + c1 w1 with w0 = Int_0^1 (1 - T), w1 = Int_0^1 (T - T(1)) in the
// normalised coordinate u, T(u) = exp(-Lambda(u)), Lambda(u) = u (a0 + r(u)) / 2,
// r(u) = a0 + (a1 - a0) u, a = tau len. Both integrands are positive and computed without
// cancellation (expm1, and Lambda(1) - Lambda(u) = (1 - u)(r(u) + a1) / 2).
vtkTetRayIntegratorQuadrature::PieceResult vtkTetRayIntegratorQuadrature::IntegrateLinear(
  double len, double tau0, double tau1, const double c0[3], const double c1[3])
{
  PieceResult r;
  const double a0 = tau0 * len, a1 = tau1 * len;
  const double depth = 0.5 * (a0 + a1);
  r.Depth = depth;
  if (!(depth > 0.0))
  {
    return r;
  }
  const ClosedRules& rules = ClosedRule();
  const bool truncated = depth > CutOffDepth;
  const double usedDepth = truncated ? CutOffDepth : depth;
  const int panels = std::max(1, static_cast<int>(std::ceil(usedDepth / ClosedPanelDepth)));
  const double panelDepth = usedDepth / panels;
  const double slope = a1 - a0;
  double w0 = 0.0, w1 = 0.0;
  double ua = 0.0;
  for (int p = 1; p <= panels; ++p)
  {
    double ub;
    if (p == panels && !truncated)
    {
      ub = 1.0;
    }
    else
    {
      // Lambda(u) = y solved in the form without cancellation.
      const double y = p * panelDepth;
      const double disc = std::max(0.0, a0 * a0 + 2.0 * slope * y);
      ub = std::min(1.0, 2.0 * y / (a0 + std::sqrt(disc)));
    }
    const double h = 0.5 * (ub - ua), m = 0.5 * (ub + ua);
    auto accumulate = [&](const auto& rule)
    {
      const int n = static_cast<int>(sizeof(rule.X) / sizeof(rule.X[0]));
      for (int i = 0; i < n; ++i)
      {
        const double u = m + h * rule.X[i];
        const double ru = a0 + slope * u;
        const double lambda = 0.5 * u * (a0 + ru);
        const double rest = 0.5 * (1.0 - u) * (ru + a1);
        w0 += h * rule.W[i] * -std::expm1(-lambda);
        w1 += h * rule.W[i] * std::exp(-lambda) * -std::expm1(-rest);
      }
    };
    if (panelDepth <= 1e-3)
    {
      accumulate(rules.R4);
    }
    else if (panelDepth <= 0.02)
    {
      accumulate(rules.R5);
    }
    else if (panelDepth <= 0.1)
    {
      accumulate(rules.R6);
    }
    else if (panelDepth <= 0.3)
    {
      accumulate(rules.R8);
    }
    else if (panelDepth <= 1.0)
    {
      accumulate(rules.R10);
    }
    else
    {
      accumulate(rules.R12);
    }
    ua = ub;
  }
  if (truncated)
  {
    // Past the cut-off 1 - T equals 1 and T - T(1) is below exp(-40).
    w0 += 1.0 - ua;
  }
  for (int i = 0; i < 3; ++i)
  {
    r.C[i] = c0[i] * w0 + c1[i] * w1;
  }
  return r;
}

//------------------------------------------------------------------------------
// One Gauss-Legendre panel [a, b] of the piece (t measured from the piece start, the scalar
// going linearly from sa at t = 0 to sb at t = len).
template <typename Evaluator>
vtkTetRayIntegratorQuadrature::PieceResult vtkTetRayIntegratorQuadrature::Panel(
  Evaluator& f, double len, double a, double b)
{
  const SpectralRule& rule = AdaptiveRule();
  const double h = 0.5 * (b - a), m = 0.5 * (b + a);
  double tau[AdaptiveOrder], c[AdaptiveOrder][3];
  for (int k = 0; k < AdaptiveOrder; ++k)
  {
    const double t = m + h * rule.G.X[k];
    f.Evaluate(t, len, tau[k], c[k]);
  }
  PieceResult r;
  double depth = 0.0;
  double emission[3][AdaptiveOrder];
  for (int k = 0; k < AdaptiveOrder; ++k)
  {
    depth += rule.G.W[k] * tau[k];
    double local = 0.0;
    for (int j = 0; j < AdaptiveOrder; ++j)
    {
      local += rule.S[k][j] * tau[j];
    }
    const double e = tau[k] * std::exp(-h * local);
    for (int i = 0; i < 3; ++i)
    {
      emission[i][k] = e * c[k][i];
      r.C[i] += h * rule.G.W[k] * emission[i][k];
    }
  }
  r.Depth = h * depth;
  // Comparing a panel with its halves alone can miss a kink (hue bends of HSV, the
  // piecewise formulas of Lab): the quadrature error oscillates with the kink's position.
  // The last Legendre coefficients of the sampled functions do not: for a smooth function
  // they are far below the integration error bound 2h(|a14| + |a15|), for a kink they stay
  // large until the panel holding it is small.
  auto tail = [&rule](const double* v)
  {
    double a14 = 0.0, a15 = 0.0;
    for (int k = 0; k < AdaptiveOrder; ++k)
    {
      a14 += rule.Tail[0][k] * v[k];
      a15 += rule.Tail[1][k] * v[k];
    }
    return std::fabs(a14) + std::fabs(a15);
  };
  double unresolved = tail(tau);
  for (int i = 0; i < 3; ++i)
  {
    unresolved = std::max(unresolved, tail(emission[i]));
  }
  r.Unresolved = 2.0 * h * unresolved;

  EstimateRoundingNoise(f, tau, c, len, a, b, r);
  return r;
}

//------------------------------------------------------------------------------
template <typename Evaluator>
void vtkTetRayIntegratorQuadrature::EstimateRoundingNoise(const Evaluator& f, const double tau[],
  const double c[][3], double len, double a, double b, PieceResult& r)
{
  const SpectralRule& rule = AdaptiveRule();
  const double h = 0.5 * (b - a);
  // The scalar of a sample is only known to the rounding of sa + (sb - sa) t / len, a few
  // units in the last place of the larger end. Where the functions are steep in the scalar
  // (a transfer-function feature a millionth of the range wide, with a huge attenuation),
  // that rounding moves the samples of tau and of the emission by far more than the
  // tolerance: Panel()'s estimates then stop shrinking with the panel, and bisection went on
  // resolving rounding noise for ~1e5 panels per segment. Estimate that noise from the
  // slopes over the panel (the spread of the samples over the panel's scalar span) and the
  // most the two last coefficients and the halves' comparison can take from it; Adapt()
  // accepts a panel whose error is below this floor. Where the functions are not that steep
  // (every ordinary property), the floor is many orders of magnitude below the tolerance
  // and changes nothing.
  const double rounding = f.Rounding(len, a, b);
  if (rounding > 0.0)
  {
    double tauMin = tau[0], tauMax = tau[0];
    double cMin[3] = { c[0][0], c[0][1], c[0][2] };
    double cMax[3] = { c[0][0], c[0][1], c[0][2] };
    for (int k = 1; k < AdaptiveOrder; ++k)
    {
      tauMin = std::min(tauMin, tau[k]);
      tauMax = std::max(tauMax, tau[k]);
      for (int i = 0; i < 3; ++i)
      {
        cMin[i] = std::min(cMin[i], c[k][i]);
        cMax[i] = std::max(cMax[i], c[k][i]);
      }
    }
    const double tauNoise = rounding * (tauMax - tauMin);
    double emissionNoise = 0.0;
    for (int i = 0; i < 3; ++i)
    {
      const double cAbs = std::max(std::fabs(cMin[i]), std::fabs(cMax[i]));
      emissionNoise =
        std::max(emissionNoise, tauNoise * cAbs + tauMax * rounding * (cMax[i] - cMin[i]));
    }
    r.Noise = 2.0 * h * (rule.TailNorm + 2.0) * std::max(tauNoise, emissionNoise);
  }
}

//------------------------------------------------------------------------------
template <typename Evaluator>
vtkTetRayIntegratorQuadrature::PieceResult vtkTetRayIntegratorQuadrature::Adapt(Evaluator& f,
  double len, double a, double b, const PieceResult& coarse, double transmittance, double tolerance,
  int level, std::atomic<vtkIdType>& unconverged)
{
  const double mid = 0.5 * (a + b);
  const PieceResult left = Panel(f, len, a, mid);
  const PieceResult right = Panel(f, len, mid, b);
  const PieceResult fine = Combine(left, right);
  double err = std::fabs(std::expm1(-fine.Depth) - std::expm1(-coarse.Depth));
  for (int i = 0; i < 3; ++i)
  {
    err = std::max(err, std::fabs(fine.C[i] - coarse.C[i]));
  }
  err = transmittance * std::max(err, left.Unresolved + right.Unresolved);
  // What rounding of the samples' scalars can explain (see EstimateRoundingNoise()) is no error to
  // resolve.
  const double noise = transmittance * (coarse.Noise + left.Noise + right.Noise);
  // Each panel may use the share of the tolerance its length deserves, and at least 1/64 of
  // it: around a jump the error shrinks only like the panel, so a share proportional to the
  // length would never be met there.
  const double allowed = tolerance * std::max((b - a) / len, 1.0 / 64.0);
  const bool resolved = coarse.Depth <= AdaptivePanelDepth;
  if ((resolved && err <= std::max(allowed, noise)) || transmittance < 1e-17)
  {
    return fine;
  }
  if (level >= MaxBisections || !(mid > a && mid < b))
  {
    ++unconverged;
    return fine;
  }
  const PieceResult l =
    Adapt(f, len, a, mid, left, transmittance, tolerance, level + 1, unconverged);
  const PieceResult r = Adapt(
    f, len, mid, b, right, transmittance * std::exp(-l.Depth), tolerance, level + 1, unconverged);
  return Combine(l, r);
}

//------------------------------------------------------------------------------
vtkTetRayIntegratorQuadrature::PieceResult vtkTetRayIntegratorQuadrature::IntegrateAdaptive(
  vtkTetRayIntegratorFunctions& f, double sa, double sb, double len, double transmittance,
  double tolerance, std::atomic<vtkIdType>& unconverged)
{
  SingleMedium single{ f, sa, sb };
  const PieceResult coarse = Panel(single, len, 0.0, len);
  return Adapt(single, len, 0.0, len, coarse, transmittance, tolerance, 0, unconverged);
}

//------------------------------------------------------------------------------
vtkTetRayIntegratorQuadrature::PieceResult vtkTetRayIntegratorQuadrature::IntegrateAdaptiveMixture(
  const std::vector<Medium>& media, double len, double transmittance, double tolerance,
  std::atomic<vtkIdType>& unconverged)
{
  MixtureMedia mixture{ media };
  const PieceResult coarse = Panel(mixture, len, 0.0, len);
  return Adapt(mixture, len, 0.0, len, coarse, transmittance, tolerance, 0, unconverged);
}

//------------------------------------------------------------------------------
// The closed form of a mixture (see the header): in the normalised coordinate u of the piece,
// A(u) = sum_i len tau_i(u) is linear, the optical depth Lambda(u) = u (A(0) + A(u)) / 2 is
// quadratic and C = len Int_0^1 sum_i tau_i(u) c_i(u) exp(-Lambda(u)) du. The integrand is a
// polynomial of degree 2 times exp(-Lambda), positive: 12-point Gauss-Legendre on panels over
// which Lambda grows by at most 2 leaves a relative error far below 1e-15 (the single medium's
// ladder of rules, one degree short for this integrand, is not reused). Past the cut-off depth
// the rest contributes below exp(-40) max(c).
vtkTetRayIntegratorQuadrature::PieceResult vtkTetRayIntegratorQuadrature::IntegrateLinearMixture(
  double len, const std::vector<double>& tau0, const std::vector<double>& tau1,
  const std::vector<double>& c0, const std::vector<double>& c1)
{
  PieceResult r;
  const size_t n = tau0.size();
  double sum0 = 0.0, sum1 = 0.0;
  for (size_t i = 0; i < n; ++i)
  {
    sum0 += tau0[i];
    sum1 += tau1[i];
  }
  const double a0 = sum0 * len, a1 = sum1 * len;
  const double depth = 0.5 * (a0 + a1);
  r.Depth = depth;
  if (!(depth > 0.0))
  {
    return r;
  }
  const GaussLegendreRule<12>& rule = ClosedRule().R12;
  const bool truncated = depth > CutOffDepth;
  const double usedDepth = truncated ? CutOffDepth : depth;
  const int panels = std::max(1, static_cast<int>(std::ceil(usedDepth / ClosedPanelDepth)));
  const double panelDepth = usedDepth / panels;
  const double slope = a1 - a0;
  double ua = 0.0;
  for (int p = 1; p <= panels; ++p)
  {
    double ub = 1.0;
    if (p < panels || truncated)
    {
      const double y = p * panelDepth;
      const double disc = std::max(0.0, a0 * a0 + 2.0 * slope * y);
      ub = std::min(1.0, 2.0 * y / (a0 + std::sqrt(disc)));
    }
    const double h = 0.5 * (ub - ua), m = 0.5 * (ub + ua);
    for (int k = 0; k < 12; ++k)
    {
      const double u = m + h * rule.X[k];
      const double lambda = 0.5 * u * (a0 + (a0 + slope * u));
      const double w = h * rule.W[k] * len * std::exp(-lambda);
      for (size_t i = 0; i < n; ++i)
      {
        const double taui = tau0[i] + (tau1[i] - tau0[i]) * u;
        for (int q = 0; q < 3; ++q)
        {
          const double ci = c0[3 * i + q] + (c1[3 * i + q] - c0[3 * i + q]) * u;
          r.C[q] += w * taui * ci;
        }
      }
    }
    ua = ub;
  }
  return r;
}
