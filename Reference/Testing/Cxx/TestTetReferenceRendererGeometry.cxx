/*=========================================================================

  Program:   TiledRayCast
  Module:    TestTetReferenceRendererGeometry.cxx

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// The reference renderer where ray casters usually fail, against analytic chord lengths:
//  - non-convex meshes: a hollow cube (a cavity), two disjoint boxes (leave and re-enter);
//  - the camera inside the mesh, and inside the cavity;
//  - an opaque depth buffer ending each ray;
//  - a transformed vtkVolume: a rigid motion with uniform scale equals the equivalent camera
//    move (with the unit distance scaled), and a non-uniform scale changes lengths;
//  - a mesh far from the origin renders like the same mesh at the origin.
#include "TetReferenceTestUtilities.h"

#include "vtkMinimalStandardRandomSequence.h"
#include "vtkTetReferenceRenderer.h"
#include "vtkTransform.h"
#include "vtkVolume.h"

namespace
{
using trc::MaxAbsDifference;
using trc::RenderImage;

double Sum(vtkImageData* image, int component)
{
  vtkDataArray* a = image->GetPointData()->GetArray("RGBA");
  double sum = 0.0;
  for (vtkIdType i = 0; i < a->GetNumberOfTuples(); ++i)
  {
    sum += a->GetComponent(i, component);
  }
  return sum;
}

// Most of the scenes: a constant medium of this colour and attenuation over flat scalars.
const double Color[3] = { 0.2, 0.7, 0.9 };
const double Tau = 0.45;
double Flat(double, double, double)
{
  return 0.5;
}
const double Origin[3] = { 0, 0, 0 };
const double Up[3] = { 0, 0, 1 };

// The others: a linear field under a red-to-blue ramp, opacity 0.2 to 1.5 over [0, 1.2].
double Linear(double x, double y, double z)
{
  return 0.3 + 0.2 * x - 0.1 * y + 0.15 * z;
}
vtkSmartPointer<vtkVolumeProperty> RampProperty()
{
  auto property = vtkSmartPointer<vtkVolumeProperty>::New();
  vtkNew<vtkColorTransferFunction> c;
  c->AddRGBPoint(0.0, 1.0, 0.2, 0.1);
  c->AddRGBPoint(1.2, 0.1, 0.4, 1.0);
  vtkNew<vtkPiecewiseFunction> o;
  o->AddPoint(0.0, 0.2);
  o->AddPoint(1.2, 1.5);
  property->SetColor(c);
  property->SetScalarOpacity(o);
  return property;
}

// A hollow cube [0,6]^3 with the cavity [2,4]^3, and a camera inside it.
int TestHollowCube()
{
  auto constant = trc::ConstantProperty(Tau, Color);
  auto cavity = [](int i, int j, int k)
  { return i >= 2 && i < 4 && j >= 2 && j < 4 && k >= 2 && k < 4; };
  const std::vector<trc::Box> boxes = { { { 0, 0, 0 }, { 6, 6, 6 }, 1.0 },
    { { 2, 2, 2 }, { 4, 4, 4 }, -1.0 } };
  for (trc::Split split : { trc::Split::Five, trc::Split::Six })
  {
    auto hollow = trc::MakeGrid(6, 6, 6, Origin, 1.0, split, Flat, cavity);
    const double focal[3] = { 3, 3, 3 };
    const double axis[3] = { 0, 1, 0 }, oblique[3] = { 0.6, -0.7, 0.4 };
    struct Case
    {
      const char* Name;
      vtkSmartPointer<vtkCamera> Camera;
    };
    const double inside[3] = { 3.2, 2.9, 3.1 }; // camera position within the cavity
    auto fromCavity = trc::MakeCamera(focal, oblique, Up, 1e-9, false, 70.0, 0.05, 30.0);
    fromCavity->SetPosition(inside[0], inside[1], inside[2]);
    fromCavity->SetFocalPoint(inside[0] + 1.0, inside[1] + 0.3, inside[2] - 0.2);
    fromCavity->SetClippingRange(0.05, 30.0);
    auto inWall = trc::MakeCamera(focal, oblique, Up, 1e-9, false, 80.0, 0.1, 30.0);
    inWall->SetPosition(1.0, 3.1, 2.9); // inside the wall, looking through the cavity
    inWall->SetFocalPoint(5.0, 3.0, 3.2);
    inWall->SetClippingRange(0.1, 30.0);
    const Case cases[] = {
      { "hollow cube, axis", trc::MakeCamera(focal, axis, Up, 20.0, true, 4.125, 1.0, 40.0) },
      { "hollow cube, oblique perspective",
        trc::MakeCamera(focal, oblique, Up, 16.0, false, 35.0, 1.0, 40.0) },
      { "camera inside the cavity", fromCavity },
      { "camera inside the wall", inWall },
    };
    for (const Case& c : cases)
    {
      vtkNew<vtkTetReferenceRenderer> renderer;
      vtkImageData* image = RenderImage(renderer, hollow, constant, c.Camera, 33, 33);
      TRC_CHECK(image);
      const std::string what =
        std::string(c.Name) + (split == trc::Split::Five ? " (5 tets)" : " (6 tets)");
      TRC_CHECK(trc::CheckBoxes(image, c.Camera, 33, 33, boxes, Tau, Color, what.c_str()) > 0);
    }
  }
  return EXIT_SUCCESS;
}

// Two disjoint boxes: rays leave the mesh and enter it again.
int TestTwoBoxes()
{
  auto constant = trc::ConstantProperty(Tau, Color);
  auto gap = [](int i, int, int) { return i >= 2 && i < 4; };
  auto twoBoxes = trc::MakeGrid(6, 2, 2, Origin, 1.0, trc::Split::Six, Flat, gap);
  const std::vector<trc::Box> boxes = { { { 0, 0, 0 }, { 2, 2, 2 }, 1.0 },
    { { 4, 0, 0 }, { 6, 2, 2 }, 1.0 } };
  const double focal[3] = { 3, 1, 1 };
  const double along[3] = { 1, 0, 0 }, oblique[3] = { 1, 0.2, 0.3 };
  auto parallel = trc::MakeCamera(focal, along, Up, 20.0, true, 1.5, 1.0, 40.0);
  auto perspective = trc::MakeCamera(focal, oblique, Up, 12.0, false, 20.0, 1.0, 40.0);
  vtkCamera* cameras[2] = { parallel, perspective };
  const char* names[2] = { "two boxes, along x", "two boxes, oblique" };
  for (int c = 0; c < 2; ++c)
  {
    vtkNew<vtkTetReferenceRenderer> renderer;
    vtkImageData* image = RenderImage(renderer, twoBoxes, constant, cameras[c], 25, 25);
    TRC_CHECK(image);
    TRC_CHECK(trc::CheckBoxes(image, cameras[c], 25, 25, boxes, Tau, Color, names[c]) > 0);
  }
  return EXIT_SUCCESS;
}

// An opaque depth buffer ends each ray where it says (some pixels have no geometry).
int TestOpaqueDepth()
{
  auto constant = trc::ConstantProperty(Tau, Color);
  auto cube = trc::MakeGrid(4, 4, 4, Origin, 1.0, trc::Split::Five, Flat);
  const double focal[3] = { 2, 2, 2 }, dir[3] = { 0.5, 0.8, 0.6 };
  for (bool parallel : { true, false })
  {
    auto camera = trc::MakeCamera(focal, dir, Up, 10.0, parallel, parallel ? 3.5 : 35.0, 2.0, 20.0);
    const int w = 30, h = 24;
    vtkNew<vtkFloatArray> depth;
    depth->SetNumberOfTuples(w * h);
    vtkNew<vtkMinimalStandardRandomSequence> random;
    random->SetSeed(99);
    for (int p = 0; p < w * h; ++p)
    {
      random->Next();
      const double r = random->GetValue();
      depth->SetValue(p, r < 0.25 ? 1.0f : static_cast<float>(0.3 + 0.6 * r));
    }
    vtkNew<vtkTetReferenceRenderer> renderer;
    renderer->SetOpaqueDepth(depth);
    vtkImageData* image = RenderImage(renderer, cube, constant, camera, w, h);
    TRC_CHECK(image);
    // The end of each ray: the window depth mapped back through the camera, here.
    auto tmax = [&](int i, int j)
    {
      const float z = depth->GetValue(i + w * j);
      return z >= 1.0f ? 1.0 : trc::LambdaAtDepth(camera, w, h, i, j, z);
    };
    const trc::Box box = { { 0, 0, 0 }, { 4, 4, 4 }, 1.0 };
    TRC_CHECK(
      trc::CheckBoxes(image, camera, w, h, { box }, Tau, Color,
        parallel ? "opaque depth, parallel" : "opaque depth, perspective", tmax, 1e-11) > 0);
    // The depth buffer must matter: without it the image is more opaque.
    vtkNew<vtkTetReferenceRenderer> open;
    vtkImageData* unclipped = RenderImage(open, cube, constant, camera, w, h);
    TRC_CHECK(unclipped && Sum(unclipped, 3) > Sum(image, 3) + 1.0);
  }
  return EXIT_SUCCESS;
}

// A transformed volume. (a) Rotation, uniform scale k and translation equal moving the
// camera by the inverse transform, with the unit distance divided by k (lengths are
// world lengths). (b) A non-uniform scale stretches the chords of a box.
int TestTransformedVolume()
{
  auto constant = trc::ConstantProperty(Tau, Color);
  auto mesh = trc::MakeGrid(3, 3, 3, Origin, 1.0, trc::Split::Five, Linear);
  auto property = RampProperty();
  const double unit = 1.3, k = 1.7;
  property->SetScalarOpacityUnitDistance(unit);

  vtkNew<vtkVolume> volume;
  volume->SetPosition(5.0, -2.0, 3.0);
  volume->RotateWXYZ(30.0, 1.0, 2.0, 3.0);
  volume->SetScale(k);
  vtkMatrix4x4* m = volume->GetMatrix();
  double center[4] = { 1.5, 1.5, 1.5, 1.0 }, worldCenter[4];
  m->MultiplyPoint(center, worldCenter);
  const double dir[3] = { -0.4, 0.9, 0.3 }, viewUp[3] = { 0.2, 0.1, 1.0 };
  for (bool parallel : { true, false })
  {
    auto camera =
      trc::MakeCamera(worldCenter, dir, viewUp, 15.0, parallel, parallel ? 4.5 : 30.0, 1.0, 40.0);
    vtkNew<vtkTetReferenceRenderer> moved;
    moved->SetVolume(volume);
    vtkImageData* a = RenderImage(moved, mesh, property, camera, 32, 28);
    TRC_CHECK(a);

    // The same view in model coordinates.
    vtkNew<vtkMatrix4x4> inverse;
    vtkMatrix4x4::Invert(m, inverse);
    double p[4] = { 0, 0, 0, 1 }, f[4] = { 0, 0, 0, 1 }, u[4] = { 0, 0, 0, 0 }, q[4];
    camera->GetPosition(p);
    camera->GetFocalPoint(f);
    camera->GetViewUp(u);
    auto model = vtkSmartPointer<vtkCamera>::New();
    inverse->MultiplyPoint(p, q);
    model->SetPosition(q[0], q[1], q[2]);
    inverse->MultiplyPoint(f, q);
    model->SetFocalPoint(q[0], q[1], q[2]);
    inverse->MultiplyPoint(u, q); // a direction: w = 0
    model->SetViewUp(q[0], q[1], q[2]);
    model->SetParallelProjection(parallel ? 1 : 0);
    model->SetParallelScale(camera->GetParallelScale() / k);
    model->SetViewAngle(camera->GetViewAngle());
    model->SetClippingRange(1.0 / k, 40.0 / k);
    auto scaled = vtkSmartPointer<vtkVolumeProperty>::New();
    scaled->DeepCopy(property);
    scaled->SetScalarOpacityUnitDistance(unit / k);
    vtkNew<vtkTetReferenceRenderer> still;
    vtkImageData* b = RenderImage(still, mesh, scaled, model, 32, 28);
    TRC_CHECK(b);
    const double diff = MaxAbsDifference(a, b);
    std::cout << "volume matrix vs camera move (" << (parallel ? "parallel" : "perspective")
              << "): max difference " << diff << ", mean alpha " << Sum(a, 3) / (32 * 28)
              << std::endl;
    TRC_CHECK(diff <= 1e-10);
    TRC_CHECK(Sum(a, 3) > 20.0);

    // SetVolumeMatrix gives the same image as SetVolume.
    vtkNew<vtkTetReferenceRenderer> byMatrix;
    byMatrix->SetVolumeMatrix(m);
    vtkImageData* c2 = RenderImage(byMatrix, mesh, property, camera, 32, 28);
    TRC_CHECK(c2 && MaxAbsDifference(a, c2) == 0.0);
  }

  // (b) Non-uniform scale and translation of a constant box: world chords.
  auto cube = trc::MakeGrid(4, 4, 4, Origin, 1.0, trc::Split::Six, Flat);
  vtkNew<vtkTransform> stretch;
  stretch->Translate(1.0, -3.0, 2.0);
  stretch->Scale(2.0, 1.0, 0.5);
  const trc::Box world = { { 1, -3, 2 }, { 9, 1, 4 }, 1.0 };
  const double focal[3] = { 5, -1, 3 }, oblique[3] = { 0.3, -0.5, 0.8 };
  auto camera = trc::MakeCamera(focal, oblique, Up, 20.0, false, 35.0, 1.0, 50.0);
  vtkNew<vtkTetReferenceRenderer> renderer;
  renderer->SetVolumeMatrix(stretch->GetMatrix());
  vtkImageData* image = RenderImage(renderer, cube, constant, camera, 33, 33);
  TRC_CHECK(image);
  TRC_CHECK(trc::CheckBoxes(image, camera, 33, 33, { world }, Tau, Color, "non-uniform scale") > 0);
  return EXIT_SUCCESS;
}

// Far from the origin: the same mesh and camera translated by (1e6, -2e6, 3e5).
int TestFarFromOrigin()
{
  const double far[3] = { 1e6, -2e6, 3e5 };
  auto fieldFar = [&](double x, double y, double z)
  { return Linear(x - far[0], y - far[1], z - far[2]); };
  auto near = trc::MakeGrid(3, 3, 3, Origin, 1.0, trc::Split::Five, Linear);
  auto distant = trc::MakeGrid(3, 3, 3, far, 1.0, trc::Split::Five, fieldFar);
  auto property = RampProperty();
  const double dir[3] = { 0.4, -0.7, 0.5 };
  const double f0[3] = { 1.5, 1.5, 1.5 };
  const double f1[3] = { 1.5 + far[0], 1.5 + far[1], 1.5 + far[2] };
  auto camera0 = trc::MakeCamera(f0, dir, Up, 10.0, false, 30.0, 1.0, 30.0);
  auto camera1 = trc::MakeCamera(f1, dir, Up, 10.0, false, 30.0, 1.0, 30.0);
  vtkNew<vtkTetReferenceRenderer> r0, r1;
  vtkImageData* a = RenderImage(r0, near, property, camera0, 32, 32);
  vtkImageData* b = RenderImage(r1, distant, property, camera1, 32, 32);
  TRC_CHECK(a && b);
  const double diff = MaxAbsDifference(a, b);
  std::cout << "mesh at 2e6 from the origin vs at the origin: max difference " << diff << std::endl;
  // The cameras' matrices carry coordinates of 2e6 in double: ~1e-10 of rounding there.
  TRC_CHECK(diff <= 1e-8);
  TRC_CHECK(Sum(a, 3) > 20.0);
  return EXIT_SUCCESS;
}
} // namespace

int TestTetReferenceRendererGeometry(int, char*[])
{
  int (*tests[])() = { TestHollowCube, TestTwoBoxes, TestOpaqueDepth, TestTransformedVolume,
    TestFarFromOrigin };
  for (auto test : tests)
  {
    if (test() != EXIT_SUCCESS)
    {
      return EXIT_FAILURE;
    }
  }
  std::cout << "TestTetReferenceRendererGeometry passed" << std::endl;
  return EXIT_SUCCESS;
}
