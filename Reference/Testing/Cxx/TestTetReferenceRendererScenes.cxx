/*=========================================================================

  Program:   TiledRayCast
  Module:    TestTetReferenceRendererScenes.cxx

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// The reference renderer's scenes: several volumes (AddVolume) and translucent layers
// (AddTranslucentLayer), against closed forms computed here from analytic chords (constant media
// in boxes: on each piece of a ray the summed attenuation tau = sum(tau_i) and colour
// sum(tau_i c_i) / tau, alpha 1 - exp(-tau L); fragments composited where they lie):
//  1. two overlapping boxes with different colours and attenuations, a box inside a box, parallel,
//     oblique perspective and the camera inside both (bound 1e-12);
//  2. a translucent layer in the middle of a box, in front of and behind it, two layers at one
//     depth, a layer behind the opaque depth, with the opaque depth (1e-12; 1e-11 with depth);
//  3. optical depth 50, and scalars and coordinates far from zero (1e-12; 1e-11 far away);
//  4. one volume through AddVolume, or with an empty layer, is the single-volume render (1e-13),
//     and non-overlapping volumes with non-linear transfer functions are the 'over' of their
//     single renders (1e-12); removing the scene gives the single render back bitwise;
//  5. bad input: an added volume without tetrahedra, without property, a null volume, layers of
//     the wrong size or with values out of range, a blend mode other than composite.
#include "TetReferenceTestUtilities.h"

#include "vtkCommand.h"
#include "vtkMinimalStandardRandomSequence.h"
#include "vtkTestErrorObserver.h"
#include "vtkTetReferenceVolume.h"
#include "vtkTransform.h"
#include "vtkVolumeMapper.h"

#include <string>

namespace
{
// A box of constant attenuation and colour.
struct Medium
{
  double Lo[3], Hi[3];
  double Tau;
  double C[3];
};

// The expected RGBA of the ray nearP + t d, media seen for t in [0, tEnd], fragments at the
// ray parameters of `fragments` (T, then premultiplied RGBA), from analytic chords. False when
// the ray passes within 1e-7 of a box face (a silhouette: the chord is not defined better).
bool Expected(const double nearP[3], const double d[3], double tEnd,
  const std::vector<Medium>& media, std::vector<std::array<double, 5>> fragments, double rgba[4])
{
  const double length = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
  std::vector<double> cuts;
  std::vector<std::array<double, 2>> spans(media.size(), { { 1.0, 0.0 } });
  for (size_t m = 0; m < media.size(); ++m)
  {
    double lo[3], hi[3], loOut[3], hiOut[3], t0, t1, u0, u1;
    for (int k = 0; k < 3; ++k)
    {
      lo[k] = media[m].Lo[k] + 1e-7;
      hi[k] = media[m].Hi[k] - 1e-7;
      loOut[k] = media[m].Lo[k] - 1e-7;
      hiOut[k] = media[m].Hi[k] + 1e-7;
    }
    if (trc::SlabInterval(nearP, d, lo, hi, 0.0, tEnd, t0, t1) !=
      trc::SlabInterval(nearP, d, loOut, hiOut, 0.0, tEnd, u0, u1))
    {
      return false;
    }
    if (trc::SlabInterval(nearP, d, media[m].Lo, media[m].Hi, 0.0, tEnd, t0, t1))
    {
      spans[m] = { { t0, t1 } };
      cuts.push_back(t0);
      cuts.push_back(t1);
    }
  }
  for (const auto& f : fragments)
  {
    cuts.push_back(f[0]);
  }
  std::sort(cuts.begin(), cuts.end());
  std::stable_sort(fragments.begin(), fragments.end(),
    [](const std::array<double, 5>& a, const std::array<double, 5>& b) { return a[0] < b[0]; });
  double color[3] = { 0, 0, 0 }, transmittance = 1.0;
  size_t next = 0;
  for (size_t k = 0; k < cuts.size(); ++k)
  {
    for (; next < fragments.size() && fragments[next][0] <= cuts[k]; ++next)
    {
      for (int q = 0; q < 3; ++q)
      {
        color[q] += transmittance * fragments[next][1 + q];
      }
      transmittance *= 1.0 - fragments[next][4];
    }
    if (k + 1 == cuts.size() || !(cuts[k + 1] > cuts[k]))
    {
      continue;
    }
    const double mid = 0.5 * (cuts[k] + cuts[k + 1]);
    double tau = 0.0, emission[3] = { 0, 0, 0 };
    for (size_t m = 0; m < media.size(); ++m)
    {
      if (spans[m][0] <= mid && mid <= spans[m][1])
      {
        tau += media[m].Tau;
        for (int q = 0; q < 3; ++q)
        {
          emission[q] += media[m].Tau * media[m].C[q];
        }
      }
    }
    if (tau > 0.0)
    {
      const double a = -std::expm1(-tau * (cuts[k + 1] - cuts[k]) * length);
      for (int q = 0; q < 3; ++q)
      {
        color[q] += transmittance * a * emission[q] / tau;
      }
      transmittance *= 1.0 - a;
    }
  }
  for (int q = 0; q < 3; ++q)
  {
    rgba[q] = color[q];
  }
  rgba[3] = 1.0 - transmittance;
  return true;
}

using trc::LambdaAtDepth;

// A translucent layer: the plane x = x0 where each pixel's ray meets it in front of the far
// plane (window depth as float), premultiplied colour rgba; depth 1 elsewhere.
struct Layer
{
  vtkNew<vtkDoubleArray> RGBA;
  vtkNew<vtkFloatArray> Depth;
};
void MakePlaneLayer(vtkCamera* camera, int w, int h, double x0, const double rgba[4], Layer& layer)
{
  layer.RGBA->SetNumberOfComponents(4);
  layer.RGBA->SetNumberOfTuples(w * h);
  layer.Depth->SetNumberOfTuples(w * h);
  vtkMatrix4x4* m = camera->GetCompositeProjectionTransformMatrix(double(w) / h, -1, 1);
  for (int j = 0; j < h; ++j)
  {
    for (int i = 0; i < w; ++i)
    {
      double nearP[3], farP[3];
      trc::PixelRay(camera, w, h, i, j, nearP, farP);
      const double t = (x0 - nearP[0]) / (farP[0] - nearP[0]);
      float z = 1.0f;
      if (t > 0.0 && t < 1.0)
      {
        const double p[4] = { nearP[0] + t * (farP[0] - nearP[0]),
          nearP[1] + t * (farP[1] - nearP[1]), nearP[2] + t * (farP[2] - nearP[2]), 1.0 };
        double c[4];
        m->MultiplyPoint(p, c);
        z = static_cast<float>(0.5 * (c[2] / c[3] + 1.0));
      }
      layer.Depth->SetValue(i + w * j, z);
      layer.RGBA->SetTuple(i + w * j, rgba);
    }
  }
}

// Checks `image` against Expected() on every pixel that is not on a silhouette; `layers` and
// `opaque` (null: none) as given to the renderer. Returns the number of pixels that see a medium
// (-1 on failure).
int CheckScene(vtkImageData* image, vtkCamera* camera, int w, int h,
  const std::vector<Medium>& media, const std::vector<Layer*>& layers, vtkFloatArray* opaque,
  double bound, const char* what)
{
  double worst = 0.0;
  int seen = 0;
  for (int j = 0; j < h; ++j)
  {
    for (int i = 0; i < w; ++i)
    {
      const int p = i + w * j;
      double nearP[3], farP[3], d[3];
      trc::PixelRay(camera, w, h, i, j, nearP, farP);
      for (int k = 0; k < 3; ++k)
      {
        d[k] = farP[k] - nearP[k];
      }
      const float zOpaque = opaque ? opaque->GetValue(p) : 1.0f;
      const double tEnd = zOpaque < 1.0f ? LambdaAtDepth(camera, w, h, i, j, zOpaque) : 1.0;
      std::vector<std::array<double, 5>> fragments;
      for (Layer* layer : layers)
      {
        const float z = layer->Depth->GetValue(p);
        if (z < zOpaque && z < 1.0f)
        {
          double c[4];
          layer->RGBA->GetTuple(p, c);
          fragments.push_back({ { LambdaAtDepth(camera, w, h, i, j, z), c[0], c[1], c[2], c[3] } });
        }
      }
      double expected[4], rgba[4];
      if (!Expected(nearP, d, tEnd, media, fragments, expected))
      {
        continue;
      }
      trc::Pixel(image, i, j, rgba);
      double diff = 0.0;
      for (int k = 0; k < 4; ++k)
      {
        diff = std::max(diff, std::fabs(rgba[k] - expected[k]));
      }
      worst = std::max(worst, diff);
      if (!(diff <= bound))
      {
        std::cerr << what << ": pixel (" << i << ", " << j << ") RGBA " << rgba[0] << " " << rgba[1]
                  << " " << rgba[2] << " " << rgba[3] << ", expected " << expected[0] << " "
                  << expected[1] << " " << expected[2] << " " << expected[3] << std::endl;
        return -1;
      }
      seen += trc::TetCount(image, i, j) > 0 ? 1 : 0;
    }
  }
  std::cout << what << ": " << seen << " pixels see a volume, max difference " << worst
            << std::endl;
  return seen;
}

using trc::MaxAbsDifference;

const double Up[3] = { 0, 0, 1 };
auto Flat = [](double, double, double) { return 0.5; };
} // namespace

namespace
{
//------------------------------------------------------------------------------
// 1. Overlapping boxes: A = [0,4]^3 (the renderer's own input), B = [2,6]x[1,3]x[1,3] and
//    C = [1,3]^3 inside A (a mesh at the origin moved by its matrix).
int TestOverlappingVolumes()
{
  const double origin[3] = { 0, 0, 0 }, originB[3] = { 2, 1, 1 };
  const std::vector<Medium> media = { { { 0, 0, 0 }, { 4, 4, 4 }, 0.35, { 0.9, 0.2, 0.1 } },
    { { 2, 1, 1 }, { 6, 3, 3 }, 0.8, { 0.1, 0.4, 1.0 } },
    { { 1, 1, 1 }, { 3, 3, 3 }, 1.5, { 0.2, 1.0, 0.3 } } };
  auto a = trc::MakeGrid(4, 4, 4, origin, 1.0, trc::Split::Five, Flat);
  auto b = trc::MakeGrid(4, 2, 2, originB, 1.0, trc::Split::Six, Flat);
  auto c = trc::MakeGrid(2, 2, 2, origin, 1.0, trc::Split::Five, Flat);
  vtkNew<vtkTransform> move;
  move->Translate(1.0, 1.0, 1.0);
  const double focal[3] = { 3, 2, 2 }, along[3] = { -1, 0, 0 }, oblique[3] = { -0.6, 0.5, 0.4 };
  auto inside = trc::MakeCamera(focal, oblique, Up, 1.0, false, 70.0, 0.05, 30.0);
  inside->SetPosition(3.1, 2.05, 1.95); // inside A and B
  inside->SetFocalPoint(6.0, 2.4, 2.2);
  inside->SetClippingRange(0.05, 30.0);
  struct Case
  {
    const char* Name;
    vtkSmartPointer<vtkCamera> Camera;
  };
  const Case cases[] = { { "A, B, C along x",
                           trc::MakeCamera(focal, along, Up, 20.0, true, 3.5, 1.0, 40.0) },
    { "A, B, C oblique perspective",
      trc::MakeCamera(focal, oblique, Up, 16.0, false, 35.0, 1.0, 40.0) },
    { "A, B, C, camera inside A and B", inside } };
  for (const Case& k : cases)
  {
    vtkNew<vtkTetReferenceRenderer> renderer;
    renderer->AddVolume(b, trc::ConstantProperty(media[1].Tau, media[1].C));
    renderer->AddVolume(c, trc::ConstantProperty(media[2].Tau, media[2].C), move->GetMatrix());
    vtkImageData* image = trc::RenderImage(
      renderer, a, trc::ConstantProperty(media[0].Tau, media[0].C), k.Camera, 31, 27);
    TRC_CHECK(image);
    TRC_CHECK(CheckScene(image, k.Camera, 31, 27, media, {}, nullptr, 1e-12, k.Name) > 100);
    TRC_CHECK(renderer->GetNumberOfTetrahedra() == 5 * 64 + 6 * 16 + 5 * 8);
  }
  return EXIT_SUCCESS;
}

//------------------------------------------------------------------------------
// 2. Translucent layers with a box [0,4]^3: planes x = 2 (inside), -1 (in front), 7 (behind),
//    two at x = 3 (same depth: composited in the order added), and an opaque depth.
int TestLayers()
{
  const double origin[3] = { 0, 0, 0 };
  const std::vector<Medium> media = { { { 0, 0, 0 }, { 4, 4, 4 }, 0.6, { 0.9, 0.5, 0.1 } } };
  auto a = trc::MakeGrid(4, 4, 4, origin, 1.0, trc::Split::Six, Flat);
  const double focal[3] = { 2, 2, 2 }, along[3] = { -1, 0, 0 }, oblique[3] = { -0.7, 0.4, 0.3 };
  const int w = 29, h = 25;
  for (bool parallel : { true, false })
  {
    auto camera = parallel ? trc::MakeCamera(focal, along, Up, 20.0, true, 3.0, 1.0, 40.0)
                           : trc::MakeCamera(focal, oblique, Up, 14.0, false, 35.0, 1.0, 40.0);
    const double inMiddle[4] = { 0.2, 0.1, 0.05, 0.4 }, inFront[4] = { 0.0, 0.3, 0.3, 0.5 },
                 behind[4] = { 0.4, 0.4, 0.0, 0.8 }, first[4] = { 0.3, 0.0, 0.0, 0.6 },
                 second[4] = { 0.0, 0.0, 0.7, 0.7 };
    Layer l1, l2, l3, l4, l5;
    MakePlaneLayer(camera, w, h, 2.0, inMiddle, l1);
    MakePlaneLayer(camera, w, h, -1.0, inFront, l2);
    MakePlaneLayer(camera, w, h, 7.0, behind, l3);
    MakePlaneLayer(camera, w, h, 3.0, first, l4);
    MakePlaneLayer(camera, w, h, 3.0, second, l5);
    const std::vector<Layer*> all = { &l1, &l2, &l3, &l4, &l5 };
    for (int opaqueCase = 0; opaqueCase < 2; ++opaqueCase)
    {
      vtkNew<vtkFloatArray> depth;
      depth->SetNumberOfTuples(w * h);
      vtkNew<vtkMinimalStandardRandomSequence> random;
      random->SetSeed(7);
      for (int p = 0; p < w * h; ++p)
      {
        random->Next();
        const double r = random->GetValue();
        depth->SetValue(p, r < 0.3 ? 1.0f : static_cast<float>(0.2 + 0.8 * r));
      }
      // One layer alone (the closed form of a layer inside a slab), then all of them.
      for (size_t n : { size_t(1), all.size() })
      {
        vtkNew<vtkTetReferenceRenderer> renderer;
        std::vector<Layer*> used(all.begin(), all.begin() + n);
        for (Layer* layer : used)
        {
          renderer->AddTranslucentLayer(layer->RGBA, layer->Depth);
        }
        renderer->SetOpaqueDepth(opaqueCase ? depth.Get() : nullptr);
        vtkImageData* image = trc::RenderImage(
          renderer, a, trc::ConstantProperty(media[0].Tau, media[0].C), camera, w, h);
        TRC_CHECK(image);
        const std::string what = std::string(parallel ? "parallel" : "perspective") + ", " +
          std::to_string(n) + " layer(s)" + (opaqueCase ? ", opaque depth" : "");
        TRC_CHECK(CheckScene(image, camera, w, h, media, used, opaqueCase ? depth.Get() : nullptr,
                    opaqueCase ? 1e-11 : 1e-12, what.c_str()) > 50);
      }
    }
  }
  return EXIT_SUCCESS;
}

//------------------------------------------------------------------------------
// 3. Optical depth 50 through A, and everything far from zero: the meshes moved by
//    (1e6, -2e6, 3e5) through their matrices, scalars 1e6.
int TestExtremes()
{
  const double origin[3] = { 0, 0, 0 }, originB[3] = { 2, 1, 1 }, far[3] = { 1e6, -2e6, 3e5 };
  auto big = [](double, double, double) { return 1e6; };
  auto a = trc::MakeGrid(4, 4, 4, origin, 1.0, trc::Split::Five, big);
  auto b = trc::MakeGrid(4, 2, 2, originB, 1.0, trc::Split::Six, big);
  auto property = [](double tau, const double c[3])
  {
    auto p = vtkSmartPointer<vtkVolumeProperty>::New();
    vtkNew<vtkColorTransferFunction> color;
    color->AddRGBPoint(1e6 - 1.0, c[0], c[1], c[2]);
    color->AddRGBPoint(1e6 + 1.0, c[0], c[1], c[2]);
    vtkNew<vtkPiecewiseFunction> opacity;
    opacity->AddPoint(1e6 - 1.0, tau);
    opacity->AddPoint(1e6 + 1.0, tau);
    p->SetColor(color);
    p->SetScalarOpacity(opacity);
    return p;
  };
  for (bool distant : { false, true })
  {
    const double* shift = distant ? far : origin;
    std::vector<Medium> media = { { { 0, 0, 0 }, { 4, 4, 4 }, 12.5, { 0.9, 0.2, 0.1 } },
      { { 2, 1, 1 }, { 6, 3, 3 }, 0.8, { 0.1, 0.4, 1.0 } } };
    for (Medium& m : media)
    {
      for (int k = 0; k < 3; ++k)
      {
        m.Lo[k] += shift[k];
        m.Hi[k] += shift[k];
      }
    }
    vtkNew<vtkTransform> move;
    move->Translate(shift[0], shift[1], shift[2]);
    const double focal[3] = { 3 + shift[0], 2 + shift[1], 2 + shift[2] }, dir[3] = { 1, 0.3, 0.2 };
    auto camera = trc::MakeCamera(focal, dir, Up, 15.0, false, 30.0, 1.0, 40.0);
    vtkNew<vtkTetReferenceRenderer> renderer;
    renderer->SetVolumeMatrix(move->GetMatrix());
    renderer->AddVolume(b, property(media[1].Tau, media[1].C), move->GetMatrix());
    vtkImageData* image =
      trc::RenderImage(renderer, a, property(media[0].Tau, media[0].C), camera, 27, 27);
    TRC_CHECK(image);
    // Far from the origin coordinates of 2e6 round to 5e-10 (measured: 2e-14 here, where the
    // expected values use the same camera): 1e-11 there.
    TRC_CHECK(CheckScene(image, camera, 27, 27, media, {}, nullptr, distant ? 1e-11 : 1e-12,
                distant ? "optical depth 50, far from zero" : "optical depth 50") > 100);
  }
  return EXIT_SUCCESS;
}
} // namespace

namespace
{
//------------------------------------------------------------------------------
// 4. A scene of one volume is the single-volume render; volumes one behind the other are the
//    'over' of their single renders. Linear fields and an HSV colour function with a node
//    midpoint and sharpness (the adaptive path).
int TestReductions()
{
  auto property = vtkSmartPointer<vtkVolumeProperty>::New();
  vtkNew<vtkColorTransferFunction> color;
  color->SetColorSpaceToHSV();
  color->AddRGBPoint(0.0, 1.0, 0.2, 0.1);
  color->AddRGBPoint(2.0, 0.1, 0.4, 1.0);
  vtkNew<vtkPiecewiseFunction> opacity;
  opacity->AddPoint(0.0, 0.3);
  opacity->AddPoint(1.0, 1.4, 0.3, 0.5);
  opacity->AddPoint(2.0, 0.6);
  property->SetColor(color);
  property->SetScalarOpacity(opacity);
  property->SetScalarOpacityUnitDistance(1.2);
  auto field = [](double x, double y, double z) { return 0.2 + 0.25 * x - 0.1 * y + 0.15 * z; };
  const double origin[3] = { 0, 0, 0 }, originB[3] = { 4, 0, 0 };
  auto a = trc::MakeGrid(2, 2, 2, origin, 1.0, trc::Split::Five, field);
  auto b = trc::MakeGrid(2, 2, 2, originB, 1.0, trc::Split::Six, field);
  const double focal[3] = { 3, 1, 1 }, dir[3] = { -1, 0.1, 0.05 };
  auto camera = trc::MakeCamera(focal, dir, Up, 20.0, true, 1.6, 1.0, 40.0);
  const int w = 24, h = 20;

  vtkNew<vtkTetReferenceRenderer> single;
  vtkImageData* reference = trc::RenderImage(single, a, property, camera, w, h);
  TRC_CHECK(reference);
  vtkNew<vtkImageData> singleImage;
  singleImage->DeepCopy(reference);
  // (a) Through AddVolume alone.
  vtkNew<vtkTetReferenceRenderer> added;
  added->AddVolume(a, property);
  vtkImageData* viaAdd = trc::RenderImage(added, nullptr, nullptr, camera, w, h);
  TRC_CHECK(viaAdd);
  // (b) The renderer's own input with a layer that has no fragment.
  Layer empty;
  const double none[4] = { 0.5, 0.5, 0.5, 0.5 };
  MakePlaneLayer(camera, w, h, 100.0, none, empty); // beyond the far plane: depth 1 everywhere
  vtkNew<vtkTetReferenceRenderer> layered;
  layered->AddTranslucentLayer(empty.RGBA, empty.Depth);
  vtkImageData* viaLayer = trc::RenderImage(layered, a, property, camera, w, h);
  TRC_CHECK(viaLayer);
  const double dAdd = MaxAbsDifference(viaAdd, singleImage);
  const double dLayer = MaxAbsDifference(viaLayer, singleImage);
  std::cout << "one volume as a scene vs single render: AddVolume " << dAdd << ", empty layer "
            << dLayer << std::endl;
  TRC_CHECK(dAdd <= 1e-13 && dLayer <= 1e-13);
  TRC_CHECK(added->GetNumberOfTetrahedra() == single->GetNumberOfTetrahedra());

  // (c) B behind A along every ray: the scene is A over B.
  vtkNew<vtkTetReferenceRenderer> alone;
  vtkImageData* imageB = trc::RenderImage(alone, b, property, camera, w, h);
  TRC_CHECK(imageB);
  vtkNew<vtkImageData> onlyB;
  onlyB->DeepCopy(imageB);
  vtkNew<vtkTetReferenceRenderer> both;
  both->AddVolume(b, property);
  vtkImageData* scene = trc::RenderImage(both, a, property, camera, w, h);
  TRC_CHECK(scene);
  double worst = 0.0, covered = 0.0;
  for (int j = 0; j < h; ++j)
  {
    for (int i = 0; i < w; ++i)
    {
      double pa[4], pb[4], ps[4];
      trc::Pixel(singleImage, i, j, pa);
      trc::Pixel(onlyB, i, j, pb);
      trc::Pixel(scene, i, j, ps);
      for (int k = 0; k < 4; ++k)
      {
        worst = std::max(worst, std::fabs(ps[k] - (pa[k] + (1.0 - pa[3]) * pb[k])));
      }
      covered += pa[3] > 0.0 && pb[3] > 0.0 ? 1.0 : 0.0;
    }
  }
  std::cout << "A in front of B: scene vs A over B " << worst << " (" << covered
            << " pixels see both)" << std::endl;
  TRC_CHECK(worst <= 1e-12 && covered > 50);

  // (d) Without its scene the renderer renders the single volume again, bitwise.
  both->RemoveAllVolumes();
  layered->RemoveAllTranslucentLayers();
  TRC_CHECK(both->GetNumberOfAddedVolumes() == 0 && layered->GetNumberOfTranslucentLayers() == 0);
  TRC_CHECK(both->Render() && MaxAbsDifference(both->GetOutput(), singleImage) == 0.0);
  TRC_CHECK(layered->Render() && MaxAbsDifference(layered->GetOutput(), singleImage) == 0.0);
  return EXIT_SUCCESS;
}

//------------------------------------------------------------------------------
// 5. Bad input: refused with an error naming what, never a crash; fine again afterwards.
int TestBadInput()
{
  const double origin[3] = { 0, 0, 0 }, c[3] = { 1, 1, 1 };
  auto cube = trc::MakeGrid(2, 2, 2, origin, 1.0, trc::Split::Five, Flat);
  auto property = trc::ConstantProperty(0.5, c);
  const double focal[3] = { 1, 1, 1 }, dir[3] = { 1, 0.2, 0.3 };
  auto camera = trc::MakeCamera(focal, dir, Up, 10.0, false, 30.0, 1.0, 30.0);
  vtkNew<vtkTest::ErrorObserver> errors;
  vtkNew<vtkTetReferenceRenderer> r;
  r->AddObserver(vtkCommand::ErrorEvent, errors);
  r->SetInputData(cube);
  r->SetVolumeProperty(property);
  r->SetCamera(camera);
  r->SetImageSize(8, 6);
  auto refused = [&](const char* what, const char* expected)
  {
    errors->Clear();
    const int ok = r->Render();
    const std::string message = errors->GetErrorMessage();
    const size_t begin = message.find("): ");
    const std::string text = begin == std::string::npos ? message : message.substr(begin + 3);
    std::cout << what << ": " << (ok ? "NOT refused" : "refused") << " ("
              << text.substr(0, text.find('\n')) << ")" << std::endl;
    return !ok && errors->GetError() && text.find(expected) != std::string::npos &&
      r->GetOutput()->GetNumberOfPoints() == 0;
  };
  // An added volume without tetrahedra, without a property, without input.
  vtkNew<vtkUnstructuredGrid> triangles;
  vtkNew<vtkPoints> points;
  points->InsertNextPoint(0, 0, 0);
  points->InsertNextPoint(1, 0, 0);
  points->InsertNextPoint(0, 1, 0);
  triangles->SetPoints(points);
  const vtkIdType tri[3] = { 0, 1, 2 };
  triangles->InsertNextCell(VTK_TRIANGLE, 3, tri);
  vtkNew<vtkDoubleArray> s3;
  s3->SetNumberOfTuples(3);
  s3->FillValue(0.5);
  triangles->GetPointData()->SetScalars(s3);
  vtkTetReferenceVolume* v = r->AddVolume(triangles, property);
  TRC_CHECK(refused("added volume without tetrahedra", "Volume 1: "));
  v->SetInputData(cube);
  v->SetVolumeProperty(nullptr);
  TRC_CHECK(refused("added volume without property", "Volume 1: no volume property"));
  v->SetVolumeProperty(property);
  v->SetInputData(nullptr);
  TRC_CHECK(refused("added volume without input", "Volume 1: no input"));
  v->SetInputData(cube);
  auto zeroUnit = vtkSmartPointer<vtkVolumeProperty>::New();
  zeroUnit->DeepCopy(property);
  zeroUnit->SetScalarOpacityUnitDistance(0.0);
  v->SetVolumeProperty(zeroUnit);
  TRC_CHECK(refused("added volume with unit distance 0", "cannot be integrated"));
  v->SetVolumeProperty(property);
  errors->Clear();
  r->AddVolume(static_cast<vtkTetReferenceVolume*>(nullptr));
  TRC_CHECK(errors->GetError() && r->GetNumberOfAddedVolumes() == 1);
  TRC_CHECK(r->GetAddedVolume(0) == v && r->GetAddedVolume(1) == nullptr);
  // Blend modes other than composite.
  r->SetBlendMode(vtkVolumeMapper::MAXIMUM_INTENSITY_BLEND);
  TRC_CHECK(refused("maximum intensity with two volumes", "composite"));
  r->SetBlendMode(vtkVolumeMapper::COMPOSITE_BLEND);
  // Layers of the wrong size or with values out of range.
  vtkNew<vtkDoubleArray> rgba;
  rgba->SetNumberOfComponents(4);
  rgba->SetNumberOfTuples(48);
  rgba->FillValue(0.25);
  vtkNew<vtkFloatArray> depth;
  depth->SetNumberOfTuples(47);
  depth->FillValue(0.5f);
  r->AddTranslucentLayer(rgba, depth);
  TRC_CHECK(refused("layer depth of the wrong size", "Translucent layer 0: the depth array"));
  depth->SetNumberOfTuples(48);
  depth->FillValue(0.5f);
  rgba->SetNumberOfComponents(3);
  rgba->SetNumberOfTuples(48);
  TRC_CHECK(refused("layer with 3 components", "Translucent layer 0: the RGBA array"));
  rgba->SetNumberOfComponents(4);
  rgba->SetNumberOfTuples(48);
  rgba->FillValue(0.25);
  rgba->SetComponent(5, 3, 1.5);
  TRC_CHECK(refused("layer alpha 1.5", "alpha in [0, 1]"));
  rgba->SetComponent(5, 3, std::nan(""));
  TRC_CHECK(refused("layer alpha NaN", "alpha in [0, 1]"));
  rgba->SetComponent(5, 3, 0.25);
  depth->SetValue(7, -0.1f);
  TRC_CHECK(refused("layer depth -0.1", "depths must lie in [0, 1]"));
  depth->SetValue(7, 0.5f);
  errors->Clear();
  r->AddTranslucentLayer(nullptr, depth);
  TRC_CHECK(errors->GetError() && r->GetNumberOfTranslucentLayers() == 1);
  // And it renders afterwards.
  errors->Clear();
  TRC_CHECK(r->Render() == 1 && !errors->GetError());
  return EXIT_SUCCESS;
}
} // namespace

int TestTetReferenceRendererScenes(int, char*[])
{
  TRC_CHECK(TestOverlappingVolumes() == EXIT_SUCCESS);
  TRC_CHECK(TestLayers() == EXIT_SUCCESS);
  TRC_CHECK(TestExtremes() == EXIT_SUCCESS);
  TRC_CHECK(TestReductions() == EXIT_SUCCESS);
  TRC_CHECK(TestBadInput() == EXIT_SUCCESS);
  std::cout << "TestTetReferenceRendererScenes passed" << std::endl;
  return EXIT_SUCCESS;
}
