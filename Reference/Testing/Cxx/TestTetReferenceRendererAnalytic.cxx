/*=========================================================================

  Program:   TiledRayCast
  Module:    TestTetReferenceRendererAnalytic.cxx

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// The reference renderer against closed forms:
//  - one tetrahedron of constant scalar: alpha = 1 - exp(-tau chord) per pixel, the chord found
//    here by clipping the ray with the four face planes (not the renderer's method);
//  - cubes of constant scalar made of 5 or 6 tetrahedra per voxel, seen along axes and
//    diagonals with pixel centres on grid points and edges: every pixel not on the cube's
//    silhouette equals 1 - exp(-tau chord) (no lost pixel, no pixel counted twice);
//  - a linear scalar field with linear and with difficult transfer functions (many nodes, a
//    narrow spike, midpoint and sharpness, HSV, clamping off) against brute-force integration
//    along the analytic ray on a sample of pixels.
#include "TetReferenceTestUtilities.h"

#include "vtkColorTransferFunction.h"
#include "vtkMinimalStandardRandomSequence.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPlane.h"
#include "vtkPlaneCollection.h"
#include "vtkTetReferenceRenderer.h"
#include "vtkVolumeProperty.h"

#include <functional>

namespace
{
// Parameter interval of the segment p + t d, t in [0, 1], inside the tetrahedron, by clipping
// with the half-spaces of its faces. Returns false when empty.
bool ClipTetrahedron(
  const double v[4][3], const double p[3], const double d[3], double& t0, double& t1)
{
  t0 = 0.0;
  t1 = 1.0;
  for (int f = 0; f < 4; ++f)
  {
    const double* a = v[(f + 1) % 4];
    const double* b = v[(f + 2) % 4];
    const double* c = v[(f + 3) % 4];
    const double* o = v[f];
    double n[3];
    const double u[3] = { b[0] - a[0], b[1] - a[1], b[2] - a[2] };
    const double w[3] = { c[0] - a[0], c[1] - a[1], c[2] - a[2] };
    n[0] = u[1] * w[2] - u[2] * w[1];
    n[1] = u[2] * w[0] - u[0] * w[2];
    n[2] = u[0] * w[1] - u[1] * w[0];
    // Orient n towards the opposite vertex: inside is n.(x - a) >= 0.
    if (n[0] * (o[0] - a[0]) + n[1] * (o[1] - a[1]) + n[2] * (o[2] - a[2]) < 0)
    {
      n[0] = -n[0];
      n[1] = -n[1];
      n[2] = -n[2];
    }
    const double g = n[0] * (p[0] - a[0]) + n[1] * (p[1] - a[1]) + n[2] * (p[2] - a[2]);
    const double s = n[0] * d[0] + n[1] * d[1] + n[2] * d[2];
    if (s == 0.0)
    {
      if (g < 0)
      {
        return false;
      }
      continue;
    }
    const double t = -g / s;
    if (s > 0)
    {
      t0 = std::max(t0, t);
    }
    else
    {
      t1 = std::min(t1, t);
    }
  }
  return t1 > t0;
}

// Cuts [t0, t1] to where p + t d lies on the side of the plane its normal points to.
bool ClipHalfSpace(vtkPlane* plane, const double p[3], const double d[3], double& t0, double& t1)
{
  double n[3], o[3];
  plane->GetNormal(n);
  plane->GetOrigin(o);
  const double g = n[0] * (p[0] - o[0]) + n[1] * (p[1] - o[1]) + n[2] * (p[2] - o[2]);
  const double s = n[0] * d[0] + n[1] * d[1] + n[2] * d[2];
  if (s > 0)
  {
    t0 = std::max(t0, -g / s);
  }
  else if (s < 0)
  {
    t1 = std::min(t1, -g / s);
  }
  else if (g < 0)
  {
    return false;
  }
  return t1 > t0;
}

double Length(const double d[3])
{
  return std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
}

using trc::RenderImage;

using Uniform = std::function<double(double, double)>;

// The constant medium of the first checks.
const double Color[3] = { 0.9, 0.6, 0.3 };
const double Tau = 0.8;

// One tetrahedron (either orientation), random cameras, parallel and perspective; from
// the seventh trial on, cut by two random clipping planes through its centroid.
int OneTetrahedron(Uniform& uniform)
{
  const double* color = Color;
  const double tau = Tau;
  auto constant = trc::ConstantProperty(Tau, Color);
  for (int trial = 0; trial < 12; ++trial)
  {
    double v[4][3];
    vtkNew<vtkPoints> points;
    points->SetDataTypeToDouble(); // the chord below uses these very coordinates
    for (int q = 0; q < 4; ++q)
    {
      for (int k = 0; k < 3; ++k)
      {
        v[q][k] = uniform(-1.0, 1.0);
      }
      points->InsertNextPoint(v[q]);
    }
    vtkNew<vtkUnstructuredGrid> tet;
    tet->SetPoints(points);
    const vtkIdType ids[4] = { 0, 1, 2, 3 };
    tet->InsertNextCell(VTK_TETRA, 4, ids);
    vtkNew<vtkDoubleArray> s;
    s->SetNumberOfTuples(4);
    s->FillValue(0.5);
    tet->GetPointData()->SetScalars(s);
    const double focal[3] = { 0, 0, 0 };
    const double dir[3] = { uniform(-1, 1), uniform(-1, 1), uniform(-1, 1) };
    const double up[3] = { uniform(-1, 1), uniform(-1, 1), uniform(-1, 1) };
    const bool parallel = trial % 2 == 0;
    auto camera = trc::MakeCamera(focal, dir, up, 5.0, parallel, parallel ? 1.5 : 35.0, 1.0, 10.0);
    vtkNew<vtkTetReferenceRenderer> renderer;
    vtkNew<vtkPlaneCollection> planes;
    for (int k = 0; trial >= 6 && k < 2; ++k)
    {
      vtkNew<vtkPlane> plane;
      // Through the tet's centroid, so that a wedge of it is left to see.
      double origin[3];
      for (int c = 0; c < 3; ++c)
      {
        origin[c] = 0.25 * (v[0][c] + v[1][c] + v[2][c] + v[3][c]);
      }
      plane->SetOrigin(origin);
      plane->SetNormal(uniform(-1, 1), uniform(-1, 1), uniform(-1, 1));
      planes->AddItem(plane);
    }
    renderer->SetClippingPlanes(planes);
    vtkImageData* image = RenderImage(renderer, tet, constant, camera, 48, 40);
    TRC_CHECK(image);
    int covered = 0;
    for (int j = 0; j < 40; ++j)
    {
      for (int i = 0; i < 48; ++i)
      {
        double nearP[3], farP[3], d[3];
        trc::PixelRay(camera, 48, 40, i, j, nearP, farP);
        for (int k = 0; k < 3; ++k)
        {
          d[k] = farP[k] - nearP[k];
        }
        double t0, t1;
        bool inside = ClipTetrahedron(v, nearP, d, t0, t1);
        for (int k = 0; k < planes->GetNumberOfItems(); ++k)
        {
          inside = inside && ClipHalfSpace(planes->GetItem(k), nearP, d, t0, t1);
        }
        const double chord = inside ? (t1 - t0) * Length(d) : 0.0;
        double rgba[4];
        trc::Pixel(image, i, j, rgba);
        const double alpha = -std::expm1(-tau * chord);
        TRC_CHECK_NEAR(rgba[3], alpha, 1e-12);
        TRC_CHECK_NEAR(rgba[0], color[0] * alpha, 1e-12);
        if (chord > 1e-6)
        {
          TRC_CHECK(trc::TetCount(image, i, j) == 1);
          ++covered;
        }
      }
    }
    TRC_CHECK(covered > (trial >= 6 ? 3 : 10));
  }
  return EXIT_SUCCESS;
}

// Cubes [0,4]^3 of 4^3 voxels, 5 or 6 tetrahedra each; pixel centres on grid points,
// edges and face diagonals.
int Cubes()
{
  const double* color = Color;
  const double tau = Tau;
  auto constant = trc::ConstantProperty(Tau, Color);
  const double origin[3] = { 0, 0, 0 };
  const double lo[3] = { 0, 0, 0 }, hi[3] = { 4, 4, 4 };
  auto flat = [](double, double, double) { return 0.5; };
  struct View
  {
    const char* Name;
    double Direction[3];
    double Up[3];
    bool Parallel;
  };
  const View views[] = {
    { "+z axis", { 0, 0, 1 }, { 0, 1, 0 }, true },
    { "-x axis", { -1, 0, 0 }, { 0, 0, 1 }, true },
    { "+y axis", { 0, 1, 0 }, { 1, 0, 0 }, true },
    { "(1,1,1) diagonal", { 1, 1, 1 }, { 0, 0, 1 }, true },
    { "(-1,1,-1) diagonal", { -1, 1, -1 }, { 0, 1, 0 }, true },
    { "(1,1,0) face diagonal", { 1, 1, 0 }, { 0, 0, 1 }, true },
    { "(0,1,-1) face diagonal", { 0, 1, -1 }, { 1, 0, 0 }, true },
    { "perspective (1,1,1)", { 1, 1, 1 }, { 0, 0, 1 }, false },
    { "perspective +z", { 0, 0, 1 }, { 0, 1, 0 }, false },
  };
  for (trc::Split split : { trc::Split::Five, trc::Split::Six })
  {
    auto cube = trc::MakeGrid(4, 4, 4, origin, 1.0, split, flat);
    for (const View& view : views)
    {
      // 33 x 33 pixels of 0.25: the central pixel's ray goes through the grid point (2, 2, 2),
      // and along axes every pixel centre lies on grid lines or between them at quarter steps.
      const double focal[3] = { 2, 2, 2 };
      auto camera = trc::MakeCamera(focal, view.Direction, view.Up, 20.0, view.Parallel,
        view.Parallel ? 4.125 : 23.0, 1.0, 60.0);
      vtkNew<vtkTetReferenceRenderer> renderer;
      vtkImageData* image = RenderImage(renderer, cube, constant, camera, 33, 33);
      TRC_CHECK(image);
      std::string what =
        std::string(split == trc::Split::Five ? "5 tets/voxel, " : "6 tets/voxel, ") + view.Name;
      const trc::Box box = { { lo[0], lo[1], lo[2] }, { hi[0], hi[1], hi[2] }, 1.0 };
      TRC_CHECK(trc::CheckBoxes(image, camera, 33, 33, { box }, tau, color, what.c_str()) > 0);
      // The central ray runs through the vertex (2, 2, 2) (along the diagonal: along a chain of
      // edges of the 6-tetrahedra split).
      double rgba[4];
      trc::Pixel(image, 16, 16, rgba);
      TRC_CHECK(rgba[3] > 0.5);
    }
  }
  return EXIT_SUCCESS;
}

// A linear field (exact in every tetrahedron) against brute force along the analytic ray.
int LinearField(Uniform& uniform)
{
  const double origin[3] = { 0, 0, 0 };
  auto field = [](double x, double y, double z) { return 0.5 + 0.2 * x + 0.1 * y - 0.15 * z; };
  auto cube = trc::MakeGrid(3, 3, 3, origin, 1.0, trc::Split::Five, field);
  const double clo[3] = { 0, 0, 0 }, chi[3] = { 3, 3, 3 };
  const double focal[3] = { 1.5, 1.5, 1.5 }, dir[3] = { 0.3, -0.5, 0.8 }, up[3] = { 0, 1, 0 };
  auto camera = trc::MakeCamera(focal, dir, up, 10.0, false, 28.0, 1.0, 30.0);

  std::vector<std::pair<std::string, vtkSmartPointer<vtkVolumeProperty>>> properties;
  std::vector<double> bounds;
  {
    auto p = vtkSmartPointer<vtkVolumeProperty>::New();
    vtkNew<vtkColorTransferFunction> c;
    c->AddRGBPoint(-0.5, 0.0, 0.2, 1.0);
    c->AddRGBPoint(1.5, 1.0, 0.4, 0.0);
    vtkNew<vtkPiecewiseFunction> o;
    o->AddPoint(-0.5, 0.1);
    o->AddPoint(1.5, 1.2);
    p->SetColor(c);
    p->SetScalarOpacity(o);
    p->SetScalarOpacityUnitDistance(1.3);
    properties.emplace_back("linear", p);
    bounds.push_back(1e-9);
  }
  {
    auto p = vtkSmartPointer<vtkVolumeProperty>::New();
    vtkNew<vtkColorTransferFunction> c;
    vtkNew<vtkPiecewiseFunction> o;
    for (int i = 0; i < 20; ++i)
    {
      const double x = uniform(-0.2, 1.2);
      const double r = uniform(0, 1), g = uniform(0, 1), b = uniform(0, 1), a = uniform(0, 3);
      c->AddRGBPoint(x, r, g, b);
      o->AddPoint(x + 0.01, a);
    }
    p->SetColor(c);
    p->SetScalarOpacity(o);
    properties.emplace_back("many nodes", p);
    bounds.push_back(1e-8);
    auto hsv = vtkSmartPointer<vtkVolumeProperty>::New();
    vtkNew<vtkColorTransferFunction> ch;
    ch->DeepCopy(c);
    ch->SetColorSpaceToHSV();
    hsv->SetColor(ch);
    hsv->SetScalarOpacity(o);
    properties.emplace_back("many nodes, HSV", hsv);
    bounds.push_back(1e-8);
  }
  {
    auto p = vtkSmartPointer<vtkVolumeProperty>::New();
    vtkNew<vtkColorTransferFunction> c;
    c->AddRGBPoint(0.0, 0.1, 0.2, 0.9, 0.3, 0.6);
    c->AddRGBPoint(0.6, 0.9, 0.7, 0.1, 0.7, 0.0);
    c->AddRGBPoint(1.2, 0.2, 0.9, 0.2);
    c->ClampingOff();
    vtkNew<vtkPiecewiseFunction> o;
    o->AddPoint(0.0, 0.3, 0.4, 0.5);
    o->AddPoint(0.5, 0.4);
    o->AddPoint(0.6, 8.0); // a narrow spike
    o->AddPoint(0.61, 0.4, 0.8, 0.0);
    o->AddPoint(1.2, 1.0);
    o->ClampingOff();
    p->SetColor(c);
    p->SetScalarOpacity(o);
    properties.emplace_back("spike, midpoint, sharpness, clamping off", p);
    bounds.push_back(1e-5); // jumps at the ends of the range (clamping off)
  }
  for (size_t q = 0; q < properties.size(); ++q)
  {
    vtkNew<vtkTetReferenceRenderer> renderer;
    vtkImageData* image = RenderImage(renderer, cube, properties[q].second, camera, 32, 32);
    TRC_CHECK(image);
    double worst = 0.0;
    int sampled = 0;
    for (int pick = 0; pick < 40 && sampled < 5; ++pick)
    {
      const int i = static_cast<int>(uniform(0, 32)), j = static_cast<int>(uniform(0, 32));
      double nearP[3], farP[3], d[3];
      trc::PixelRay(camera, 32, 32, i, j, nearP, farP);
      for (int k = 0; k < 3; ++k)
      {
        d[k] = farP[k] - nearP[k];
      }
      double t0, t1;
      if (!trc::SlabInterval(nearP, d, clo, chi, 0.0, 1.0, t0, t1) || (t1 - t0) * Length(d) < 0.5)
      {
        continue;
      }
      const double len = (t1 - t0) * Length(d);
      auto s = [&](double t)
      {
        const double u = t0 + (t1 - t0) * t / len;
        return field(nearP[0] + u * d[0], nearP[1] + u * d[1], nearP[2] + u * d[2]);
      };
      double brute[4], rgba[4];
      trc::BruteForce(properties[q].second, s, len, 200000, brute);
      trc::Pixel(image, i, j, rgba);
      for (int k = 0; k < 4; ++k)
      {
        worst = std::max(worst, std::fabs(rgba[k] - brute[k]));
      }
      ++sampled;
    }
    std::cout << "linear field, " << properties[q].first << ": " << sampled
              << " pixels against brute force, max difference " << worst << " (bound " << bounds[q]
              << ")" << std::endl;
    TRC_CHECK(sampled == 5);
    TRC_CHECK(worst <= bounds[q]);
  }

  // The same field split in 6 tetrahedra per voxel renders the same image.
  auto kuhn = trc::MakeGrid(3, 3, 3, origin, 1.0, trc::Split::Six, field);
  vtkNew<vtkTetReferenceRenderer> a, b;
  vtkImageData* ia = RenderImage(a, cube, properties[0].second, camera, 32, 32);
  vtkImageData* ib = RenderImage(b, kuhn, properties[0].second, camera, 32, 32);
  TRC_CHECK(ia && ib);
  double stats[3];
  TRC_CHECK(vtkTetReferenceRenderer::CompareImages(ia, ib, stats));
  std::cout << "5 vs 6 tetrahedra per voxel, linear field: max difference " << stats[2] / 255.0
            << std::endl;
  TRC_CHECK(stats[2] / 255.0 <= 1e-12);
  return EXIT_SUCCESS;
}

// Blend modes on one tet with a linear field and linear transfer functions, against closed
// forms along each pixel's chord: the scalar is linear along it, from s0 to s1; maximum
// and minimum intensity take the functions at max(s0, s1) and min(s0, s1); average and
// additive integrate opacity(s) * normalised s, a product of two linear functions of s
// (mean (f0 g0 + f1 g1) / 3 + (f0 g1 + f1 g0) / 6 over the chord).
int BlendModes()
{
  const double v[4][3] = { { -1, -1, -1 }, { 1.2, -0.8, -0.9 }, { -0.7, 1.1, -1 },
    { -0.9, -0.8, 1.3 } };
  const double g[3] = { 0.7, -0.4, 0.9 };
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkDoubleArray> scalars;
  double smin = 1e300, smax = -1e300;
  for (int q = 0; q < 4; ++q)
  {
    points->InsertNextPoint(v[q]);
    const double value = 2.0 + g[0] * v[q][0] + g[1] * v[q][1] + g[2] * v[q][2];
    scalars->InsertNextValue(value);
    smin = std::min(smin, value);
    smax = std::max(smax, value);
  }
  vtkNew<vtkUnstructuredGrid> tet;
  tet->SetPoints(points);
  const vtkIdType ids[4] = { 0, 1, 2, 3 };
  tet->InsertNextCell(VTK_TETRA, 4, ids);
  tet->GetPointData()->SetScalars(scalars);
  vtkNew<vtkColorTransferFunction> colour;
  colour->AddRGBPoint(smin, 0.1, 0.8, 0.3);
  colour->AddRGBPoint(smax, 0.9, 0.2, 0.6);
  vtkNew<vtkPiecewiseFunction> opacity;
  opacity->AddPoint(smin, 0.1);
  opacity->AddPoint(smax, 0.7);
  vtkNew<vtkVolumeProperty> property;
  property->SetColor(colour);
  property->SetScalarOpacity(opacity);
  property->SetScalarOpacityUnitDistance(0.8);
  auto field = [&](const double p[3]) { return 2.0 + g[0] * p[0] + g[1] * p[1] + g[2] * p[2]; };
  auto normalised = [&](double s) { return (s - smin) / (smax - smin); };
  const double focal[3] = { 0, 0, 0 }, dir[3] = { 0.3, -0.5, -1.0 }, up[3] = { 0, 1, 0 };
  auto camera = trc::MakeCamera(focal, dir, up, 6.0, false, 40.0, 1.0, 20.0);
  for (int mode = 1; mode <= 4; ++mode)
  {
    vtkNew<vtkTetReferenceRenderer> renderer;
    renderer->SetBlendMode(mode);
    vtkImageData* image = RenderImage(renderer, tet, property, camera, 40, 40);
    TRC_CHECK(image);
    int covered = 0;
    for (int j = 0; j < 40; ++j)
    {
      for (int i = 0; i < 40; ++i)
      {
        double nearP[3], farP[3], d[3];
        trc::PixelRay(camera, 40, 40, i, j, nearP, farP);
        for (int k = 0; k < 3; ++k)
        {
          d[k] = farP[k] - nearP[k];
        }
        double t0, t1, rgba[4];
        trc::Pixel(image, i, j, rgba);
        if (!ClipTetrahedron(v, nearP, d, t0, t1) || (t1 - t0) * Length(d) < 1e-6)
        {
          continue;
        }
        ++covered;
        double p0[3], p1[3];
        for (int k = 0; k < 3; ++k)
        {
          p0[k] = nearP[k] + t0 * d[k];
          p1[k] = nearP[k] + t1 * d[k];
        }
        const double s0 = field(p0), s1 = field(p1);
        double expected[4];
        if (mode <= 2)
        {
          const double s = mode == 1 ? std::max(s0, s1) : std::min(s0, s1);
          double c[3];
          colour->GetColor(s, c);
          const double a = opacity->GetValue(s);
          expected[0] = c[0] * a;
          expected[1] = c[1] * a;
          expected[2] = c[2] * a;
          expected[3] = a;
        }
        else
        {
          const double f0 = opacity->GetValue(s0), f1 = opacity->GetValue(s1);
          const double n0 = normalised(s0), n1 = normalised(s1);
          const double mean = (f0 * n0 + f1 * n1) / 3.0 + (f0 * n1 + f1 * n0) / 6.0;
          const double chord = (t1 - t0) * Length(d);
          const double gray = std::min(
            1.0, mode == 3 ? mean : mean * chord / property->GetScalarOpacityUnitDistance());
          expected[0] = expected[1] = expected[2] = gray;
          expected[3] = 1.0;
        }
        for (int k = 0; k < 4; ++k)
        {
          TRC_CHECK_NEAR(rgba[k], expected[k], 1e-9);
        }
      }
    }
    TRC_CHECK(covered > 50);
  }
  return EXIT_SUCCESS;
}

} // namespace

int TestTetReferenceRendererAnalytic(int, char*[])
{
  vtkNew<vtkMinimalStandardRandomSequence> random;
  random->SetSeed(4242);
  Uniform uniform = [&random](double a, double b)
  {
    random->Next();
    return random->GetRangeValue(a, b);
  };
  // One sequence of random numbers through the checks, in this order.
  TRC_CHECK(OneTetrahedron(uniform) == EXIT_SUCCESS);
  TRC_CHECK(Cubes() == EXIT_SUCCESS);
  TRC_CHECK(LinearField(uniform) == EXIT_SUCCESS);
  std::cout << "TestTetReferenceRendererAnalytic passed" << std::endl;
  TRC_CHECK(BlendModes() == EXIT_SUCCESS);
  return EXIT_SUCCESS;
}
