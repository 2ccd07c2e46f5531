/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkTetRayIntegrator.cxx

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "vtkTetRayIntegrator.h"

#include "vtkColorTransferFunction.h"
#include "vtkDiscretizableColorTransferFunction.h"
#include "vtkDoubleArray.h"
#include "vtkMath.h"
#include "vtkObjectFactory.h"
#include "vtkPiecewiseFunction.h"
#include "vtkSMPThreadLocal.h"
#include "vtkSmartPointer.h"
#include "vtkVolumeProperty.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstring>
#include <functional>
#include <limits>
#include <mutex>
#include <vector>

namespace
{
// Beyond this optical depth the transmittance (< 4.3e-18) no longer changes a double result.
constexpr double CutOffDepth = 40.0;
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

// One copy of the transfer functions, evaluated through VTK.
struct FunctionSet
{
  vtkSmartPointer<vtkColorTransferFunction> Color; // null when the gray function is used
  vtkSmartPointer<vtkPiecewiseFunction> Gray;
  vtkSmartPointer<vtkPiecewiseFunction> Opacity;
  double InverseUnitDistance = 1.0;

  // tau is clamped at 0: a negative attenuation has no physical meaning and would let the
  // transmittance grow without bound.
  void Evaluate(double s, double& tau, double c[3])
  {
    tau = std::max(0.0, this->Opacity->GetValue(s)) * this->InverseUnitDistance;
    if (this->Color)
    {
      this->Color->GetColor(s, c);
    }
    else
    {
      c[0] = c[1] = c[2] = this->Gray->GetValue(s);
    }
  }

  static vtkSmartPointer<vtkPiecewiseFunction> Clone(vtkPiecewiseFunction* f)
  {
    vtkSmartPointer<vtkPiecewiseFunction> copy = vtkSmartPointer<vtkPiecewiseFunction>::Take(
      vtkPiecewiseFunction::SafeDownCast(f->NewInstance()));
    // Duplicate nodes survive DeepCopy only if the copy allows them before the nodes arrive.
    copy->SetAllowDuplicateScalars(f->GetAllowDuplicateScalars());
    copy->DeepCopy(f);
    copy->SetClamping(f->GetClamping());
    copy->SetUseLogScale(f->GetUseLogScale());
    return copy;
  }

  static vtkSmartPointer<vtkColorTransferFunction> Clone(vtkColorTransferFunction* f)
  {
    vtkSmartPointer<vtkColorTransferFunction> copy =
      vtkSmartPointer<vtkColorTransferFunction>::Take(
        vtkColorTransferFunction::SafeDownCast(f->NewInstance()));
    copy->SetAllowDuplicateScalars(f->GetAllowDuplicateScalars());
    copy->DeepCopy(f);
    // What DeepCopy may leave out, depending on the VTK version.
    copy->SetClamping(f->GetClamping());
    copy->SetColorSpace(f->GetColorSpace());
    copy->SetHSVWrap(f->GetHSVWrap());
    copy->SetScale(f->GetScale());
    copy->SetNanColor(f->GetNanColor());
    copy->SetBelowRangeColor(f->GetBelowRangeColor());
    copy->SetUseBelowRangeColor(f->GetUseBelowRangeColor());
    copy->SetAboveRangeColor(f->GetAboveRangeColor());
    copy->SetUseAboveRangeColor(f->GetUseAboveRangeColor());
    // VTK 9.1's DeepCopy of a discretizable map leaves out its discretization (a copy of
    // ParaView's default map would be smooth) and its lookup table is built on demand.
    auto* discrete = vtkDiscretizableColorTransferFunction::SafeDownCast(f);
    auto* discreteCopy = vtkDiscretizableColorTransferFunction::SafeDownCast(copy);
    if (discrete && discreteCopy)
    {
      discreteCopy->SetDiscretize(discrete->GetDiscretize());
      discreteCopy->SetNumberOfValues(discrete->GetNumberOfValues());
      discreteCopy->SetIndexedLookup(discrete->GetIndexedLookup());
      discreteCopy->SetUseLogScale(discrete->GetUseLogScale());
      discrete->Build();
      discreteCopy->Build();
    }
    return copy;
  }

  void CopyFrom(const FunctionSet& other)
  {
    this->Color = other.Color ? Clone(other.Color) : nullptr;
    this->Gray = other.Gray ? Clone(other.Gray) : nullptr;
    this->Opacity = Clone(other.Opacity);
    this->InverseUnitDistance = other.InverseUnitDistance;
  }
};

struct ThreadSlot
{
  bool Ready = false;
  FunctionSet Functions;
};

// Node positions and per-interval linearity of one transfer function.
struct NodeLayout
{
  std::vector<double> X;
  std::vector<char> LinearPiece; // piece k is [X[k], X[k+1]]

  // Whether the function is linear on an open elementary interval that contains x (x strictly
  // between two consecutive breakpoints, so never equal to a node).
  bool LinearAt(double x) const
  {
    if (this->X.size() < 2 || x < this->X.front() || x > this->X.back())
    {
      return true; // constant outside the node range (clamped or zero)
    }
    const size_t k = std::upper_bound(this->X.begin(), this->X.end(), x) - this->X.begin();
    return this->LinearPiece[k - 1] != 0;
  }
};

// Midpoints are clamped the way VTK evaluates them.
double NodeMidpoint(double x0, double x1, double midpoint)
{
  midpoint = std::min(std::max(midpoint, 1e-5), 1.0 - 1e-5);
  return x0 + midpoint * (x1 - x0);
}

struct PieceResult
{
  double Depth = 0.0;
  double C[3] = { 0.0, 0.0, 0.0 };
  // Adaptive panels: an estimate of the integration error from how well the samples resolve
  // the attenuation and the emitted light (see vtkInternals::Panel).
  double Unresolved = 0.0;
  // Adaptive panels: the part of such estimates that rounding the samples' scalars to doubles
  // alone can cause (see vtkInternals::Panel); bisection cannot reduce an error below it.
  double Noise = 0.0;
};

// A piece followed by another: depths add, the second one is seen through the first.
PieceResult Combine(const PieceResult& front, const PieceResult& back)
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

// Closed form on a piece of length len where tau and c are linear (see the class
// documentation): C = c0 w0 + c1 w1 with w0 = Int_0^1 (1 - T), w1 = Int_0^1 (T - T(1)) in the
// normalised coordinate u, T(u) = exp(-Lambda(u)), Lambda(u) = u (a0 + r(u)) / 2,
// r(u) = a0 + (a1 - a0) u, a = tau len. Both integrands are positive and computed without
// cancellation (expm1, and Lambda(1) - Lambda(u) = (1 - u)(r(u) + a1) / 2).
PieceResult IntegrateLinearPiece(
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
} // namespace

//------------------------------------------------------------------------------
class vtkTetRayIntegrator::vtkInternals
{
public:
  bool Ready = false;
  FunctionSet Snapshot;
  std::vector<double> Breaks;
  // Elementary interval i is (Breaks[i-1], Breaks[i]) with Breaks[-1] = -inf and
  // Breaks[n] = +inf; on a linear interval the values at its ends are stored.
  struct Interval
  {
    bool Linear = false;
    bool Bounded = false;
    double X0 = 0.0, X1 = 0.0;
    double Tau0 = 0.0, Tau1 = 0.0;
    double C0[3] = { 0.0, 0.0, 0.0 };
    double C1[3] = { 0.0, 0.0, 0.0 };
  };
  std::vector<Interval> Intervals;
  mutable vtkSMPThreadLocal<ThreadSlot> Slots;
  mutable std::mutex CloneMutex;
  mutable std::atomic<vtkIdType> Unconverged{ 0 };

  FunctionSet& Local() const
  {
    ThreadSlot& slot = this->Slots.Local();
    if (!slot.Ready)
    {
      // Copying reads the snapshot only, but VTK does not promise that; serialise the copies
      // (once per thread).
      std::lock_guard<std::mutex> lock(this->CloneMutex);
      slot.Functions.CopyFrom(this->Snapshot);
      slot.Ready = true;
    }
    return slot.Functions;
  }

  size_t IntervalIndex(double s) const
  {
    return std::upper_bound(this->Breaks.begin(), this->Breaks.end(), s) - this->Breaks.begin();
  }

  void LinearValues(const Interval& iv, double s, double& tau, double c[3]) const
  {
    if (!iv.Bounded)
    {
      tau = iv.Tau0;
      c[0] = iv.C0[0];
      c[1] = iv.C0[1];
      c[2] = iv.C0[2];
      return;
    }
    const double f = (s - iv.X0) / (iv.X1 - iv.X0);
    tau = iv.Tau0 + (iv.Tau1 - iv.Tau0) * f;
    for (int i = 0; i < 3; ++i)
    {
      c[i] = iv.C0[i] + (iv.C1[i] - iv.C0[i]) * f;
    }
  }

  // One Gauss-Legendre panel [a, b] of the piece (t measured from the piece start, the scalar
  // going linearly from sa at t = 0 to sb at t = len).
  PieceResult Panel(FunctionSet& f, double sa, double sb, double len, double a, double b) const
  {
    const SpectralRule& rule = AdaptiveRule();
    const double h = 0.5 * (b - a), m = 0.5 * (b + a);
    double tau[AdaptiveOrder], c[AdaptiveOrder][3];
    for (int k = 0; k < AdaptiveOrder; ++k)
    {
      const double t = m + h * rule.G.X[k];
      const double s = sa + (sb - sa) * (t / len);
      f.Evaluate(s, tau[k], c[k]);
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

    // The scalar of a sample is only known to the rounding of sa + (sb - sa) t / len, a few
    // units in the last place of the larger end. Where the functions are steep in the scalar
    // (a transfer-function feature a millionth of the range wide, with a huge attenuation),
    // that rounding moves the samples of tau and of the emission by far more than the
    // tolerance: the estimates above then stop shrinking with the panel, and bisection went on
    // resolving rounding noise for ~1e5 panels per segment. Estimate that noise from the
    // slopes over the panel (the spread of the samples over the panel's scalar span) and the
    // most the two last coefficients and the halves' comparison can take from it; Adapt()
    // accepts a panel whose error is below this floor. Where the functions are not that steep
    // (every ordinary property), the floor is many orders of magnitude below the tolerance
    // and changes nothing.
    const double span = std::fabs(sb - sa) * ((b - a) / len);
    if (span > 0.0)
    {
      const double rounding = 4.0 * std::numeric_limits<double>::epsilon() *
        std::max(std::fabs(sa), std::fabs(sb)) / span;
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
    return r;
  }

  PieceResult Adapt(FunctionSet& f, double sa, double sb, double len, double a, double b,
    const PieceResult& coarse, double transmittance, double tolerance, int level) const
  {
    const double mid = 0.5 * (a + b);
    const PieceResult left = this->Panel(f, sa, sb, len, a, mid);
    const PieceResult right = this->Panel(f, sa, sb, len, mid, b);
    const PieceResult fine = Combine(left, right);
    double err = std::fabs(std::expm1(-fine.Depth) - std::expm1(-coarse.Depth));
    for (int i = 0; i < 3; ++i)
    {
      err = std::max(err, std::fabs(fine.C[i] - coarse.C[i]));
    }
    err = transmittance * std::max(err, left.Unresolved + right.Unresolved);
    // What rounding of the samples' scalars can explain (see Panel()) is no error to resolve.
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
      ++this->Unconverged;
      return fine;
    }
    const PieceResult l =
      this->Adapt(f, sa, sb, len, a, mid, left, transmittance, tolerance, level + 1);
    const PieceResult r = this->Adapt(
      f, sa, sb, len, mid, b, right, transmittance * std::exp(-l.Depth), tolerance, level + 1);
    return Combine(l, r);
  }

  PieceResult IntegrateAdaptive(
    double sa, double sb, double len, double transmittance, double tolerance) const
  {
    FunctionSet& f = this->Local();
    const PieceResult coarse = this->Panel(f, sa, sb, len, 0.0, len);
    return this->Adapt(f, sa, sb, len, 0.0, len, coarse, transmittance, tolerance, 0);
  }
};

//------------------------------------------------------------------------------
vtkStandardNewMacro(vtkTetRayIntegrator);

//------------------------------------------------------------------------------
vtkTetRayIntegrator::vtkTetRayIntegrator()
  : Tolerance(1e-11)
  , UseClosedForm(1)
  , Internals(new vtkInternals)
{
}

//------------------------------------------------------------------------------
vtkTetRayIntegrator::~vtkTetRayIntegrator()
{
  delete this->Internals;
}

//------------------------------------------------------------------------------
int vtkTetRayIntegrator::Initialize(vtkVolumeProperty* property)
{
  // Start from scratch: stale per-thread copies must not survive a new property.
  delete this->Internals;
  this->Internals = new vtkInternals;
  vtkInternals& in = *this->Internals;

  if (!property)
  {
    vtkErrorMacro("No volume property.");
    return 0;
  }
  const double unit = property->GetScalarOpacityUnitDistance(0);
  if (!(unit > 0.0) || !std::isfinite(unit))
  {
    vtkErrorMacro("The scalar opacity unit distance must be positive and finite, not " << unit);
    return 0;
  }
  vtkPiecewiseFunction* opacity = property->GetScalarOpacity(0);
  vtkColorTransferFunction* color = nullptr;
  vtkPiecewiseFunction* gray = nullptr;
  if (property->GetColorChannels(0) == 1)
  {
    gray = property->GetGrayTransferFunction(0);
  }
  else
  {
    color = property->GetRGBTransferFunction(0);
  }
  if (!opacity || (!color && !gray))
  {
    vtkErrorMacro("The volume property has no usable transfer functions.");
    return 0;
  }
  if (color && color->GetColorSpace() == VTK_CTF_LAB_CIEDE2000)
  {
    // VTK 9.1 searches a path through Lab space at every evaluation (about 35 ms each), which
    // makes an exact integral impractical.
    vtkErrorMacro("The LAB_CIEDE2000 colour space is not supported by the reference integrator.");
    return 0;
  }
  in.Snapshot.Opacity = FunctionSet::Clone(opacity);
  in.Snapshot.Color = color ? FunctionSet::Clone(color) : nullptr;
  in.Snapshot.Gray = gray ? FunctionSet::Clone(gray) : nullptr;
  in.Snapshot.InverseUnitDistance = 1.0 / unit;

  // Node layouts and linearity of each piece (see the class documentation).
  NodeLayout colorLayout, opacityLayout;
  std::vector<double> breaks;
  auto addPiecewise = [&breaks](vtkPiecewiseFunction* f, NodeLayout& layout)
  {
    const int n = f->GetSize();
    std::vector<double> mids(n), sharp(n);
    for (int i = 0; i < n; ++i)
    {
      double v[4];
      f->GetNodeValue(i, v);
      layout.X.push_back(v[0]);
      mids[i] = v[2];
      sharp[i] = v[3];
    }
    for (int i = 0; i + 1 < n; ++i)
    {
      const bool linear = mids[i] == 0.5 && sharp[i] < 0.01 && !f->GetUseLogScale();
      layout.LinearPiece.push_back(linear ? 1 : 0);
      if (!linear && layout.X[i + 1] > layout.X[i])
      {
        breaks.push_back(NodeMidpoint(layout.X[i], layout.X[i + 1], mids[i]));
      }
    }
    breaks.insert(breaks.end(), layout.X.begin(), layout.X.end());
  };
  addPiecewise(in.Snapshot.Opacity, opacityLayout);
  if (in.Snapshot.Gray)
  {
    addPiecewise(in.Snapshot.Gray, colorLayout);
  }
  else
  {
    vtkColorTransferFunction* f = in.Snapshot.Color;
    // Only plain RGB interpolation with a linear scale is linear between nodes; subclasses
    // (such as the discretizable function) may evaluate differently.
    const bool linearSpace = f->GetColorSpace() == VTK_CTF_RGB && f->GetScale() == VTK_CTF_LINEAR &&
      strcmp(f->GetClassName(), "vtkColorTransferFunction") == 0;
    const int n = f->GetSize();
    std::vector<double> mids(n), sharp(n);
    for (int i = 0; i < n; ++i)
    {
      double v[6];
      f->GetNodeValue(i, v);
      colorLayout.X.push_back(v[0]);
      mids[i] = v[4];
      sharp[i] = v[5];
    }
    // Diverging interpolation may pass through white half way between two nodes: a kink.
    const bool diverging = f->GetColorSpace() == VTK_CTF_DIVERGING;
    for (int i = 0; i + 1 < n; ++i)
    {
      if (diverging && colorLayout.X[i + 1] > colorLayout.X[i])
      {
        breaks.push_back(NodeMidpoint(colorLayout.X[i], colorLayout.X[i + 1], 0.5));
      }
      const bool linear = linearSpace && mids[i] == 0.5 && sharp[i] < 0.01;
      colorLayout.LinearPiece.push_back(linear ? 1 : 0);
      if (!(mids[i] == 0.5 && sharp[i] < 0.01) && colorLayout.X[i + 1] > colorLayout.X[i])
      {
        breaks.push_back(NodeMidpoint(colorLayout.X[i], colorLayout.X[i + 1], mids[i]));
      }
    }
    breaks.insert(breaks.end(), colorLayout.X.begin(), colorLayout.X.end());
  }
  breaks.erase(
    std::remove_if(breaks.begin(), breaks.end(), [](double x) { return !std::isfinite(x); }),
    breaks.end());
  std::sort(breaks.begin(), breaks.end());
  breaks.erase(std::unique(breaks.begin(), breaks.end()), breaks.end());

  // HSV interpolation bends the RGB components wherever the hue crosses a multiple of 1/6.
  // Adaptive quadrature can misjudge its error at such kinks, so they become breakpoints too:
  // found where the sextant of the hue of VTK's colours changes, between dense samples, then
  // by bisection to the last bit. A missed or misplaced bend only costs adaptive work.
  // Lab and diverging interpolation go through XYZ, and VTK clips the resulting RGB (a channel
  // below 0 becomes 0, a colour above 1 is scaled down): kinks wherever that clipping starts
  // or stops, found the same way from the clipping state of VTK's colours.
  const int space = in.Snapshot.Color ? in.Snapshot.Color->GetColorSpace() : VTK_CTF_RGB;
  if (space == VTK_CTF_HSV || space == VTK_CTF_LAB || space == VTK_CTF_DIVERGING)
  {
    vtkColorTransferFunction* f = in.Snapshot.Color;
    const bool hsvSpace = space == VTK_CTF_HSV;
    auto sextant = [f, hsvSpace](double x)
    {
      double rgb[3];
      f->GetColor(x, rgb);
      if (hsvSpace)
      {
        double hsv[3];
        vtkMath::RGBToHSV(rgb, hsv);
        return std::min(5, static_cast<int>(6.0 * hsv[0]));
      }
      return (rgb[0] == 0.0 ? 1 : 0) | (rgb[1] == 0.0 ? 2 : 0) | (rgb[2] == 0.0 ? 4 : 0) |
        (std::max(rgb[0], std::max(rgb[1], rgb[2])) == 1.0 ? 8 : 0);
    };
    // Every change of state between l and r (states sl and sr), down to adjacent doubles.
    std::function<void(double, int, double, int)> bisect = [&](double l, int sl, double r, int sr)
    {
      if (sl == sr)
      {
        return;
      }
      const double m = 0.5 * (l + r);
      if (!(m > l && m < r))
      {
        breaks.push_back(r);
        return;
      }
      const int sm = sextant(m);
      bisect(l, sl, m, sm);
      bisect(m, sm, r, sr);
    };
    const std::vector<double> pieces(breaks);
    for (size_t i = 0; i + 1 < pieces.size(); ++i)
    {
      const double lo = pieces[i], hi = pieces[i + 1];
      if (lo < colorLayout.X.front() || hi > colorLayout.X.back())
      {
        continue; // constant outside the node range
      }
      // The ends are sampled too: the colour is continuous at nodes, and a bend may lie
      // anywhere in the piece, right next to a node included.
      constexpr int samples = 256;
      double xa = lo;
      int ka = sextant(xa);
      for (int k = 1; k <= samples; ++k)
      {
        const double xb = k == samples ? hi : lo + (hi - lo) * k / samples;
        const int kb = sextant(xb);
        bisect(xa, ka, xb, kb);
        xa = xb;
        ka = kb;
      }
    }
    std::sort(breaks.begin(), breaks.end());
    breaks.erase(std::unique(breaks.begin(), breaks.end()), breaks.end());
  }
  in.Breaks = breaks;

  // The snapshot and the per-thread copies must evaluate exactly like the property's own
  // functions; check it on sample points (VTK versions differ in what DeepCopy carries over).
  FunctionSet original;
  original.Opacity = opacity;
  original.Color = color;
  original.Gray = gray;
  original.InverseUnitDistance = in.Snapshot.InverseUnitDistance;
  FunctionSet check;
  check.CopyFrom(in.Snapshot);
  std::vector<double> samples(breaks);
  for (size_t i = 0; i + 1 < breaks.size(); ++i)
  {
    samples.push_back(0.5 * (breaks[i] + breaks[i + 1]));
    samples.push_back(breaks[i] + 0.1234 * (breaks[i + 1] - breaks[i]));
  }
  if (!breaks.empty())
  {
    samples.push_back(breaks.front() - 1.0 - std::fabs(breaks.front()));
    samples.push_back(breaks.back() + 1.0 + std::fabs(breaks.back()));
  }
  for (double s : samples)
  {
    double t0, t1, t2, c0[3], c1[3], c2[3];
    original.Evaluate(s, t0, c0);
    in.Snapshot.Evaluate(s, t1, c1);
    check.Evaluate(s, t2, c2);
    if (t0 != t1 || c0[0] != c1[0] || c0[1] != c1[1] || c0[2] != c1[2] || t0 != t2 ||
      c0[0] != c2[0] || c0[1] != c2[1] || c0[2] != c2[2])
    {
      vtkErrorMacro("A copy of the transfer functions does not evaluate like the original (at "
        << s << "); cannot integrate thread-safely.");
      return 0;
    }
  }

  // Elementary intervals.
  const size_t nb = breaks.size();
  in.Intervals.resize(nb + 1);
  for (size_t i = 0; i <= nb; ++i)
  {
    vtkInternals::Interval& iv = in.Intervals[i];
    const bool hasLow = i > 0, hasHigh = i < nb;
    iv.Bounded = hasLow && hasHigh;
    iv.X0 = hasLow ? breaks[i - 1] : -std::numeric_limits<double>::infinity();
    iv.X1 = hasHigh ? breaks[i] : std::numeric_limits<double>::infinity();
    double probe;
    if (iv.Bounded)
    {
      probe = 0.5 * (iv.X0 + iv.X1);
    }
    else if (hasHigh)
    {
      probe = iv.X1 - 1.0 - std::fabs(iv.X1);
    }
    else if (hasLow)
    {
      probe = iv.X0 + 1.0 + std::fabs(iv.X0);
    }
    else
    {
      probe = 0.0;
    }
    iv.Linear = colorLayout.LinearAt(probe) && opacityLayout.LinearAt(probe);
    if (!iv.Linear)
    {
      continue;
    }
    // Values come from VTK itself, sampled strictly inside the interval (at a node VTK may
    // return either side's value) and extrapolated linearly to its ends; a third sample checks
    // that the function really is linear there.
    if (iv.Bounded)
    {
      const double xa = iv.X0 + 0.25 * (iv.X1 - iv.X0);
      const double xb = iv.X0 + 0.75 * (iv.X1 - iv.X0);
      double ta, tb, tm, ca[3], cb[3], cm[3];
      in.Snapshot.Evaluate(xa, ta, ca);
      in.Snapshot.Evaluate(xb, tb, cb);
      in.Snapshot.Evaluate(probe, tm, cm);
      auto linearOk = [](double va, double vb, double vm) {
        return std::fabs(vm - 0.5 * (va + vb)) <= 1e-12 * (std::fabs(va) + std::fabs(vb)) + 1e-300;
      };
      bool ok = linearOk(ta, tb, tm);
      for (int k = 0; k < 3; ++k)
      {
        ok = ok && linearOk(ca[k], cb[k], cm[k]);
      }
      if (!ok)
      {
        iv.Linear = false;
        continue;
      }
      iv.Tau0 = std::max(0.0, 1.5 * ta - 0.5 * tb);
      iv.Tau1 = std::max(0.0, 1.5 * tb - 0.5 * ta);
      for (int k = 0; k < 3; ++k)
      {
        iv.C0[k] = 1.5 * ca[k] - 0.5 * cb[k];
        iv.C1[k] = 1.5 * cb[k] - 0.5 * ca[k];
      }
    }
    else
    {
      double tf, cf[3];
      const double far = probe + (hasHigh ? -1.0 : 1.0) * (1.0 + std::fabs(probe));
      in.Snapshot.Evaluate(probe, iv.Tau0, iv.C0);
      in.Snapshot.Evaluate(far, tf, cf);
      if (tf != iv.Tau0 || cf[0] != iv.C0[0] || cf[1] != iv.C0[1] || cf[2] != iv.C0[2])
      {
        iv.Linear = false;
        continue;
      }
      iv.Tau1 = iv.Tau0;
      std::copy(iv.C0, iv.C0 + 3, iv.C1);
    }
  }
  in.Ready = true;
  this->Modified();
  return 1;
}

//------------------------------------------------------------------------------
bool vtkTetRayIntegrator::IsInitialized() const
{
  return this->Internals->Ready;
}

//------------------------------------------------------------------------------
void vtkTetRayIntegrator::Integrate(double sf, double sb, double length, double rgba[4]) const
{
  double depth;
  this->IntegrateWithDepth(sf, sb, length, rgba, &depth);
}

//------------------------------------------------------------------------------
void vtkTetRayIntegrator::IntegrateWithDepth(
  double sf, double sb, double length, double rgba[4], double* opticalDepth) const
{
  rgba[0] = rgba[1] = rgba[2] = rgba[3] = 0.0;
  if (opticalDepth)
  {
    *opticalDepth = 0.0;
  }
  const vtkInternals& in = *this->Internals;
  if (!in.Ready || !(length > 0.0) || !std::isfinite(length) || !std::isfinite(sf) ||
    !std::isfinite(sb))
  {
    return;
  }

  if (sf == sb)
  {
    // Constant scalar: VTK's own value at sf (exact at a node too), unless sf lies strictly
    // inside a linear interval.
    double tau, c[3];
    const size_t idx = in.IntervalIndex(sf);
    const bool atBreak = idx > 0 && in.Breaks[idx - 1] == sf;
    if (!atBreak && in.Intervals[idx].Linear && this->UseClosedForm)
    {
      in.LinearValues(in.Intervals[idx], sf, tau, c);
    }
    else
    {
      in.Local().Evaluate(sf, tau, c);
    }
    const double depth = tau * length;
    const double alpha = -std::expm1(-depth);
    for (int i = 0; i < 3; ++i)
    {
      rgba[i] = c[i] * alpha;
    }
    rgba[3] = alpha;
    if (opticalDepth)
    {
      *opticalDepth = depth;
    }
    return;
  }

  // Scalars where the segment must be split, in ray order.
  const bool ascending = sf < sb;
  const double lo = ascending ? sf : sb, hi = ascending ? sb : sf;
  const size_t first = std::upper_bound(in.Breaks.begin(), in.Breaks.end(), lo) - in.Breaks.begin();
  const size_t last = std::lower_bound(in.Breaks.begin(), in.Breaks.end(), hi) - in.Breaks.begin();
  const size_t inner = last > first ? last - first : 0;
  const double ds = sb - sf;

  double depth = 0.0;
  double color[3] = { 0.0, 0.0, 0.0 };
  bool cut = false;
  double sa = sf, ta = 0.0;
  for (size_t p = 0; p <= inner; ++p)
  {
    double se, te;
    if (p == inner)
    {
      se = sb;
      te = length;
    }
    else
    {
      se = ascending ? in.Breaks[first + p] : in.Breaks[last - 1 - p];
      te = length * ((se - sf) / ds);
    }
    const double len = te - ta;
    if (len > 0.0)
    {
      if (depth > CutOffDepth)
      {
        cut = true;
        break;
      }
      const double transmittance = std::exp(-depth);
      const size_t idx = in.IntervalIndex(0.5 * (sa + se));
      PieceResult piece;
      if (in.Intervals[idx].Linear && this->UseClosedForm)
      {
        double tau0, tau1, c0[3], c1[3];
        in.LinearValues(in.Intervals[idx], sa, tau0, c0);
        in.LinearValues(in.Intervals[idx], se, tau1, c1);
        piece = IntegrateLinearPiece(len, tau0, tau1, c0, c1);
      }
      else
      {
        piece = in.IntegrateAdaptive(sa, se, len, transmittance, this->Tolerance);
      }
      for (int i = 0; i < 3; ++i)
      {
        color[i] += transmittance * piece.C[i];
      }
      depth += piece.Depth;
    }
    sa = se;
    ta = te;
  }
  for (int i = 0; i < 3; ++i)
  {
    rgba[i] = color[i];
  }
  rgba[3] = -std::expm1(-depth);
  if (opticalDepth)
  {
    *opticalDepth = cut ? std::numeric_limits<double>::infinity() : depth;
  }
}

//------------------------------------------------------------------------------
int vtkTetRayIntegrator::GetNumberOfNodes() const
{
  return static_cast<int>(this->Internals->Breaks.size());
}

//------------------------------------------------------------------------------
double vtkTetRayIntegrator::GetNode(int i) const
{
  const std::vector<double>& b = this->Internals->Breaks;
  if (i < 0 || i >= static_cast<int>(b.size()))
  {
    vtkErrorMacro("Node index " << i << " out of range [0, " << b.size() << ").");
    return 0.0;
  }
  return b[i];
}

//------------------------------------------------------------------------------
void vtkTetRayIntegrator::GetNodes(vtkDoubleArray* nodes) const
{
  if (!nodes)
  {
    return;
  }
  const std::vector<double>& b = this->Internals->Breaks;
  nodes->SetNumberOfComponents(1);
  nodes->SetNumberOfTuples(static_cast<vtkIdType>(b.size()));
  for (size_t i = 0; i < b.size(); ++i)
  {
    nodes->SetValue(static_cast<vtkIdType>(i), b[i]);
  }
}

//------------------------------------------------------------------------------
bool vtkTetRayIntegrator::IsIntervalLinear(int i) const
{
  const vtkInternals& in = *this->Internals;
  if (!in.Ready || i < 0 || i >= static_cast<int>(in.Intervals.size()))
  {
    return false;
  }
  return in.Intervals[i].Linear;
}

//------------------------------------------------------------------------------
vtkIdType vtkTetRayIntegrator::GetNumberOfUnconvergedPanels() const
{
  return this->Internals->Unconverged.load();
}

//------------------------------------------------------------------------------
void vtkTetRayIntegrator::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Initialized: " << (this->Internals->Ready ? "yes" : "no") << "\n";
  os << indent << "NumberOfNodes: " << this->Internals->Breaks.size() << "\n";
  os << indent << "Tolerance: " << this->Tolerance << "\n";
  os << indent << "UseClosedForm: " << this->UseClosedForm << "\n";
  os << indent << "NumberOfUnconvergedPanels: " << this->Internals->Unconverged.load() << "\n";
}
