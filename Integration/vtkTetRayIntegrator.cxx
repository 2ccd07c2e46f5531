/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkTetRayIntegrator.cxx

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "vtkTetRayIntegrator.h"

#include "vtkColorTransferFunction.h"
#include "vtkDoubleArray.h"
#include "vtkObjectFactory.h"
#include "vtkPiecewiseFunction.h"
#include "vtkSMPThreadLocal.h"
#include "vtkSmartPointer.h"
#include "vtkTetRayIntegratorFunctions.h"
#include "vtkTetRayIntegratorIntervals.h"
#include "vtkTetRayIntegratorQuadrature.h"
#include "vtkVolumeProperty.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <mutex>
#include <vector>

// The integrator's set-up and its two kinds of pieces are private classes of their own:
// vtkTetRayIntegratorFunctions (the copies of the transfer functions it evaluates),
// vtkTetRayIntegratorIntervals (breakpoints, and which elementary intervals are linear) and
// vtkTetRayIntegratorQuadrature (closed form on linear pieces, adaptive quadrature elsewhere).

//------------------------------------------------------------------------------
class vtkTetRayIntegrator::vtkInternals
{
public:
  // One copy of the transfer functions per thread, made from the snapshot on first use.
  struct ThreadSlot
  {
    bool Ready = false;
    vtkTetRayIntegratorFunctions Functions;
  };

  bool Ready = false;
  vtkTetRayIntegratorFunctions Snapshot;
  vtkTetRayIntegratorIntervals Pieces;
  mutable vtkSMPThreadLocal<ThreadSlot> Slots;
  mutable std::mutex CloneMutex;
  mutable std::atomic<vtkIdType> Unconverged{ 0 };

  vtkTetRayIntegratorFunctions& Local() const
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

  // One piece of IntegrateMixture() (see there).
  static vtkTetRayIntegratorQuadrature::PieceResult MixturePiece(const std::vector<int>& media,
    vtkTetRayIntegrator* const integrators[], const double sf[], const double sb[], double ua,
    double ub, double len, double transmittance, double tolerance);
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
  in.Snapshot.Opacity = vtkTetRayIntegratorFunctions::Clone(opacity);
  in.Snapshot.Color = color ? vtkTetRayIntegratorFunctions::Clone(color) : nullptr;
  in.Snapshot.Gray = gray ? vtkTetRayIntegratorFunctions::Clone(gray) : nullptr;
  in.Snapshot.InverseUnitDistance = 1.0 / unit;

  // Breakpoints and the kind of each piece between them (see the class documentation).
  in.Pieces.FindBreaks(in.Snapshot);
  if (!this->CheckCopies(opacity, color, gray))
  {
    return 0;
  }
  in.Pieces.BuildIntervals(in.Snapshot);
  in.Ready = true;
  this->Modified();
  return 1;
}

//------------------------------------------------------------------------------
bool vtkTetRayIntegrator::CheckCopies(
  vtkPiecewiseFunction* opacity, vtkColorTransferFunction* color, vtkPiecewiseFunction* gray)
{
  vtkInternals& in = *this->Internals;
  // The snapshot and the per-thread copies must evaluate exactly like the property's own
  // functions; check it on sample points (VTK versions differ in what DeepCopy carries over).
  vtkTetRayIntegratorFunctions original;
  original.Opacity = opacity;
  original.Color = color;
  original.Gray = gray;
  original.InverseUnitDistance = in.Snapshot.InverseUnitDistance;
  vtkTetRayIntegratorFunctions check;
  check.CopyFrom(in.Snapshot);
  const std::vector<double>& breaks = in.Pieces.Breaks;
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
      return false;
    }
  }
  return true;
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
    const size_t idx = in.Pieces.IntervalIndex(sf);
    const bool atBreak = idx > 0 && in.Pieces.Breaks[idx - 1] == sf;
    if (!atBreak && in.Pieces.Intervals[idx].Linear && this->UseClosedForm)
    {
      in.Pieces.LinearValues(in.Pieces.Intervals[idx], sf, tau, c);
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
  const size_t first = std::upper_bound(in.Pieces.Breaks.begin(), in.Pieces.Breaks.end(), lo) -
    in.Pieces.Breaks.begin();
  const size_t last = std::lower_bound(in.Pieces.Breaks.begin(), in.Pieces.Breaks.end(), hi) -
    in.Pieces.Breaks.begin();
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
      se = ascending ? in.Pieces.Breaks[first + p] : in.Pieces.Breaks[last - 1 - p];
      te = length * ((se - sf) / ds);
    }
    const double len = te - ta;
    if (len > 0.0)
    {
      if (depth > vtkTetRayIntegratorQuadrature::CutOffDepth)
      {
        cut = true;
        break;
      }
      const double transmittance = std::exp(-depth);
      const size_t idx = in.Pieces.IntervalIndex(0.5 * (sa + se));
      vtkTetRayIntegratorQuadrature::PieceResult piece;
      if (in.Pieces.Intervals[idx].Linear && this->UseClosedForm)
      {
        double tau0, tau1, c0[3], c1[3];
        in.Pieces.LinearValues(in.Pieces.Intervals[idx], sa, tau0, c0);
        in.Pieces.LinearValues(in.Pieces.Intervals[idx], se, tau1, c1);
        piece = vtkTetRayIntegratorQuadrature::IntegrateLinear(len, tau0, tau1, c0, c1);
      }
      else
      {
        piece = vtkTetRayIntegratorQuadrature::IntegrateAdaptive(
          in.Local(), sa, se, len, transmittance, this->Tolerance, in.Unconverged);
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
void vtkTetRayIntegrator::IntegrateMixture(int numberOfMedia,
  vtkTetRayIntegrator* const integrators[], const double sf[], const double sb[], double length,
  double rgba[4], double* opticalDepth)
{
  rgba[0] = rgba[1] = rgba[2] = rgba[3] = 0.0;
  if (opticalDepth)
  {
    *opticalDepth = 0.0;
  }
  if (!(length > 0.0) || !std::isfinite(length))
  {
    return;
  }
  // The media that contribute (as IntegrateWithDepth() leaves the others out).
  std::vector<int> media;
  for (int i = 0; i < numberOfMedia; ++i)
  {
    if (integrators[i] && integrators[i]->Internals->Ready && std::isfinite(sf[i]) &&
      std::isfinite(sb[i]))
    {
      media.push_back(i);
    }
  }
  if (media.empty())
  {
    return;
  }
  if (media.size() == 1)
  {
    const int i = media[0];
    integrators[i]->IntegrateWithDepth(sf[i], sb[i], length, rgba, opticalDepth);
    return;
  }

  // Where any medium crosses one of its breakpoints, as a fraction u of the segment.
  std::vector<double> cuts = { 0.0 };
  double tolerance = 1.0;
  for (int i : media)
  {
    tolerance = std::min(tolerance, integrators[i]->Tolerance);
    const std::vector<double>& breaks = integrators[i]->Internals->Pieces.Breaks;
    const double lo = std::min(sf[i], sb[i]), hi = std::max(sf[i], sb[i]);
    for (auto b = std::upper_bound(breaks.begin(), breaks.end(), lo); b != breaks.end() && *b < hi;
         ++b)
    {
      const double u = (*b - sf[i]) / (sb[i] - sf[i]);
      if (u > 0.0 && u < 1.0)
      {
        cuts.push_back(u);
      }
    }
  }
  std::sort(cuts.begin(), cuts.end());
  cuts.erase(std::unique(cuts.begin(), cuts.end()), cuts.end());
  cuts.push_back(1.0);

  vtkTetRayIntegratorQuadrature::PieceResult total;
  bool cut = false;
  double ta = 0.0;
  for (size_t p = 0; p + 1 < cuts.size(); ++p)
  {
    const double te = p + 2 == cuts.size() ? length : length * cuts[p + 1];
    const double len = te - ta;
    if (len > 0.0)
    {
      if (total.Depth > vtkTetRayIntegratorQuadrature::CutOffDepth)
      {
        cut = true;
        break;
      }
      const vtkTetRayIntegratorQuadrature::PieceResult piece = vtkInternals::MixturePiece(
        media, integrators, sf, sb, cuts[p], cuts[p + 1], len, std::exp(-total.Depth), tolerance);
      total = vtkTetRayIntegratorQuadrature::Combine(total, piece);
    }
    ta = te;
  }
  for (int i = 0; i < 3; ++i)
  {
    rgba[i] = total.C[i];
  }
  rgba[3] = -std::expm1(-total.Depth);
  if (opticalDepth)
  {
    *opticalDepth = cut ? std::numeric_limits<double>::infinity() : total.Depth;
  }
}

//------------------------------------------------------------------------------
// One piece [ua, ub] (fractions of the segment, length len) of a mixture, on which no medium
// crosses a breakpoint: in closed form where every medium is linear there, adaptively otherwise.
vtkTetRayIntegratorQuadrature::PieceResult vtkTetRayIntegrator::vtkInternals::MixturePiece(
  const std::vector<int>& media, vtkTetRayIntegrator* const integrators[], const double sf[],
  const double sb[], double ua, double ub, double len, double transmittance, double tolerance)
{
  const size_t n = media.size();
  std::vector<double> tau0(n), tau1(n), c0(3 * n), c1(3 * n);
  std::vector<vtkTetRayIntegratorQuadrature::Medium> adaptive(n);
  bool linear = true;
  for (size_t k = 0; k < n; ++k)
  {
    const int i = media[k];
    const vtkInternals& in = *integrators[i]->Internals;
    const double sa = ua == 0.0 ? sf[i] : sf[i] + (sb[i] - sf[i]) * ua;
    const double se = ub == 1.0 ? sb[i] : sf[i] + (sb[i] - sf[i]) * ub;
    const size_t idx = in.Pieces.IntervalIndex(0.5 * (sa + se));
    // A constant scalar on a breakpoint takes VTK's own value there, as IntegrateWithDepth().
    const bool atBreak = sa == se && idx > 0 && in.Pieces.Breaks[idx - 1] == sa;
    if (linear && !atBreak && in.Pieces.Intervals[idx].Linear && integrators[i]->UseClosedForm)
    {
      in.Pieces.LinearValues(in.Pieces.Intervals[idx], sa, tau0[k], &c0[3 * k]);
      in.Pieces.LinearValues(in.Pieces.Intervals[idx], se, tau1[k], &c1[3 * k]);
    }
    else
    {
      linear = false;
    }
    adaptive[k].Functions = &in.Local();
    adaptive[k].S0 = sa;
    adaptive[k].S1 = se;
  }
  if (linear)
  {
    return vtkTetRayIntegratorQuadrature::IntegrateLinearMixture(len, tau0, tau1, c0, c1);
  }
  return vtkTetRayIntegratorQuadrature::IntegrateAdaptiveMixture(
    adaptive, len, transmittance, tolerance, integrators[media[0]]->Internals->Unconverged);
}

//------------------------------------------------------------------------------
int vtkTetRayIntegrator::GetNumberOfNodes() const
{
  return static_cast<int>(this->Internals->Pieces.Breaks.size());
}

//------------------------------------------------------------------------------
double vtkTetRayIntegrator::GetNode(int i) const
{
  const std::vector<double>& b = this->Internals->Pieces.Breaks;
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
  const std::vector<double>& b = this->Internals->Pieces.Breaks;
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
  if (!in.Ready || i < 0 || i >= static_cast<int>(in.Pieces.Intervals.size()))
  {
    return false;
  }
  return in.Pieces.Intervals[i].Linear;
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
  os << indent << "NumberOfNodes: " << this->Internals->Pieces.Breaks.size() << "\n";
  os << indent << "Tolerance: " << this->Tolerance << "\n";
  os << indent << "UseClosedForm: " << this->UseClosedForm << "\n";
  os << indent << "NumberOfUnconvergedPanels: " << this->Internals->Unconverged.load() << "\n";
}
