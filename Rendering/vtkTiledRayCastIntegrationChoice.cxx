/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkTiledRayCastIntegrationChoice.cxx

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "vtkTiledRayCastIntegrationChoice.h"

#include "vtkDataArray.h"
#include "vtkMath.h"
#include "vtkSMPTools.h"
#include "vtkTetMesh.h"
#include "vtkTetRayIntegrator.h"
#include "vtkTiledRayCastPreIntegrationTable.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <random>

namespace
{
constexpr int NumberOfSegments = 4096;
constexpr int NumberOfRays = 512;
constexpr double SafetyFactor = 2.0;

// A table as the shaders read it: (mean colour, optical depth per unit length) entries,
// interpolated bilinearly (2D) or trilinearly (3D) between grid points.
class TableReader
{
public:
  explicit TableReader(vtkTiledRayCastPreIntegrationTable* table)
    : Table(table)
  {
    table->GetSize(this->Size);
    table->GetScalarRange(this->Range);
    this->ScalarScale =
      this->Range[1] > this->Range[0] ? (this->Size[0] - 1) / (this->Range[1] - this->Range[0]) : 0;
    this->Data = table->GetTable();
  }

  // The entry at (front scalar, back scalar, length grid coordinate).
  std::array<double, 4> Lookup(double s0, double s1, double lengthGrid) const
  {
    const double last = this->Size[0] - 1;
    const double g[3] = { std::min(std::max((s0 - this->Range[0]) * this->ScalarScale, 0.0), last),
      std::min(std::max((s1 - this->Range[0]) * this->ScalarScale, 0.0), last),
      std::min(std::max(lengthGrid, 0.0), this->Size[2] - 1.0) };
    int i[3];
    double f[3];
    for (int a = 0; a < 3; ++a)
    {
      i[a] =
        std::min(static_cast<int>(g[a]), std::max(0, (a < 2 ? this->Size[0] : this->Size[2]) - 2));
      f[a] = g[a] - i[a];
      if ((a < 2 ? this->Size[0] : this->Size[2]) == 1)
      {
        i[a] = 0;
        f[a] = 0;
      }
    }
    std::array<double, 4> result = { 0, 0, 0, 0 };
    for (int corner = 0; corner < 8; ++corner)
    {
      const int d[3] = { corner & 1, (corner >> 1) & 1, (corner >> 2) & 1 };
      double w = 1;
      for (int a = 0; a < 3; ++a)
      {
        w *= d[a] ? f[a] : 1 - f[a];
      }
      if (w == 0)
      {
        continue;
      }
      const size_t n = static_cast<size_t>(this->Size[0]);
      const float* e = this->Data +
        4 * ((static_cast<size_t>(i[2] + d[2]) * n + (i[1] + d[1])) * n + (i[0] + d[0]));
      for (int c = 0; c < 4; ++c)
      {
        result[c] += w * e[c];
      }
    }
    return result;
  }

  // Premultiplied colour and alpha of a segment, as vtkTiledRayCastPreIntegration2D/3D.glsl.
  void Integrate(double sf, double sb, double d, double rgba[4]) const
  {
    rgba[0] = rgba[1] = rgba[2] = rgba[3] = 0;
    if (!(d > 0) || !std::isfinite(sf) || !std::isfinite(sb))
    {
      return;
    }
    if (this->Table->GetDimension() == 3)
    {
      const double longest = this->Table->GetMaximumLength();
      const int parts = std::max(1, static_cast<int>(std::ceil(d / longest)));
      const double part = d / parts;
      const double lengthGrid = longest > 0 ? part * (this->Size[2] - 1) / longest : 0;
      for (int k = 0; k < parts; ++k)
      {
        const auto piece =
          this->Lookup(sf + (sb - sf) * k / parts, sf + (sb - sf) * (k + 1) / parts, lengthGrid);
        Over(piece, 1 - std::exp(-std::min(piece[3] * part, 80.0)), rgba);
      }
      return;
    }
    // 2D: one lookup at the reference length, split where the segment is optically thick.
    const double ratio = d / this->Table->GetReferenceLength();
    auto piece = this->Lookup(sf, sb, 0);
    const double depth = piece[3] * d;
    // Clamped as doubles: a near-opaque segment's depth is far beyond any int.
    const int parts = static_cast<int>(
      std::min(std::max(1.0, std::ceil(depth / 0.5)), std::max(1.0, std::ceil(ratio))));
    const double part = d / parts;
    for (int k = 0; k < parts; ++k)
    {
      if (parts > 1)
      {
        piece = this->Lookup(sf + (sb - sf) * k / parts, sf + (sb - sf) * (k + 1) / parts, 0);
      }
      Over(piece, 1 - std::exp(-std::min(piece[3] * part, 80.0)), rgba);
    }
  }

private:
  static void Over(const std::array<double, 4>& piece, double alpha, double rgba[4])
  {
    const double t = 1 - rgba[3];
    for (int c = 0; c < 3; ++c)
    {
      rgba[c] += t * alpha * piece[c];
    }
    rgba[3] += t * alpha;
  }

  vtkTiledRayCastPreIntegrationTable* Table;
  int Size[3];
  double Range[2];
  double ScalarScale;
  const float* Data;
};

// rgba = rgba over (in front of) piece.
void Composite(double rgba[4], const double piece[4])
{
  const double t = 1 - rgba[3];
  for (int c = 0; c < 4; ++c)
  {
    rgba[c] += t * piece[c];
  }
}
}

//------------------------------------------------------------------------------
vtkTiledRayCastIntegrationChoice::vtkTiledRayCastIntegrationChoice() = default;
vtkTiledRayCastIntegrationChoice::~vtkTiledRayCastIntegrationChoice() = default;

//------------------------------------------------------------------------------
void vtkTiledRayCastIntegrationChoice::SampleSegments(
  vtkTetMesh* mesh, vtkDataArray* movedPoints, double norm)
{
  const vtkMTimeType movedTime = movedPoints ? movedPoints->GetMTime() : 0;
  if (mesh == this->SampledMesh && mesh->GetMTime() == this->SampledMeshTime &&
    movedPoints == this->SampledPoints && movedTime == this->SampledPointsTime &&
    norm == this->SampledNorm)
  {
    return;
  }
  this->SampledMesh = mesh;
  this->SampledMeshTime = mesh->GetMTime();
  this->SampledPoints = movedPoints;
  this->SampledPointsTime = movedTime;
  this->SampledNorm = norm;
  this->Segments.clear();
  const vtkIdType numTets = mesh->GetNumberOfTetrahedra();
  // The tets a ray crosses, about: 1.0-1.4 cbrt(tets) measured on the benchmark meshes.
  this->SegmentsPerRay =
    std::max(1, static_cast<int>(std::ceil(1.5 * std::cbrt(static_cast<double>(numTets)))));
  const double* points = mesh->GetPoints();
  const uint32_t* inputIds = mesh->GetPointInputIds();
  // A point of the mesh where it is now: the mesh's copy, or the input's moved coordinates
  // (read in double, as a build would copy them).
  auto pointOf = [&](uint32_t id, double p[3])
  {
    if (movedPoints)
    {
      movedPoints->GetTuple(inputIds ? inputIds[id] : id, p);
    }
    else
    {
      std::copy(points + 3 * id, points + 3 * id + 3, p);
    }
  };
  const uint32_t* tetPoints = mesh->GetTetPoints();
  const double* pointScalars = mesh->GetPointScalars();
  const double* cellScalars = mesh->GetCellScalars();
  const uint8_t* flags = mesh->GetTetFlags();
  if (numTets == 0 || (!pointScalars && !cellScalars))
  {
    return;
  }
  std::mt19937_64 random(20261202);
  std::uniform_int_distribution<vtkIdType> pickTet(0, numTets - 1);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::normal_distribution<double> normal;
  for (int attempt = 0;
       attempt < 4 * NumberOfSegments && static_cast<int>(this->Segments.size()) < NumberOfSegments;
       ++attempt)
  {
    const vtkIdType t = pickTet(random);
    if (flags[t] & (vtkTetMesh::Overlapping | vtkTetMesh::Degenerate))
    {
      continue;
    }
    // A random point (uniform barycentric weights) and direction: the chord through it ends on
    // the faces where a barycentric weight reaches 0.
    double w[4], sum = 0;
    for (double& v : w)
    {
      v = -std::log(std::max(unit(random), 1e-300));
      sum += v;
    }
    double p[4][3], s[4];
    for (int k = 0; k < 4; ++k)
    {
      const uint32_t id = tetPoints[4 * t + k];
      pointOf(id, p[k]);
      s[k] = cellScalars ? cellScalars[t] : pointScalars[id];
      w[k] /= sum;
    }
    double dir[3] = { normal(random), normal(random), normal(random) };
    // The barycentric weights change along dir by the solution of [p1-p0 p2-p0 p3-p0] b = dir
    // (b the rates of weights 1-3; weight 0 takes minus their sum).
    double e[3][3];
    for (int k = 0; k < 3; ++k)
    {
      for (int a = 0; a < 3; ++a)
      {
        e[a][k] = p[k + 1][a] - p[0][a];
      }
    }
    if (!(std::abs(vtkMath::Determinant3x3(e)) > 0))
    {
      continue;
    }
    double rate[4];
    vtkMath::LinearSolve3x3(e, dir, rate + 1);
    rate[0] = -(rate[1] + rate[2] + rate[3]);
    double forward = VTK_DOUBLE_MAX, backward = VTK_DOUBLE_MAX;
    for (int k = 0; k < 4; ++k)
    {
      if (rate[k] < 0)
      {
        forward = std::min(forward, -w[k] / rate[k]);
      }
      else if (rate[k] > 0)
      {
        backward = std::min(backward, w[k] / rate[k]);
      }
    }
    if (forward == VTK_DOUBLE_MAX || backward == VTK_DOUBLE_MAX)
    {
      continue;
    }
    double front = 0, back = 0;
    for (int k = 0; k < 4; ++k)
    {
      front += (w[k] - backward * rate[k]) * s[k];
      back += (w[k] + forward * rate[k]) * s[k];
    }
    const double length =
      (forward + backward) * std::sqrt(dir[0] * dir[0] + dir[1] * dir[1] + dir[2] * dir[2]) * norm;
    if (std::isfinite(front) && std::isfinite(back) && length > 0)
    {
      this->Segments.push_back({ front, back, length });
    }
  }
}

//------------------------------------------------------------------------------
bool vtkTiledRayCastIntegrationChoice::SetProperty(vtkVolumeProperty* property)
{
  return this->Exact->Initialize(property) != 0 && this->Exact->IsInitialized();
}

//------------------------------------------------------------------------------
double vtkTiledRayCastIntegrationChoice::PredictError(vtkTiledRayCastPreIntegrationTable* table)
{
  const size_t n = this->Segments.size();
  this->WorstSegmentError = 0;
  if (n == 0 || !this->Exact->IsInitialized())
  {
    return 0;
  }
  // Each segment's exact and table colours.
  std::vector<std::array<double, 4>> exact(n), approximate(n);
  const TableReader reader(table);
  vtkSMPTools::For(0, static_cast<vtkIdType>(n),
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType i = begin; i < end; ++i)
      {
        const Segment& s = this->Segments[i];
        this->Exact->Integrate(s.Front, s.Back, s.Length, exact[i].data());
        reader.Integrate(s.Front, s.Back, s.Length, approximate[i].data());
      }
    });
  for (size_t i = 0; i < n; ++i)
  {
    for (int c = 0; c < 4; ++c)
    {
      this->WorstSegmentError =
        std::max(this->WorstSegmentError, 255.0 * std::abs(exact[i][c] - approximate[i][c]));
    }
  }
  // Rays of SegmentsPerRay segments drawn from the samples, composited both ways.
  std::mt19937_64 random(1202);
  std::uniform_int_distribution<size_t> pick(0, n - 1);
  double worst = 0;
  for (int r = 0; r < NumberOfRays; ++r)
  {
    double a[4] = { 0, 0, 0, 0 }, b[4] = { 0, 0, 0, 0 };
    for (int k = 0; k < this->SegmentsPerRay && a[3] < 0.999; ++k)
    {
      const size_t i = pick(random);
      Composite(a, exact[i].data());
      Composite(b, approximate[i].data());
    }
    for (int c = 0; c < 4; ++c)
    {
      worst = std::max(worst, 255.0 * std::abs(a[c] - b[c]));
    }
  }
  // Twice the worse of the two: on the scenes measured (docs/mapper.md) the random composition
  // and the worst sample fell short of the image's worst pixel by up to 2.1x (five huge tets,
  // whose longest chords are rare among the samples) and 6.5x (a 2 %-wide opacity band, whose
  // grazing rays are); with the factor no table was taken where its image was more than the
  // framebuffer's rounding off, and the band's tables were refused.
  return SafetyFactor * std::max(worst, this->WorstSegmentError);
}
