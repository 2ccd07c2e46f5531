/*=========================================================================

  Program:   TiledRayCast
  Module:    TestTetRayIntegratorMixture.cxx

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// vtkTetRayIntegrator::IntegrateMixture, several media overlapping along a segment (attenuation
// sum(tau_i), emission sum(tau_i c_i)), against what must hold independently of its code:
//  - constant media: alpha = 1 - exp(-(tau1 + tau2) L), colour (tau1 c1 + tau2 c2)/(tau1 + tau2)
//    times alpha, also at optical depths 50 and 2000 (bound 1e-14);
//  - two copies of a medium are that medium with twice the opacity (closed form 1e-14, HSV
//    adaptive 1e-10), a transparent medium changes nothing (1e-14), a NaN medium is left out
//    (bitwise), one medium is IntegrateWithDepth bitwise;
//  - a segment equals its two halves composited (1e-13);
//  - different media on different scalar ramps (linear; HSV with midpoint and sharpness; a
//    narrow spike) against a 2-million-step brute-force march of the summed medium (1e-10,
//    measured 9e-13, the brute force's own error; the spike 1e-8, measured 4e-10).
#include "TetIntegrationTestUtilities.h"

#include "vtkTetRayIntegrator.h"

namespace
{
// A property with a two-node linear colour and opacity (or HSV colour, and a middle node with
// midpoint and sharpness, when `curved`).
vtkSmartPointer<vtkVolumeProperty> RampProperty(const double c0[3], const double c1[3], double o0,
  double o1, double unit, bool curved, double scale = 1.0)
{
  auto property = vtkSmartPointer<vtkVolumeProperty>::New();
  vtkNew<vtkColorTransferFunction> color;
  color->AddRGBPoint(0.0, c0[0], c0[1], c0[2]);
  color->AddRGBPoint(1.0, c1[0], c1[1], c1[2]);
  vtkNew<vtkPiecewiseFunction> opacity;
  opacity->AddPoint(0.0, scale * o0);
  if (curved)
  {
    color->SetColorSpaceToHSV();
    opacity->AddPoint(0.45, scale * 0.5 * (o0 + o1), 0.3, 0.4);
  }
  opacity->AddPoint(1.0, scale * o1);
  property->SetColor(color);
  property->SetScalarOpacity(opacity);
  property->SetScalarOpacityUnitDistance(unit);
  return property;
}

// Brute force of the summed medium: n midpoint steps, each a constant step integrated exactly.
void BruteForceMixture(const std::vector<vtkVolumeProperty*>& properties, const double* sf,
  const double* sb, double len, int n, double rgba[4])
{
  const double h = len / n;
  double transmittance = 1.0, c[3] = { 0.0, 0.0, 0.0 };
  for (int k = 0; k < n; ++k)
  {
    const double u = (k + 0.5) / n;
    double tau = 0.0, emission[3] = { 0.0, 0.0, 0.0 };
    for (size_t m = 0; m < properties.size(); ++m)
    {
      vtkVolumeProperty* p = properties[m];
      const double s = sf[m] + (sb[m] - sf[m]) * u;
      const double taum =
        std::max(0.0, p->GetScalarOpacity(0)->GetValue(s)) / p->GetScalarOpacityUnitDistance(0);
      double rgb[3];
      p->GetRGBTransferFunction(0)->GetColor(s, rgb);
      tau += taum;
      for (int q = 0; q < 3; ++q)
      {
        emission[q] += taum * rgb[q];
      }
    }
    const double a = -std::expm1(-tau * h);
    for (int q = 0; q < 3; ++q)
    {
      c[q] += tau > 0.0 ? transmittance * a * emission[q] / tau : 0.0;
    }
    transmittance *= 1.0 - a;
  }
  rgba[0] = c[0];
  rgba[1] = c[1];
  rgba[2] = c[2];
  rgba[3] = 1.0 - transmittance;
}

double MaxDiff(const double a[4], const double b[4])
{
  double worst = 0.0;
  for (int k = 0; k < 4; ++k)
  {
    worst = std::max(worst, std::fabs(a[k] - b[k]));
  }
  return worst;
}

vtkSmartPointer<vtkTetRayIntegrator> Integrator(vtkVolumeProperty* property)
{
  auto integrator = vtkSmartPointer<vtkTetRayIntegrator>::New();
  return integrator->Initialize(property) ? integrator : nullptr;
}

int TestConstantMedia()
{
  const double c1[3] = { 0.9, 0.2, 0.1 }, c2[3] = { 0.1, 0.3, 1.0 };
  for (double scale : { 1e-9, 1.0, 25.0, 1000.0 }) // optical depths 2.7e-9 to 2700
  {
    const double tau1 = 0.7 * scale, tau2 = 0.2 * scale, len = 3.0;
    auto p1 = trc::ConstantProperty(tau1, c1);
    auto p2 = trc::ConstantProperty(tau2, c2);
    auto i1 = Integrator(p1);
    auto i2 = Integrator(p2);
    TRC_CHECK(i1 && i2);
    vtkTetRayIntegrator* media[2] = { i1, i2 };
    const double sf[2] = { 0.5, 0.2 }, sb[2] = { 0.5, 0.8 };
    double rgba[4], depth;
    vtkTetRayIntegrator::IntegrateMixture(2, media, sf, sb, len, rgba, &depth);
    const double alpha = -std::expm1(-(tau1 + tau2) * len);
    double expected[4] = { 0, 0, 0, alpha };
    for (int q = 0; q < 3; ++q)
    {
      expected[q] = (tau1 * c1[q] + tau2 * c2[q]) / (tau1 + tau2) * alpha;
    }
    std::cout << "constant media, optical depth " << (tau1 + tau2) * len << ": difference "
              << MaxDiff(rgba, expected) << std::endl;
    TRC_CHECK(MaxDiff(rgba, expected) <= 1e-14 * std::max(1.0, alpha));
    TRC_CHECK(alpha >= 1.0 || std::fabs(depth - (tau1 + tau2) * len) <= 1e-15 * depth);
  }
  return EXIT_SUCCESS;
}

// Two copies of a medium = the medium with twice the opacity; a transparent medium changes
// nothing; a NaN medium is left out; a mixture of one is the medium's own integral.
int TestIdentities()
{
  const double c0[3] = { 1.0, 0.3, 0.1 }, c1[3] = { 0.2, 0.5, 1.0 };
  for (bool curved : { false, true })
  {
    auto single = RampProperty(c0, c1, 0.4, 2.2, 1.3, curved);
    auto doubled = RampProperty(c0, c1, 0.4, 2.2, 1.3, curved, 2.0);
    auto clear = RampProperty(c0, c1, 0.0, 0.0, 1.0, false);
    auto is = Integrator(single);
    auto id = Integrator(doubled);
    auto ic = Integrator(clear);
    TRC_CHECK(is && id && ic);
    const double bound = curved ? 1e-10 : 1e-14;
    double worstCopy = 0.0, worstClear = 0.0;
    for (int k = 0; k < 50; ++k)
    {
      const double sf = -0.2 + 0.029 * k, sb = 1.1 - 0.023 * k, len = 0.05 + 0.07 * k;
      vtkTetRayIntegrator* two[2] = { is, is };
      const double sfs[2] = { sf, sf }, sbs[2] = { sb, sb };
      double mix[4], ref[4];
      vtkTetRayIntegrator::IntegrateMixture(2, two, sfs, sbs, len, mix, nullptr);
      id->Integrate(sf, sb, len, ref);
      worstCopy = std::max(worstCopy, MaxDiff(mix, ref));
      vtkTetRayIntegrator* withClear[2] = { ic, is };
      const double sfc[2] = { 0.3, sf }, sbc[2] = { 0.9, sb };
      vtkTetRayIntegrator::IntegrateMixture(2, withClear, sfc, sbc, len, mix, nullptr);
      is->Integrate(sf, sb, len, ref);
      worstClear = std::max(worstClear, MaxDiff(mix, ref));
      // NaN: left out, and one medium is exactly IntegrateWithDepth.
      const double sfn[2] = { std::nan(""), sf };
      double depthMix, depthRef;
      vtkTetRayIntegrator::IntegrateMixture(2, withClear, sfn, sbc, len, mix, &depthMix);
      is->IntegrateWithDepth(sf, sb, len, ref, &depthRef);
      TRC_CHECK(MaxDiff(mix, ref) == 0.0 && depthMix == depthRef);
    }
    std::cout << (curved ? "HSV, midpoint and sharpness" : "linear")
              << ": two copies vs doubled opacity " << worstCopy << ", with a transparent medium "
              << worstClear << std::endl;
    TRC_CHECK(worstCopy <= bound && worstClear <= bound);
  }
  return EXIT_SUCCESS;
}

// Halves composited, and brute force, for different media on different ramps.
int TestAgainstBruteForce()
{
  const double a0[3] = { 1.0, 0.3, 0.1 }, a1[3] = { 0.2, 0.5, 1.0 };
  const double b0[3] = { 0.1, 0.9, 0.2 }, b1[3] = { 0.8, 0.1, 0.7 };
  auto spike = vtkSmartPointer<vtkVolumeProperty>::New();
  {
    vtkNew<vtkColorTransferFunction> color;
    color->AddRGBPoint(0.0, 1.0, 1.0, 0.0);
    color->AddRGBPoint(1.0, 0.0, 1.0, 1.0);
    vtkNew<vtkPiecewiseFunction> opacity;
    opacity->AddPoint(0.0, 0.0);
    opacity->AddPoint(0.499, 0.0);
    opacity->AddPoint(0.5, 50.0);
    opacity->AddPoint(0.501, 0.0);
    opacity->AddPoint(1.0, 0.0);
    spike->SetColor(color);
    spike->SetScalarOpacity(opacity);
  }
  struct Case
  {
    const char* Name;
    vtkSmartPointer<vtkVolumeProperty> A, B;
    double Bound;
  };
  const Case cases[] = {
    { "linear + linear", RampProperty(a0, a1, 0.3, 1.9, 1.0, false),
      RampProperty(b0, b1, 1.2, 0.1, 0.7, false), 1e-10 },
    { "HSV curved + linear", RampProperty(a0, a1, 0.3, 1.9, 1.0, true),
      RampProperty(b0, b1, 1.2, 0.1, 0.7, false), 1e-10 },
    { "linear + spike", RampProperty(a0, a1, 0.3, 1.9, 1.0, false), spike, 1e-8 },
  };
  for (const Case& c : cases)
  {
    auto ia = Integrator(c.A);
    auto ib = Integrator(c.B);
    TRC_CHECK(ia && ib);
    vtkTetRayIntegrator* media[2] = { ia, ib };
    const double sf[2] = { -0.1, 1.05 }, sb[2] = { 1.2, 0.02 }, len = 1.7;
    double whole[4], depth;
    vtkTetRayIntegrator::IntegrateMixture(2, media, sf, sb, len, whole, &depth);
    // The two halves, composited.
    const double mid[2] = { 0.5 * (sf[0] + sb[0]), 0.5 * (sf[1] + sb[1]) };
    double front[4], back[4], frontDepth, backDepth;
    vtkTetRayIntegrator::IntegrateMixture(2, media, sf, mid, 0.5 * len, front, &frontDepth);
    vtkTetRayIntegrator::IntegrateMixture(2, media, mid, sb, 0.5 * len, back, &backDepth);
    double halves[4];
    for (int q = 0; q < 3; ++q)
    {
      halves[q] = front[q] + std::exp(-frontDepth) * back[q];
    }
    halves[3] = -std::expm1(-(frontDepth + backDepth));
    double brute[4];
    BruteForceMixture({ c.A, c.B }, sf, sb, len, 2000000, brute);
    std::cout << c.Name << ": alpha " << whole[3] << ", halves " << MaxDiff(whole, halves)
              << ", brute force " << MaxDiff(whole, brute) << std::endl;
    TRC_CHECK(MaxDiff(whole, halves) <= 1e-13);
    TRC_CHECK(MaxDiff(whole, brute) <= c.Bound);
    TRC_CHECK(whole[3] > 0.5 && ia->GetNumberOfUnconvergedPanels() == 0 &&
      ib->GetNumberOfUnconvergedPanels() == 0);
  }
  return EXIT_SUCCESS;
}
} // namespace

int TestTetRayIntegratorMixture(int, char*[])
{
  TRC_CHECK(TestConstantMedia() == EXIT_SUCCESS);
  TRC_CHECK(TestIdentities() == EXIT_SUCCESS);
  TRC_CHECK(TestAgainstBruteForce() == EXIT_SUCCESS);
  std::cout << "TestTetRayIntegratorMixture passed" << std::endl;
  return EXIT_SUCCESS;
}
