/*=========================================================================

  Program:   TiledRayCast
  Module:    TestTetRayIntegrator.cxx

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// The exact segment integrator against closed forms (constant and linear attenuation, linear
// colour, via erf), against itself (composition of split segments, closed form against the
// adaptive path), and against brute-force integration of VTK's own transfer functions for the
// cases that have no closed form (many nodes, narrow spikes, midpoint and sharpness, HSV and
// Lab colour spaces, clamping off, gray). Bounds are stated next to each check.
#include "TetIntegrationTestUtilities.h"

#include "vtkCommand.h"
#include "vtkDoubleArray.h"
#include "vtkMath.h"
#include "vtkMinimalStandardRandomSequence.h"
#include "vtkSMPTools.h"
#include "vtkTestErrorObserver.h"
#include "vtkTetRayIntegrator.h"

#include <functional>
#include <vector>

namespace
{
using Uniform = std::function<double(double, double)>;

vtkSmartPointer<vtkVolumeProperty> LinearProperty(
  double o0, double o1, const double c0[3], const double c1[3], double unit)
{
  auto property = vtkSmartPointer<vtkVolumeProperty>::New();
  vtkNew<vtkColorTransferFunction> color;
  color->AddRGBPoint(0.0, c0[0], c0[1], c0[2]);
  color->AddRGBPoint(1.0, c1[0], c1[1], c1[2]);
  vtkNew<vtkPiecewiseFunction> opacity;
  opacity->AddPoint(0.0, o0);
  opacity->AddPoint(1.0, o1);
  property->SetColor(color);
  property->SetScalarOpacity(opacity);
  property->SetScalarOpacityUnitDistance(unit);
  return property;
}

// Largest difference over the four channels.
double MaxDiff(const double a[4], const double b[4])
{
  double m = 0.0;
  for (int k = 0; k < 4; ++k)
  {
    m = std::max(m, std::fabs(a[k] - b[k]));
  }
  return m;
}

// Compares the integrator with the brute force on a segment (scalar from sf to sb over len).
int CompareWithBruteForce(const char* what, vtkVolumeProperty* property, double sf, double sb,
  double len, int steps, double bound)
{
  vtkNew<vtkTetRayIntegrator> integrator;
  if (!integrator->Initialize(property))
  {
    std::cerr << what << ": Initialize failed" << std::endl;
    return EXIT_FAILURE;
  }
  double exact[4], brute[4];
  integrator->Integrate(sf, sb, len, exact);
  trc::BruteForce(
    property, [=](double t) { return sf + (sb - sf) * t / len; }, len, steps, brute);
  const double diff = MaxDiff(exact, brute);
  std::cout << what << ": rgba " << exact[0] << " " << exact[1] << " " << exact[2] << " "
            << exact[3] << ", max difference to brute force " << diff << " (bound " << bound << ")"
            << std::endl;
  TRC_CHECK(diff <= bound);
  TRC_CHECK(exact[3] > 1e-3); // the case must not be trivially transparent
  TRC_CHECK(integrator->GetNumberOfUnconvergedPanels() == 0);
  return EXIT_SUCCESS;
}

// Constant colour and attenuation: alpha = 1 - exp(-tau L), C = c alpha (relative 1e-14).
int ConstantAttenuation(Uniform& uniform)
{
  const double c[3] = { 0.9, 0.5, 0.2 };
  for (int trial = 0; trial < 50; ++trial)
  {
    const double tau = uniform(0.01, 20.0), len = uniform(1e-4, 3.0);
    auto property = trc::ConstantProperty(tau, c);
    vtkNew<vtkTetRayIntegrator> integrator;
    TRC_CHECK(integrator->Initialize(property));
    const double s0 = uniform(0.0, 1.0), s1 = trial % 2 ? s0 : uniform(0.0, 1.0);
    double rgba[4];
    integrator->Integrate(s0, s1, len, rgba);
    const double alpha = -std::expm1(-tau * len);
    TRC_CHECK_NEAR(rgba[3], alpha, 1e-14 * alpha);
    for (int k = 0; k < 3; ++k)
    {
      TRC_CHECK_NEAR(rgba[k], c[k] * alpha, 1e-14 * alpha);
    }
  }
  return EXIT_SUCCESS;
}

// Linear colour, constant attenuation:
// C = c0 alpha + (c1 - c0) (1 - exp(-tau L)(1 + tau L)) / (tau L)   (absolute 1e-13).
int LinearColour(Uniform& uniform)
{
  for (int trial = 0; trial < 50; ++trial)
  {
    const double c0[3] = { uniform(0, 1), uniform(0, 1), uniform(0, 1) };
    const double c1[3] = { uniform(0, 1), uniform(0, 1), uniform(0, 1) };
    const double o = uniform(0.05, 5.0), len = uniform(0.1, 2.0);
    auto property = LinearProperty(o, o, c0, c1, 1.0);
    vtkNew<vtkTetRayIntegrator> integrator;
    TRC_CHECK(integrator->Initialize(property));
    double rgba[4];
    integrator->Integrate(0.0, 1.0, len, rgba);
    const double tl = o * len, alpha = -std::expm1(-tl);
    const double ramp = (1.0 - std::exp(-tl) * (1.0 + tl)) / tl;
    TRC_CHECK_NEAR(rgba[3], alpha, 1e-14);
    for (int k = 0; k < 3; ++k)
    {
      TRC_CHECK_NEAR(rgba[k], c0[k] * alpha + (c1[k] - c0[k]) * ramp, 1e-13);
    }
  }
  return EXIT_SUCCESS;
}

// Linear attenuation and linear colour, with Int_0^L T from erfc (absolute 1e-12):
// T(t) = exp(-(tau0 t + k t^2 / 2)), k = (tau1 - tau0) / L > 0,
// Int T = sqrt(pi / 2k) [exp(a^2) erfc(a) - exp(a^2) erfc(b)], a = tau0 / sqrt(2k),
// b = (tau0 + k L) / sqrt(2k); C = c0 - c1 T(L) + (c1 - c0) / L Int T.
int LinearAttenuation(Uniform& uniform)
{
  for (int trial = 0; trial < 50; ++trial)
  {
    const double c0[3] = { uniform(0, 1), uniform(0, 1), uniform(0, 1) };
    const double c1[3] = { uniform(0, 1), uniform(0, 1), uniform(0, 1) };
    const double tau0 = uniform(0.05, 2.0), tau1 = tau0 + uniform(0.1, 3.0);
    const double len = uniform(0.2, 2.0), unit = uniform(0.5, 2.0);
    auto property = LinearProperty(tau0 * unit, tau1 * unit, c0, c1, unit);
    vtkNew<vtkTetRayIntegrator> integrator;
    TRC_CHECK(integrator->Initialize(property));
    double rgba[4];
    integrator->Integrate(0.0, 1.0, len, rgba);
    const double k = (tau1 - tau0) / len, r = std::sqrt(2.0 * k);
    const double a = tau0 / r, b = (tau0 + k * len) / r;
    const double intT =
      std::sqrt(vtkMath::Pi() / (2.0 * k)) * std::exp(a * a) * (std::erfc(a) - std::erfc(b));
    const double tl = std::exp(-0.5 * len * (tau0 + tau1));
    TRC_CHECK_NEAR(rgba[3], 1.0 - tl, 1e-14);
    for (int q = 0; q < 3; ++q)
    {
      TRC_CHECK_NEAR(rgba[q], c0[q] - c1[q] * tl + (c1[q] - c0[q]) / len * intT, 1e-12);
    }
    // Decreasing attenuation (the same formula with the roles of the ends swapped is not
    // needed: reversing the segment must keep alpha).
    double reversed[4];
    integrator->Integrate(1.0, 0.0, len, reversed);
    TRC_CHECK_NEAR(reversed[3], rgba[3], 1e-15);
  }
  return EXIT_SUCCESS;
}

// A transfer function with many nodes (piecewise linear RGB), drawn from `uniform`.
vtkSmartPointer<vtkVolumeProperty> ManyNodes(Uniform& uniform)
{
  auto manyNodes = vtkSmartPointer<vtkVolumeProperty>::New();
  vtkNew<vtkColorTransferFunction> color;
  vtkNew<vtkPiecewiseFunction> opacity;
  for (int i = 0; i < 30; ++i)
  {
    color->AddRGBPoint(uniform(0.0, 1.0), uniform(0, 1), uniform(0, 1), uniform(0, 1));
  }
  for (int i = 0; i < 25; ++i)
  {
    opacity->AddPoint(uniform(0.0, 1.0), uniform(0.0, 4.0));
  }
  manyNodes->SetColor(color);
  manyNodes->SetScalarOpacity(opacity);
  manyNodes->SetScalarOpacityUnitDistance(0.7);
  return manyNodes;
}

// The same functions in HSV space (non-linear between nodes).
vtkSmartPointer<vtkVolumeProperty> InHSV(vtkVolumeProperty* manyNodes)
{
  auto manyNodesHSV = vtkSmartPointer<vtkVolumeProperty>::New();
  vtkNew<vtkColorTransferFunction> color;
  color->DeepCopy(manyNodes->GetRGBTransferFunction(0));
  color->SetColorSpaceToHSV();
  manyNodesHSV->SetColor(color);
  manyNodesHSV->SetScalarOpacity(manyNodes->GetScalarOpacity(0));
  manyNodesHSV->SetScalarOpacityUnitDistance(0.7);
  return manyNodesHSV;
}

// Composition: a segment equals its two halves composited front to back
// (1e-13 on linear pieces; 1e-11 with HSV, where both sides are adaptive).
int Composition(Uniform& uniform, vtkVolumeProperty* manyNodes, vtkVolumeProperty* manyNodesHSV)
{
  vtkVolumeProperty* properties[2] = { manyNodes, manyNodesHSV };
  const double bounds[2] = { 1e-13, 1e-11 };
  for (int p = 0; p < 2; ++p)
  {
    vtkNew<vtkTetRayIntegrator> integrator;
    TRC_CHECK(integrator->Initialize(properties[p]));
    for (int trial = 0; trial < 100; ++trial)
    {
      const double s0 = uniform(-0.2, 1.2), s2 = uniform(-0.2, 1.2), len = uniform(0.01, 3.0);
      const double f = uniform(0.05, 0.95);
      const double s1 = s0 + (s2 - s0) * f;
      double whole[4], front[4], back[4];
      integrator->Integrate(s0, s2, len, whole);
      integrator->Integrate(s0, s1, len * f, front);
      integrator->Integrate(s1, s2, len * (1.0 - f), back);
      double composed[4];
      for (int k = 0; k < 3; ++k)
      {
        composed[k] = front[k] + (1.0 - front[3]) * back[k];
      }
      composed[3] = 1.0 - (1.0 - front[3]) * (1.0 - back[3]);
      TRC_CHECK(MaxDiff(whole, composed) <= bounds[p]);
    }
    TRC_CHECK(integrator->GetNumberOfUnconvergedPanels() == 0);
  }
  return EXIT_SUCCESS;
}

// Closed form against the adaptive path on linear pieces (1e-10).
int ClosedFormAgainstAdaptive(Uniform& uniform, vtkVolumeProperty* manyNodes)
{
  vtkNew<vtkTetRayIntegrator> closed, adaptive;
  TRC_CHECK(closed->Initialize(manyNodes));
  adaptive->UseClosedFormOff();
  TRC_CHECK(adaptive->Initialize(manyNodes));
  double worst = 0.0;
  for (int trial = 0; trial < 200; ++trial)
  {
    const double s0 = uniform(-0.2, 1.2), s1 = uniform(-0.2, 1.2), len = uniform(0.001, 5.0);
    double a[4], b[4];
    closed->Integrate(s0, s1, len, a);
    adaptive->Integrate(s0, s1, len, b);
    worst = std::max(worst, MaxDiff(a, b));
  }
  std::cout << "closed form vs adaptive, 200 segments: max difference " << worst << std::endl;
  TRC_CHECK(worst <= 1e-10);
  TRC_CHECK(adaptive->GetNumberOfUnconvergedPanels() == 0);
  return EXIT_SUCCESS;
}

// Brute force (midpoint marching with VTK's own evaluation). Its error is O(step^2) at
// kinks and O(step) at jumps, which sets the bounds: 1e-8 for continuous functions,
// 1e-7 with a spike of slope 5e4, 1e-5 where the functions jump.
int BruteForce(vtkVolumeProperty* manyNodes, vtkVolumeProperty* manyNodesHSV)
{
  TRC_CHECK(CompareWithBruteForce("many nodes, clamped", manyNodes, -0.1, 1.1, 1.5, 400000, 1e-8) ==
    EXIT_SUCCESS);
  TRC_CHECK(CompareWithBruteForce("many nodes, HSV", manyNodesHSV, 1.1, -0.1, 1.5, 400000, 1e-8) ==
    EXIT_SUCCESS);
  {
    // A narrow opacity spike (width 0.002, attenuation 50 per unit) over a colour ramp.
    auto property = vtkSmartPointer<vtkVolumeProperty>::New();
    vtkNew<vtkColorTransferFunction> color;
    color->AddRGBPoint(0.0, 0.0, 0.0, 1.0);
    color->AddRGBPoint(1.0, 1.0, 0.0, 0.0);
    vtkNew<vtkPiecewiseFunction> opacity;
    opacity->AddPoint(0.0, 0.05);
    opacity->AddPoint(0.499, 0.05);
    opacity->AddPoint(0.5, 50.0);
    opacity->AddPoint(0.501, 0.05);
    opacity->AddPoint(1.0, 0.05);
    property->SetColor(color);
    property->SetScalarOpacity(opacity);
    TRC_CHECK(CompareWithBruteForce("narrow spike", property, 0.0, 1.0, 2.0, 2000000, 1e-7) ==
      EXIT_SUCCESS);
  }
  {
    // Midpoints and sharpness: Hermite curves (sharpness 0.5), kinked lines (midpoint 0.2,
    // sharpness 0), in colour and opacity.
    auto property = vtkSmartPointer<vtkVolumeProperty>::New();
    vtkNew<vtkColorTransferFunction> color;
    color->AddRGBPoint(0.0, 0.1, 0.2, 0.9, 0.3, 0.5);
    color->AddRGBPoint(0.4, 0.9, 0.8, 0.1, 0.2, 0.0);
    color->AddRGBPoint(1.0, 0.5, 0.1, 0.3);
    vtkNew<vtkPiecewiseFunction> opacity;
    opacity->AddPoint(0.0, 0.2, 0.7, 0.4);
    opacity->AddPoint(0.5, 3.0, 0.2, 0.0);
    opacity->AddPoint(0.8, 0.5, 0.5, 0.9);
    opacity->AddPoint(1.0, 2.0);
    property->SetColor(color);
    property->SetScalarOpacity(opacity);
    TRC_CHECK(CompareWithBruteForce(
                "midpoint and sharpness", property, 0.0, 1.0, 1.3, 400000, 1e-8) == EXIT_SUCCESS);
    // Sharpness 1: piecewise constant with a jump at the midpoint.
    vtkNew<vtkPiecewiseFunction> steps;
    steps->AddPoint(0.0, 0.3, 0.35, 1.0);
    steps->AddPoint(0.6, 2.5, 0.5, 1.0);
    steps->AddPoint(1.0, 0.7);
    property->SetScalarOpacity(steps);
    TRC_CHECK(CompareWithBruteForce("sharpness 1 (steps)", property, 1.0, 0.0, 1.3, 400000, 1e-5) ==
      EXIT_SUCCESS);
  }
  {
    // Clamping off: zero outside the node range (a jump at each end of the range).
    auto property = vtkSmartPointer<vtkVolumeProperty>::New();
    vtkNew<vtkColorTransferFunction> color;
    color->AddRGBPoint(0.2, 1.0, 0.5, 0.0);
    color->AddRGBPoint(0.8, 0.0, 0.5, 1.0);
    color->ClampingOff();
    vtkNew<vtkPiecewiseFunction> opacity;
    opacity->AddPoint(0.2, 1.5);
    opacity->AddPoint(0.8, 0.5);
    opacity->ClampingOff();
    property->SetColor(color);
    property->SetScalarOpacity(opacity);
    TRC_CHECK(CompareWithBruteForce("clamping off", property, -0.3, 1.4, 1.7, 400000, 1e-5) ==
      EXIT_SUCCESS);
    // A constant scalar exactly at a node: VTK's own value there.
    vtkNew<vtkTetRayIntegrator> integrator;
    TRC_CHECK(integrator->Initialize(property));
    for (double s : { 0.2, 0.8, 0.5, -1.0, 2.0 })
    {
      double rgba[4];
      integrator->Integrate(s, s, 0.9, rgba);
      const double alpha = -std::expm1(-opacity->GetValue(s) * 0.9);
      TRC_CHECK_NEAR(rgba[3], alpha, 1e-15);
    }
  }
  {
    // Lab interpolation, and a gray function with a non-default midpoint.
    auto property = vtkSmartPointer<vtkVolumeProperty>::New();
    vtkNew<vtkColorTransferFunction> color;
    color->AddRGBPoint(0.0, 0.05, 0.1, 0.9);
    color->AddRGBPoint(0.5, 0.9, 0.9, 0.1);
    color->AddRGBPoint(1.0, 0.8, 0.0, 0.05);
    color->SetColorSpaceToLab();
    vtkNew<vtkPiecewiseFunction> opacity;
    opacity->AddPoint(0.0, 0.5);
    opacity->AddPoint(1.0, 2.0);
    property->SetColor(color);
    property->SetScalarOpacity(opacity);
    TRC_CHECK(CompareWithBruteForce("Lab", property, 0.0, 1.0, 1.0, 400000, 1e-8) == EXIT_SUCCESS);
    vtkNew<vtkPiecewiseFunction> gray;
    gray->AddPoint(0.0, 0.1, 0.8, 0.0);
    gray->AddPoint(1.0, 0.9);
    property->SetColor(gray);
    TRC_CHECK(property->GetColorChannels(0) == 1);
    TRC_CHECK(CompareWithBruteForce("gray, midpoint 0.8", property, 1.0, 0.0, 1.0, 400000, 1e-8) ==
      EXIT_SUCCESS);
  }
  return EXIT_SUCCESS;
}

// Node list and linearity of intervals.
int NodeList()
{
  auto property = vtkSmartPointer<vtkVolumeProperty>::New();
  vtkNew<vtkColorTransferFunction> color;
  color->AddRGBPoint(0.0, 0, 0, 0);
  color->AddRGBPoint(0.5, 1, 1, 1, 0.25, 0.0); // kink at 0.5 + 0.25 * 0.5 = 0.625
  color->AddRGBPoint(1.0, 0, 0, 0);
  vtkNew<vtkPiecewiseFunction> opacity;
  opacity->AddPoint(0.25, 1.0);
  opacity->AddPoint(2.0, 1.0);
  property->SetColor(color);
  property->SetScalarOpacity(opacity);
  vtkNew<vtkTetRayIntegrator> integrator;
  TRC_CHECK(integrator->Initialize(property));
  const double expected[] = { 0.0, 0.25, 0.5, 0.625, 1.0, 2.0 };
  TRC_CHECK(integrator->GetNumberOfNodes() == 6);
  for (int i = 0; i < 6; ++i)
  {
    TRC_CHECK(integrator->GetNode(i) == expected[i]);
  }
  vtkNew<vtkDoubleArray> nodes;
  integrator->GetNodes(nodes);
  TRC_CHECK(nodes->GetNumberOfTuples() == 6 && nodes->GetValue(3) == 0.625);
  // Intervals: (-inf,0) (0,.25) (.25,.5) (.5,.625) (.625,1) (1,2) (2,inf); the two around the
  // non-default midpoint are not linear.
  const bool linear[] = { true, true, true, false, false, true, true };
  for (int i = 0; i < 7; ++i)
  {
    TRC_CHECK(integrator->IsIntervalLinear(i) == linear[i]);
  }
  return EXIT_SUCCESS;
}

// HSV: every hue bend is a node, so between two consecutive nodes the hue of VTK's
//  colours stays within one sixth of the circle (a bend right next to a node was once
//  missed: 7e-9 of error there).
int HueBends(vtkVolumeProperty* manyNodesHSV)
{
  vtkNew<vtkTetRayIntegrator> integrator;
  TRC_CHECK(integrator->Initialize(manyNodesHSV));
  vtkColorTransferFunction* c = manyNodesHSV->GetRGBTransferFunction(0);
  const int n = integrator->GetNumberOfNodes();
  TRC_CHECK(n > 55); // the 55 nodes plus bends
  for (int i = 0; i + 1 < n; ++i)
  {
    const double lo = integrator->GetNode(i), hi = integrator->GetNode(i + 1);
    int first = -1;
    for (int k = 1; k < 200; ++k)
    {
      double rgb[3], hsv[3];
      c->GetColor(lo + (hi - lo) * k / 200.0, rgb);
      vtkMath::RGBToHSV(rgb, hsv);
      const int sextant = std::min(5, static_cast<int>(6.0 * hsv[0]));
      first = first < 0 ? sextant : first;
      TRC_CHECK(sextant == first);
    }
  }
  return EXIT_SUCCESS;
}

// Non-finite or empty segments contribute nothing; bad properties are refused.
int Refusals(vtkVolumeProperty* manyNodes)
{
  vtkNew<vtkTetRayIntegrator> integrator;
  double rgba[4] = { 1, 1, 1, 1 };
  integrator->Integrate(0.0, 1.0, 1.0, rgba); // not initialised
  TRC_CHECK(rgba[0] == 0.0 && rgba[3] == 0.0);
  TRC_CHECK(integrator->Initialize(manyNodes));
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  const double cases[][3] = { { nan, 0.5, 1.0 }, { 0.5, nan, 1.0 }, { inf, 0.5, 1.0 },
    { 0.2, 0.5, 0.0 }, { 0.2, 0.5, -1.0 }, { 0.2, 0.5, nan }, { 0.2, 0.5, inf } };
  for (const auto& c : cases)
  {
    rgba[0] = rgba[1] = rgba[2] = rgba[3] = 1.0;
    integrator->Integrate(c[0], c[1], c[2], rgba);
    TRC_CHECK(rgba[0] == 0.0 && rgba[1] == 0.0 && rgba[2] == 0.0 && rgba[3] == 0.0);
  }
  vtkNew<vtkTest::ErrorObserver> errors;
  integrator->AddObserver(vtkCommand::ErrorEvent, errors);
  TRC_CHECK(integrator->Initialize(nullptr) == 0);
  TRC_CHECK(errors->GetError());
  TRC_CHECK(!integrator->IsInitialized());
  errors->Clear();
  auto zeroUnit = vtkSmartPointer<vtkVolumeProperty>::New();
  zeroUnit->SetScalarOpacityUnitDistance(0.0);
  TRC_CHECK(integrator->Initialize(zeroUnit) == 0);
  TRC_CHECK(errors->GetError());
  return EXIT_SUCCESS;
}

// Thread safety: the same results, bitwise, from vtkSMPTools threads (HSV: the per-thread
// copies of the transfer functions are in use).
int ThreadSafety(Uniform& uniform, vtkVolumeProperty* manyNodesHSV)
{
  vtkNew<vtkTetRayIntegrator> integrator;
  TRC_CHECK(integrator->Initialize(manyNodesHSV));
  const int n = 2000;
  std::vector<double> segments(3 * n), serial(4 * n), parallel(4 * n);
  for (int i = 0; i < n; ++i)
  {
    segments[3 * i] = uniform(-0.2, 1.2);
    segments[3 * i + 1] = uniform(-0.2, 1.2);
    segments[3 * i + 2] = uniform(0.01, 2.0);
    integrator->Integrate(
      segments[3 * i], segments[3 * i + 1], segments[3 * i + 2], &serial[4 * i]);
  }
  vtkSMPTools::For(0, n, 16,
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType i = begin; i < end; ++i)
      {
        integrator->Integrate(
          segments[3 * i], segments[3 * i + 1], segments[3 * i + 2], &parallel[4 * i]);
      }
    });
  TRC_CHECK(serial == parallel);
  return EXIT_SUCCESS;
}

} // namespace

int TestTetRayIntegrator(int, char*[])
{
  vtkNew<vtkMinimalStandardRandomSequence> random;
  random->SetSeed(12345);
  Uniform uniform = [&random](double a, double b)
  {
    random->Next();
    return random->GetRangeValue(a, b);
  };
  // One sequence of random numbers through the checks, in this order.
  TRC_CHECK(ConstantAttenuation(uniform) == EXIT_SUCCESS);
  TRC_CHECK(LinearColour(uniform) == EXIT_SUCCESS);
  TRC_CHECK(LinearAttenuation(uniform) == EXIT_SUCCESS);
  vtkSmartPointer<vtkVolumeProperty> manyNodes = ManyNodes(uniform);
  vtkSmartPointer<vtkVolumeProperty> manyNodesHSV = InHSV(manyNodes);
  TRC_CHECK(Composition(uniform, manyNodes, manyNodesHSV) == EXIT_SUCCESS);
  TRC_CHECK(ClosedFormAgainstAdaptive(uniform, manyNodes) == EXIT_SUCCESS);
  TRC_CHECK(BruteForce(manyNodes, manyNodesHSV) == EXIT_SUCCESS);
  TRC_CHECK(NodeList() == EXIT_SUCCESS);
  TRC_CHECK(HueBends(manyNodesHSV) == EXIT_SUCCESS);
  TRC_CHECK(Refusals(manyNodes) == EXIT_SUCCESS);
  TRC_CHECK(ThreadSafety(uniform, manyNodesHSV) == EXIT_SUCCESS);

  std::cout << "TestTetRayIntegrator passed" << std::endl;
  return EXIT_SUCCESS;
}
