/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkTetRayIntegratorIntervals.cxx

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "vtkTetRayIntegratorIntervals.h"

#include "vtkColorTransferFunction.h"
#include "vtkMath.h"
#include "vtkPiecewiseFunction.h"
#include "vtkTetRayIntegratorFunctions.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <functional>
#include <limits>

namespace
{
// Midpoints are clamped the way VTK evaluates them.
double NodeMidpoint(double x0, double x1, double midpoint)
{
  midpoint = std::min(std::max(midpoint, 1e-5), 1.0 - 1e-5);
  return x0 + midpoint * (x1 - x0);
}
}

//------------------------------------------------------------------------------
void vtkTetRayIntegratorIntervals::FindBreaks(const vtkTetRayIntegratorFunctions& f)
{
  this->Breaks.clear();
  this->AddPiecewiseNodes(f.Opacity, this->OpacityLayout);
  if (f.Gray)
  {
    this->AddPiecewiseNodes(f.Gray, this->ColorLayout);
  }
  else
  {
    this->AddColorNodes(f.Color);
  }
  this->Breaks.erase(std::remove_if(this->Breaks.begin(), this->Breaks.end(),
                       [](double x) { return !std::isfinite(x); }),
    this->Breaks.end());
  std::sort(this->Breaks.begin(), this->Breaks.end());
  this->Breaks.erase(std::unique(this->Breaks.begin(), this->Breaks.end()), this->Breaks.end());

  const int space = f.Color ? f.Color->GetColorSpace() : VTK_CTF_RGB;
  if (space == VTK_CTF_HSV || space == VTK_CTF_LAB || space == VTK_CTF_DIVERGING)
  {
    this->AddColorKinks(f.Color);
  }
}

//------------------------------------------------------------------------------
void vtkTetRayIntegratorIntervals::AddPiecewiseNodes(vtkPiecewiseFunction* f, NodeLayout& layout)
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
      this->Breaks.push_back(NodeMidpoint(layout.X[i], layout.X[i + 1], mids[i]));
    }
  }
  this->Breaks.insert(this->Breaks.end(), layout.X.begin(), layout.X.end());
}

//------------------------------------------------------------------------------
void vtkTetRayIntegratorIntervals::AddColorNodes(vtkColorTransferFunction* f)
{
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
    this->ColorLayout.X.push_back(v[0]);
    mids[i] = v[4];
    sharp[i] = v[5];
  }
  // Diverging interpolation may pass through white half way between two nodes: a kink.
  const bool diverging = f->GetColorSpace() == VTK_CTF_DIVERGING;
  for (int i = 0; i + 1 < n; ++i)
  {
    if (diverging && this->ColorLayout.X[i + 1] > this->ColorLayout.X[i])
    {
      this->Breaks.push_back(NodeMidpoint(this->ColorLayout.X[i], this->ColorLayout.X[i + 1], 0.5));
    }
    const bool linear = linearSpace && mids[i] == 0.5 && sharp[i] < 0.01;
    this->ColorLayout.LinearPiece.push_back(linear ? 1 : 0);
    if (!(mids[i] == 0.5 && sharp[i] < 0.01) && this->ColorLayout.X[i + 1] > this->ColorLayout.X[i])
    {
      this->Breaks.push_back(
        NodeMidpoint(this->ColorLayout.X[i], this->ColorLayout.X[i + 1], mids[i]));
    }
  }
  this->Breaks.insert(this->Breaks.end(), this->ColorLayout.X.begin(), this->ColorLayout.X.end());
}

//------------------------------------------------------------------------------
// HSV interpolation bends the RGB components wherever the hue crosses a multiple of 1/6.
// Adaptive quadrature can misjudge its error at such kinks, so they become breakpoints too:
// found where the sextant of the hue of VTK's colours changes, between dense samples, then
// by bisection to the last bit. A missed or misplaced bend only costs adaptive work.
// Lab and diverging interpolation go through XYZ, and VTK clips the resulting RGB (a channel
// below 0 becomes 0, a colour above 1 is scaled down): kinks wherever that clipping starts
// or stops, found the same way from the clipping state of VTK's colours.
void vtkTetRayIntegratorIntervals::AddColorKinks(vtkColorTransferFunction* f)
{
  const int space = f->GetColorSpace();
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
      this->Breaks.push_back(r);
      return;
    }
    const int sm = sextant(m);
    bisect(l, sl, m, sm);
    bisect(m, sm, r, sr);
  };
  const std::vector<double> pieces(this->Breaks);
  for (size_t i = 0; i + 1 < pieces.size(); ++i)
  {
    const double lo = pieces[i], hi = pieces[i + 1];
    if (lo < this->ColorLayout.X.front() || hi > this->ColorLayout.X.back())
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
  std::sort(this->Breaks.begin(), this->Breaks.end());
  this->Breaks.erase(std::unique(this->Breaks.begin(), this->Breaks.end()), this->Breaks.end());
}

//------------------------------------------------------------------------------
void vtkTetRayIntegratorIntervals::BuildIntervals(vtkTetRayIntegratorFunctions& f)
{
  const size_t nb = this->Breaks.size();
  this->Intervals.resize(nb + 1);
  for (size_t i = 0; i <= nb; ++i)
  {
    Interval& iv = this->Intervals[i];
    const bool hasLow = i > 0, hasHigh = i < nb;
    iv.Bounded = hasLow && hasHigh;
    iv.X0 = hasLow ? this->Breaks[i - 1] : -std::numeric_limits<double>::infinity();
    iv.X1 = hasHigh ? this->Breaks[i] : std::numeric_limits<double>::infinity();
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
    iv.Linear = this->ColorLayout.LinearAt(probe) && this->OpacityLayout.LinearAt(probe);
    if (!iv.Linear)
    {
      continue;
    }
    this->SetLinearValues(f, iv, probe);
  }
}

//------------------------------------------------------------------------------
void vtkTetRayIntegratorIntervals::SetLinearValues(
  vtkTetRayIntegratorFunctions& f, Interval& iv, double probe)
{
  const bool hasHigh = iv.X1 < std::numeric_limits<double>::infinity();
  // Values come from VTK itself, sampled strictly inside the interval (at a node VTK may
  // return either side's value) and extrapolated linearly to its ends; a third sample checks
  // that the function really is linear there.
  if (iv.Bounded)
  {
    const double xa = iv.X0 + 0.25 * (iv.X1 - iv.X0);
    const double xb = iv.X0 + 0.75 * (iv.X1 - iv.X0);
    double ta, tb, tm, ca[3], cb[3], cm[3];
    f.Evaluate(xa, ta, ca);
    f.Evaluate(xb, tb, cb);
    f.Evaluate(probe, tm, cm);
    auto linearOk = [](double va, double vb, double vm)
    { return std::fabs(vm - 0.5 * (va + vb)) <= 1e-12 * (std::fabs(va) + std::fabs(vb)) + 1e-300; };
    bool ok = linearOk(ta, tb, tm);
    for (int k = 0; k < 3; ++k)
    {
      ok = ok && linearOk(ca[k], cb[k], cm[k]);
    }
    if (!ok)
    {
      iv.Linear = false;
      return;
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
    f.Evaluate(probe, iv.Tau0, iv.C0);
    f.Evaluate(far, tf, cf);
    if (tf != iv.Tau0 || cf[0] != iv.C0[0] || cf[1] != iv.C0[1] || cf[2] != iv.C0[2])
    {
      iv.Linear = false;
      return;
    }
    iv.Tau1 = iv.Tau0;
    std::copy(iv.C0, iv.C0 + 3, iv.C1);
  }
}

//------------------------------------------------------------------------------
size_t vtkTetRayIntegratorIntervals::IntervalIndex(double s) const
{
  return std::upper_bound(this->Breaks.begin(), this->Breaks.end(), s) - this->Breaks.begin();
}

//------------------------------------------------------------------------------
void vtkTetRayIntegratorIntervals::LinearValues(
  const Interval& iv, double s, double& tau, double c[3]) const
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
