/*=========================================================================

  Program:   TiledRayCast
  Module:    TestTetReferenceRendererShading.cxx

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// The reference renderer's shading (docs/design.md, "Shading") against closed forms: a cube of
// tetrahedra holding one linear field s = g.x + s0 (one gradient everywhere) under a constant
// transfer function, so that every pixel's unshaded colour is c alpha, alpha = 1 - exp(-tau
// chord), the chord clipped here from the cube's slabs. Shaded, the pixel is
//   (ka + kd sum D_i |n.l_i|) c alpha + ks sum S_i |n.h_i|^p alpha
// with n = -g / |g|, l_i towards the light, h_i the half vector of l_i and the direction to the
// viewer (absolute values with two-sided lighting; one-sided: no diffuse or highlight where n.l
// is not positive, no highlight where n.h is not). Checked to 1e-12 for a scene light, a
// headlight and a camera light, two-sided and one-sided, perspective and parallel; a constant
// field (zero gradient) gets the ambient term alone; blend modes other than compositing and
// scenes are not shaded (the latter refused with an error). Gradient opacity likewise: the
// function at |g| scales the attenuation.
#include "TetReferenceTestUtilities.h"

#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkMath.h"
#include "vtkTestErrorObserver.h"

namespace
{
// The scene: colour and attenuation of the constant transfer function, the cube's field
// gradient, the camera (direction from the focal point towards the camera) and a scene light.
const double c[3] = { 0.9, 0.6, 0.3 };
const double tau = 0.7;
const double origin[3] = { 0, 0, 0 };
const double g[3] = { 0.3, -0.2, 0.5 };
const double focal[3] = { 1, 1, 1 };
const double direction[3] = { 0.4, -0.7, 1.0 };
const double up[3] = { 0, 0, 1 };
const double scenePosition[3] = { -1.0, 2.0, -3.0 };
const double warm[3] = { 1.0, 0.8, 0.6 };
const double cool[3] = { 0.6, 0.8, 1.0 };

struct Material
{
  double Ka = 0.15, Kd = 0.6, Ks = 0.4, Power = 12.0;
};

struct LightSpec
{
  double ToLight[3];
  double Diffuse[3];
  double Specular[3];
};

double Dot(const double a[3], const double b[3])
{
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

void Normalize(double a[3])
{
  const double n = std::sqrt(Dot(a, a));
  for (int k = 0; k < 3; ++k)
  {
    a[k] /= n;
  }
}

// The closed form of one pixel: the cube's chord along the pixel's ray, then the shaded colour.
void Expected(vtkCamera* camera, int size, int i, int j, double tau, const double c[3],
  const double g[3], const Material& m, const std::vector<LightSpec>& lights, bool twoSided,
  double rgba[4])
{
  double nearP[3], farP[3], d[3];
  trc::PixelRay(camera, size, size, i, j, nearP, farP);
  for (int k = 0; k < 3; ++k)
  {
    d[k] = farP[k] - nearP[k];
  }
  const double lo[3] = { 0, 0, 0 }, hi[3] = { 2, 2, 2 };
  double t0, t1;
  const double chord =
    trc::SlabInterval(nearP, d, lo, hi, 0.0, 1.0, t0, t1) ? (t1 - t0) * std::sqrt(Dot(d, d)) : 0.0;
  const double alpha = -std::expm1(-tau * chord);
  double n[3] = { -g[0], -g[1], -g[2] };
  const bool flat = Dot(g, g) == 0.0;
  if (!flat)
  {
    Normalize(n);
  }
  double v[3] = { -d[0], -d[1], -d[2] };
  Normalize(v);
  double scale[3] = { m.Ka, m.Ka, m.Ka }, offset[3] = { 0, 0, 0 };
  for (const LightSpec& l : lights)
  {
    double h[3] = { l.ToLight[0] + v[0], l.ToLight[1] + v[1], l.ToLight[2] + v[2] };
    Normalize(h);
    double nl = flat ? 0.0 : Dot(n, l.ToLight);
    double nh = flat ? 0.0 : Dot(n, h);
    if (twoSided)
    {
      nl = std::abs(nl);
      nh = std::abs(nh);
    }
    for (int k = 0; k < 3 && nl > 0.0; ++k)
    {
      scale[k] += m.Kd * nl * l.Diffuse[k];
      offset[k] += nh > 0.0 ? m.Ks * std::pow(nh, m.Power) * l.Specular[k] : 0.0;
    }
  }
  for (int k = 0; k < 3; ++k)
  {
    rgba[k] = (scale[k] * c[k] + offset[k]) * alpha;
  }
  rgba[3] = alpha;
}

vtkSmartPointer<vtkLight> MakeLight(
  int type, const double position[3], const double diffuse[3], double intensity)
{
  auto light = vtkSmartPointer<vtkLight>::New();
  light->SetLightType(type);
  light->SetPosition(position[0], position[1], position[2]);
  light->SetFocalPoint(0, 0, 0);
  light->SetDiffuseColor(diffuse[0], diffuse[1], diffuse[2]);
  light->SetSpecularColor(0.5, 0.7, 1.0);
  light->SetIntensity(intensity);
  return light;
}

// Renders the cube shaded and compares every pixel with the closed form; returns pixels hit.
int CheckImage(vtkUnstructuredGrid* cube, vtkVolumeProperty* property, vtkCamera* camera,
  vtkLightCollection* lights, const std::vector<LightSpec>& specs, bool twoSided, double tau,
  const double c[3], const double g[3], const Material& m, double& worst)
{
  const int size = 24;
  vtkNew<vtkTetReferenceRenderer> renderer;
  renderer->SetLights(lights);
  renderer->SetTwoSidedLighting(twoSided);
  renderer->DoublePrecisionOutputOn();
  vtkImageData* image = trc::RenderImage(renderer, cube, property, camera, size, size);
  if (!image)
  {
    worst = 1.0;
    return 0;
  }
  int hit = 0;
  for (int j = 0; j < size; ++j)
  {
    for (int i = 0; i < size; ++i)
    {
      double expected[4], rgba[4];
      Expected(camera, size, i, j, tau, c, g, m, specs, twoSided, expected);
      trc::Pixel(image, i, j, rgba);
      hit += expected[3] > 1e-3 ? 1 : 0;
      for (int k = 0; k < 4; ++k)
      {
        worst = std::max(worst, std::abs(rgba[k] - expected[k]));
      }
    }
  }
  return hit;
}

// Gradient opacity: the cube's |g| = 0.616 maps to k = 0.2 + 0.8 |g| through a ramp, which
// scales the attenuation (alpha = 1 - exp(-k tau chord)), shaded or not; outside a function
// that does not clamp, k = 0 (nothing drawn); disabled, k = 1.
int CheckGradientOpacity(vtkVolumeProperty* property, vtkUnstructuredGrid* cube)
{
  const Material m;
  const double magnitude = std::sqrt(Dot(g, g));
  const double k = 0.2 + 0.8 * magnitude;
  vtkNew<vtkPiecewiseFunction> ramp;
  ramp->AddPoint(0.0, 0.2);
  ramp->AddPoint(1.0, 1.0);
  property->SetGradientOpacity(ramp);
  auto camera = trc::MakeCamera(focal, direction, up, 8.0, false, 30.0, 1.0, 20.0);
  vtkNew<vtkLightCollection> lights;
  lights->AddItem(MakeLight(VTK_LIGHT_TYPE_SCENE_LIGHT, scenePosition, warm, 0.9));
  LightSpec spec;
  for (int c = 0; c < 3; ++c)
  {
    spec.ToLight[c] = scenePosition[c];
    spec.Diffuse[c] = 0.9 * warm[c];
    spec.Specular[c] = 0.9 * (c == 0 ? 0.5 : (c == 1 ? 0.7 : 1.0));
  }
  Normalize(spec.ToLight);
  Material unlit;
  unlit.Ka = 1.0;
  unlit.Kd = 0.0;
  unlit.Ks = 0.0;
  property->ShadeOff();
  double worst = 0.0;
  TRC_CHECK(
    CheckImage(cube, property, camera, lights, {}, true, k * tau, c, g, unlit, worst) > 100);
  std::cout << "gradient opacity: largest difference " << worst << "\n";
  TRC_CHECK(worst <= 1e-12);
  property->ShadeOn();
  worst = 0.0;
  TRC_CHECK(
    CheckImage(cube, property, camera, lights, { spec }, true, k * tau, c, g, m, worst) > 100);
  std::cout << "gradient opacity, shaded: largest difference " << worst << "\n";
  TRC_CHECK(worst <= 1e-12);
  ramp->RemoveAllPoints();
  ramp->AddPoint(1.0, 1.0);
  ramp->AddPoint(2.0, 1.0);
  ramp->ClampingOff();
  worst = 0.0;
  CheckImage(cube, property, camera, lights, { spec }, true, 0.0, c, g, m, worst);
  TRC_CHECK(worst == 0.0);
  property->DisableGradientOpacityOn();
  worst = 0.0;
  TRC_CHECK(CheckImage(cube, property, camera, lights, { spec }, true, tau, c, g, m, worst) > 100);
  TRC_CHECK(worst <= 1e-12);
  property->DisableGradientOpacityOff();
  property->SetGradientOpacity(nullptr);
  return EXIT_SUCCESS;
}
} // namespace

int TestTetReferenceRendererShading(int, char*[])
{
  const Material m;
  auto property = trc::ConstantProperty(tau, c);
  property->ShadeOn();
  property->SetAmbient(m.Ka);
  property->SetDiffuse(m.Kd);
  property->SetSpecular(m.Ks);
  property->SetSpecularPower(m.Power);

  auto linear = [](double x, double y, double z) { return 1.0 + g[0] * x + g[1] * y + g[2] * z; };
  auto cube = trc::MakeGrid(2, 2, 2, origin, 1.0, trc::Split::Five, linear);
  const double zero[3] = { 0, 0, 0 };
  auto flat = trc::MakeGrid(
    2, 2, 2, origin, 1.0, trc::Split::Six, [](double, double, double) { return 1.5; });

  for (bool parallel : { false, true })
  {
    auto camera =
      trc::MakeCamera(focal, direction, up, 8.0, parallel, parallel ? 2.0 : 30.0, 1.0, 20.0);
    // A scene light, a headlight (the camera's direction whatever its own position) and a camera
    // light (placed in the camera's frame: its position (1, 0, 1) is to the right and behind).
    auto scene = MakeLight(VTK_LIGHT_TYPE_SCENE_LIGHT, scenePosition, warm, 0.9);
    const double anywhere[3] = { 5, 5, 5 };
    auto head = MakeLight(VTK_LIGHT_TYPE_HEADLIGHT, anywhere, cool, 0.5);
    const double cameraFrame[3] = { 1, 0, 1 };
    auto cameraLight = MakeLight(VTK_LIGHT_TYPE_CAMERA_LIGHT, cameraFrame, warm, 0.4);
    cameraLight->SetFocalPoint(0, 0, 0);
    vtkNew<vtkLightCollection> lights;
    lights->AddItem(scene);
    lights->AddItem(head);
    lights->AddItem(cameraLight);
    std::vector<LightSpec> specs(3);
    double toCamera[3] = { direction[0], direction[1], direction[2] };
    Normalize(toCamera);
    const double forward[3] = { -toCamera[0], -toCamera[1], -toCamera[2] };
    double right[3];
    vtkMath::Cross(forward, up, right); // the camera's right: forward x view up
    Normalize(right);
    const double* positions[3] = { scenePosition, toCamera, nullptr };
    double cameraLightDir[3];
    for (int k = 0; k < 3; ++k)
    {
      // The camera light's position in the camera frame (x right, y up, z towards the camera):
      // (1, 0, 1) minus its focal point, the origin of that frame.
      cameraLightDir[k] = right[k] + toCamera[k];
    }
    positions[2] = cameraLightDir;
    const double* colours[3] = { warm, cool, warm };
    const double intensities[3] = { 0.9, 0.5, 0.4 };
    for (int l = 0; l < 3; ++l)
    {
      for (int k = 0; k < 3; ++k)
      {
        specs[l].ToLight[k] = positions[l][k];
        specs[l].Diffuse[k] = intensities[l] * colours[l][k];
        specs[l].Specular[k] = intensities[l] * (k == 0 ? 0.5 : (k == 1 ? 0.7 : 1.0));
      }
      Normalize(specs[l].ToLight);
    }
    for (bool twoSided : { true, false })
    {
      double worst = 0.0;
      const int hit =
        CheckImage(cube, property, camera, lights, specs, twoSided, tau, c, g, m, worst);
      std::cout << (parallel ? "parallel" : "perspective")
                << (twoSided ? ", two-sided" : ", one-sided") << ": " << hit
                << " pixels, largest difference " << worst << "\n";
      TRC_CHECK(hit > 100);
      TRC_CHECK(worst <= 1e-12);
      // The field's opposite: one-sided lighting then lights the other side.
      const double minusG[3] = { -g[0], -g[1], -g[2] };
      auto opposite = trc::MakeGrid(2, 2, 2, origin, 1.0, trc::Split::Six,
        [](double x, double y, double z) { return 3.0 - g[0] * x - g[1] * y - g[2] * z; });
      worst = 0.0;
      TRC_CHECK(CheckImage(opposite, property, camera, lights, specs, twoSided, tau, c, minusG, m,
                  worst) > 100);
      TRC_CHECK(worst <= 1e-12);
      // A constant field: no gradient, the ambient term alone.
      worst = 0.0;
      TRC_CHECK(
        CheckImage(flat, property, camera, lights, specs, twoSided, tau, c, zero, m, worst) > 100);
      TRC_CHECK(worst <= 1e-12);
    }
    // No lights at all: the ambient term alone.
    double worst = 0.0;
    TRC_CHECK(CheckImage(cube, property, camera, nullptr, {}, true, tau, c, zero, m, worst) > 100);
    TRC_CHECK(worst <= 1e-12);
  }

  // Shading off, or a blend mode other than compositing: unshaded (the flat cube's c alpha).
  {
    const double direction2[3] = { 1, 1, 1 };
    auto camera = trc::MakeCamera(focal, direction2, up, 8.0, true, 2.0, 1.0, 20.0);
    Material unlit;
    unlit.Ka = 1.0;
    unlit.Kd = 0.0;
    unlit.Ks = 0.0;
    vtkNew<vtkLightCollection> lights;
    lights->AddItem(MakeLight(VTK_LIGHT_TYPE_SCENE_LIGHT, scenePosition, warm, 1.0));
    property->ShadeOff();
    double worst = 0.0;
    TRC_CHECK(CheckImage(cube, property, camera, lights, {}, true, tau, c, g, unlit, worst) > 100);
    TRC_CHECK(worst <= 1e-12);
    // Maximum intensity: the same image shaded or not.
    vtkImageData* images[2];
    vtkNew<vtkTetReferenceRenderer> maximum[2];
    for (int shade = 0; shade < 2; ++shade)
    {
      property->SetShade(shade);
      maximum[shade]->SetLights(lights);
      maximum[shade]->SetBlendMode(1);
      images[shade] = trc::RenderImage(maximum[shade], cube, property, camera, 24, 24);
      TRC_CHECK(images[shade]);
    }
    double stats[3];
    TRC_CHECK(vtkTetReferenceRenderer::CompareImages(images[0], images[1], stats));
    TRC_CHECK(stats[2] == 0.0);
  }

  TRC_CHECK(CheckGradientOpacity(property, cube) == EXIT_SUCCESS);

  // A scene refuses a shaded volume, with an error.
  {
    auto camera = trc::MakeCamera(focal, direction, up, 8.0, false, 30.0, 1.0, 20.0);
    vtkNew<vtkTetReferenceRenderer> renderer;
    vtkNew<vtkTest::ErrorObserver> errors;
    renderer->AddObserver(vtkCommand::ErrorEvent, errors);
    renderer->SetCamera(camera);
    renderer->AddVolume(cube, property);
    TRC_CHECK(renderer->Render() == 0);
    TRC_CHECK(errors->GetError() && errors->GetErrorMessage().find("shaded") != std::string::npos);
  }
  return EXIT_SUCCESS;
}
