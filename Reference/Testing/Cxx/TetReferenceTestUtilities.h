/*=========================================================================

  Program:   TiledRayCast
  Module:    TetReferenceTestUtilities.h

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// Helpers shared by the reference renderer's tests: structured tetrahedral meshes, analytic
// chords and cameras (the brute-force integrator of the optical model is in
// Testing/Cxx/TetIntegrationTestUtilities.h, which the integrator's tests share). None of it uses
// the renderer's or the integrator's code: the tests compare two independent computations.
#ifndef TetReferenceTestUtilities_h
#define TetReferenceTestUtilities_h

#include "TetIntegrationTestUtilities.h" // For TRC_CHECK_NEAR, BruteForce
#include "TiledRayCastTestCheck.h"       // For TRC_CHECK

#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkColorTransferFunction.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkIntArray.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkSmartPointer.h"
#include "vtkTetReferenceRenderer.h"
#include "vtkUnstructuredGrid.h"
#include "vtkVolumeProperty.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <iostream>
#include <vector>

namespace trc
{

enum class Split
{
  Five, // 5 tetrahedra per voxel, alternating parity (conforming)
  Six   // 6 Kuhn tetrahedra around the diagonal v0-v6 (conforming)
};

// Renders `input` with `renderer` (double-precision output) and returns the image, null when
// the renderer refused.
inline vtkImageData* RenderImage(vtkTetReferenceRenderer* renderer, vtkDataSet* input,
  vtkVolumeProperty* property, vtkCamera* camera, int width, int height)
{
  renderer->SetInputData(input);
  renderer->SetVolumeProperty(property);
  renderer->SetCamera(camera);
  renderer->SetImageSize(width, height);
  renderer->DoublePrecisionOutputOn();
  return renderer->Render() ? renderer->GetOutput() : nullptr;
}

// The largest difference between two images' "RGBA" values.
inline double MaxAbsDifference(vtkImageData* a, vtkImageData* b)
{
  vtkDataArray* da = a->GetPointData()->GetArray("RGBA");
  vtkDataArray* db = b->GetPointData()->GetArray("RGBA");
  double worst = 0.0;
  for (vtkIdType i = 0; i < da->GetNumberOfValues(); ++i)
  {
    worst =
      std::max(worst, std::fabs(da->GetComponent(i / 4, i % 4) - db->GetComponent(i / 4, i % 4)));
  }
  return worst;
}

// A grid of nx x ny x nz voxels of size h starting at origin, each split into tetrahedra.
// Voxels for which skip(i, j, k) is true are left out (holes). The point scalars are
// field(x, y, z) (array "Field"); the cell scalars are field at the tetrahedron's centroid
// (array "CellField"). Tetrahedra come with both orientations, as in real data.
inline vtkSmartPointer<vtkUnstructuredGrid> MakeGrid(int nx, int ny, int nz, const double origin[3],
  double h, Split split, const std::function<double(double, double, double)>& field,
  const std::function<bool(int, int, int)>& skip = nullptr)
{
  auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkDoubleArray> scalars;
  scalars->SetName("Field");
  auto pid = [&](int i, int j, int k)
  { return static_cast<vtkIdType>(i + (nx + 1) * (j + (ny + 1) * k)); };
  for (int k = 0; k <= nz; ++k)
  {
    for (int j = 0; j <= ny; ++j)
    {
      for (int i = 0; i <= nx; ++i)
      {
        const double x = origin[0] + h * i, y = origin[1] + h * j, z = origin[2] + h * k;
        points->InsertNextPoint(x, y, z);
        scalars->InsertNextValue(field(x, y, z));
      }
    }
  }
  grid->SetPoints(points);
  grid->GetPointData()->SetScalars(scalars);
  vtkNew<vtkDoubleArray> cellScalars;
  cellScalars->SetName("CellField");
  static const int five[2][5][4] = { { { 0, 1, 3, 4 }, { 1, 2, 3, 6 }, { 1, 4, 5, 6 },
                                       { 3, 4, 6, 7 }, { 1, 3, 4, 6 } },
    { { 0, 1, 2, 5 }, { 0, 2, 3, 7 }, { 0, 4, 5, 7 }, { 2, 5, 6, 7 }, { 0, 2, 5, 7 } } };
  static const int six[6][4] = { { 0, 1, 2, 6 }, { 0, 2, 3, 6 }, { 0, 3, 7, 6 }, { 0, 7, 4, 6 },
    { 0, 4, 5, 6 }, { 0, 5, 1, 6 } };
  grid->AllocateExact(static_cast<vtkIdType>(6) * nx * ny * nz, 4);
  for (int k = 0; k < nz; ++k)
  {
    for (int j = 0; j < ny; ++j)
    {
      for (int i = 0; i < nx; ++i)
      {
        if (skip && skip(i, j, k))
        {
          continue;
        }
        const vtkIdType v[8] = { pid(i, j, k), pid(i + 1, j, k), pid(i + 1, j + 1, k),
          pid(i, j + 1, k), pid(i, j, k + 1), pid(i + 1, j, k + 1), pid(i + 1, j + 1, k + 1),
          pid(i, j + 1, k + 1) };
        const int count = split == Split::Five ? 5 : 6;
        for (int t = 0; t < count; ++t)
        {
          const int* local = split == Split::Five ? five[(i + j + k) % 2][t] : six[t];
          vtkIdType ids[4];
          double c[3] = { 0.0, 0.0, 0.0 };
          for (int q = 0; q < 4; ++q)
          {
            ids[q] = v[local[q]];
            double p[3];
            points->GetPoint(ids[q], p);
            for (int r = 0; r < 3; ++r)
            {
              c[r] += 0.25 * p[r];
            }
          }
          grid->InsertNextCell(VTK_TETRA, 4, ids);
          cellScalars->InsertNextValue(field(c[0], c[1], c[2]));
        }
      }
    }
  }
  grid->GetCellData()->AddArray(cellScalars);
  return grid;
}

// Parameter interval [t0, t1] (clipped to [tmin, tmax]) of the segment p + t d inside the box;
// returns false when empty. A ray in a face plane of the box counts as inside.
inline bool SlabInterval(const double p[3], const double d[3], const double lo[3],
  const double hi[3], double tmin, double tmax, double& t0, double& t1)
{
  t0 = tmin;
  t1 = tmax;
  for (int k = 0; k < 3; ++k)
  {
    if (d[k] == 0.0)
    {
      if (p[k] < lo[k] || p[k] > hi[k])
      {
        return false;
      }
      continue;
    }
    double a = (lo[k] - p[k]) / d[k], b = (hi[k] - p[k]) / d[k];
    if (a > b)
    {
      std::swap(a, b);
    }
    t0 = std::max(t0, a);
    t1 = std::min(t1, b);
  }
  return t1 > t0;
}

// A camera looking at focal from focal + distance * direction (normalised here).
inline vtkSmartPointer<vtkCamera> MakeCamera(const double focal[3], const double direction[3],
  const double viewUp[3], double distance, bool parallel, double scaleOrAngle, double nearClip,
  double farClip)
{
  auto camera = vtkSmartPointer<vtkCamera>::New();
  const double n = std::sqrt(
    direction[0] * direction[0] + direction[1] * direction[1] + direction[2] * direction[2]);
  camera->SetFocalPoint(focal[0], focal[1], focal[2]);
  camera->SetPosition(focal[0] + distance * direction[0] / n,
    focal[1] + distance * direction[1] / n, focal[2] + distance * direction[2] / n);
  camera->SetViewUp(viewUp[0], viewUp[1], viewUp[2]);
  camera->SetParallelProjection(parallel ? 1 : 0);
  if (parallel)
  {
    camera->SetParallelScale(scaleOrAngle);
  }
  else
  {
    camera->SetViewAngle(scaleOrAngle);
  }
  camera->SetClippingRange(nearClip, farClip);
  return camera;
}

// The ray of pixel (i, j) as docs/design.md defines it: world points at NDC z = -1 and +1 of
// the camera's composite projection (pixel centres), written out here independently.
inline void PixelRay(
  vtkCamera* camera, int width, int height, double i, double j, double nearP[3], double farP[3])
{
  vtkNew<vtkMatrix4x4> inverse;
  inverse->DeepCopy(
    camera->GetCompositeProjectionTransformMatrix(static_cast<double>(width) / height, -1.0, 1.0));
  inverse->Invert();
  const double x = 2.0 * (i + 0.5) / width - 1.0, y = 2.0 * (j + 0.5) / height - 1.0;
  for (int end = 0; end < 2; ++end)
  {
    const double in[4] = { x, y, end == 0 ? -1.0 : 1.0, 1.0 };
    double out[4];
    inverse->MultiplyPoint(in, out);
    double* p = end == 0 ? nearP : farP;
    for (int k = 0; k < 3; ++k)
    {
      p[k] = out[k] / out[3];
    }
  }
}

// The ray parameter (0 at the near plane, 1 at the far plane) of window depth z on pixel (i, j).
inline double LambdaAtDepth(vtkCamera* camera, int w, int h, int i, int j, double z)
{
  double nearP[3], farP[3];
  trc::PixelRay(camera, w, h, i, j, nearP, farP);
  vtkNew<vtkMatrix4x4> inverse;
  inverse->DeepCopy(camera->GetCompositeProjectionTransformMatrix(double(w) / h, -1, 1));
  inverse->Invert();
  const double in[4] = { 2.0 * (i + 0.5) / w - 1.0, 2.0 * (j + 0.5) / h - 1.0, 2.0 * z - 1.0, 1.0 };
  double out[4];
  inverse->MultiplyPoint(in, out);
  double num = 0.0, den = 0.0;
  for (int k = 0; k < 3; ++k)
  {
    const double dk = farP[k] - nearP[k];
    num += (out[k] / out[3] - nearP[k]) * dk;
    den += dk * dk;
  }
  return num / den;
}

// Pixel values of a reference output.
inline void Pixel(vtkImageData* image, int i, int j, double rgba[4])
{
  int dims[3];
  image->GetDimensions(dims);
  vtkDataArray* a = image->GetPointData()->GetArray("RGBA");
  a->GetTuple(i + dims[0] * static_cast<vtkIdType>(j), rgba);
}

inline int TetCount(vtkImageData* image, int i, int j)
{
  int dims[3];
  image->GetDimensions(dims);
  return static_cast<int>(image->GetPointData()
                            ->GetArray("NumberOfTets")
                            ->GetComponent(i + dims[0] * static_cast<vtkIdType>(j), 0));
}

// A box [Lo, Hi] of constant attenuation that adds (Sign +1) or removes (Sign -1, a cavity
// inside another box) chord length.
struct Box
{
  double Lo[3];
  double Hi[3];
  double Sign;
};

// Checks an image of boxes of constant attenuation tau and colour c pixel by pixel against
// alpha = 1 - exp(-tau chord), C = c alpha, the chord summed over the boxes with their signs,
// along each pixel's ray from the near plane (t = 0) to t = tmax(i, j) (1, the far plane, by
// default). Pixels whose ray passes within 1e-7 of a box's boundary (a silhouette) are left
// out: the chord is not defined better than that there. Returns the number of pixels checked,
// or -1 on failure (also when no checked pixel sees any box).
inline int CheckBoxes(vtkImageData* image, vtkCamera* camera, int width, int height,
  const std::vector<Box>& boxes, double tau, const double c[3], const char* what,
  const std::function<double(int, int)>& tmax = nullptr, double bound = 1e-12)
{
  int checked = 0, inside = 0;
  double worst = 0.0;
  for (int j = 0; j < height; ++j)
  {
    for (int i = 0; i < width; ++i)
    {
      double nearP[3], farP[3], d[3];
      PixelRay(camera, width, height, i, j, nearP, farP);
      for (int k = 0; k < 3; ++k)
      {
        d[k] = farP[k] - nearP[k];
      }
      const double tEnd = tmax ? tmax(i, j) : 1.0;
      const double length = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
      bool ambiguous = false, any = false;
      double chord = 0.0;
      for (const Box& box : boxes)
      {
        const double e = 1e-7;
        double loIn[3], hiIn[3], loOut[3], hiOut[3];
        for (int k = 0; k < 3; ++k)
        {
          loIn[k] = box.Lo[k] + e;
          hiIn[k] = box.Hi[k] - e;
          loOut[k] = box.Lo[k] - e;
          hiOut[k] = box.Hi[k] + e;
        }
        double t0, t1, u0, u1, w0, w1;
        const bool hit = SlabInterval(nearP, d, box.Lo, box.Hi, 0.0, tEnd, t0, t1);
        const bool hitIn = SlabInterval(nearP, d, loIn, hiIn, 0.0, tEnd, u0, u1);
        const bool hitOut = SlabInterval(nearP, d, loOut, hiOut, 0.0, tEnd, w0, w1);
        ambiguous = ambiguous || hitIn != hitOut;
        any = any || (hitIn && box.Sign > 0);
        if (hit)
        {
          chord += box.Sign * (t1 - t0) * length;
        }
      }
      if (ambiguous)
      {
        continue;
      }
      double rgba[4];
      Pixel(image, i, j, rgba);
      const double alpha = -std::expm1(-tau * chord);
      double diff = std::fabs(rgba[3] - alpha);
      for (int k = 0; k < 3; ++k)
      {
        diff = std::max(diff, std::fabs(rgba[k] - c[k] * alpha));
      }
      worst = std::max(worst, diff);
      if (!(diff <= bound))
      {
        std::cerr << what << ": pixel (" << i << ", " << j << ") alpha " << rgba[3] << ", expected "
                  << alpha << " (chord " << chord << "), " << TetCount(image, i, j) << " tetrahedra"
                  << std::endl;
        return -1;
      }
      if (chord > 1e-6 && TetCount(image, i, j) == 0)
      {
        std::cerr << what << ": pixel (" << i << ", " << j << ") crosses no tetrahedron"
                  << std::endl;
        return -1;
      }
      ++checked;
      inside += (any && chord > 1e-6) ? 1 : 0;
    }
  }
  std::cout << what << ": " << checked << " pixels checked (" << inside
            << " see the mesh), max difference " << worst << std::endl;
  if (inside == 0)
  {
    std::cerr << what << ": the mesh is not in view" << std::endl;
    return -1;
  }
  return checked;
}

} // namespace trc

#endif
