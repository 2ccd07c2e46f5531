/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkTetMesh.cxx

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "vtkTetMesh.h"

#include "vtkDoubleArray.h"
#include "vtkMath.h"
#include "vtkObjectFactory.h"
#include "vtkTypeUInt32Array.h"

#include <cmath>
#include <cstring>
#include <limits>

vtkStandardNewMacro(vtkTetMesh);

//------------------------------------------------------------------------------
vtkTetMesh::vtkTetMesh() = default;

//------------------------------------------------------------------------------
vtkTetMesh::~vtkTetMesh() = default;

//------------------------------------------------------------------------------
void vtkTetMesh::Initialize()
{
  this->Points.clear();
  this->TetPoints.clear();
  this->TetNeighbors.clear();
  this->BoundaryFaces.clear();
  this->TetInputCellIds.clear();
  this->PointInputIds.clear();
  this->TetFlags.clear();
  this->PointScalars.clear();
  this->CellScalars.clear();
  this->HasCellScalars = false;
  this->ScalarRange[0] = this->ScalarRange[1] = 0.0;
  const double empty[6] = { 0.0, -1.0, 0.0, -1.0, 0.0, -1.0 };
  std::memcpy(this->Bounds, empty, sizeof(empty));
  this->Shift[0] = this->Shift[1] = this->Shift[2] = 0.0;
  this->LongestEdge = 0.0;
  this->Report->Reset();
  this->TopologyTime.Modified();
  this->PointsTime.Modified();
  this->ScalarsTime.Modified();
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkTetMesh::GetScalarRange(double range[2]) const
{
  range[0] = this->ScalarRange[0];
  range[1] = this->ScalarRange[1];
}

//------------------------------------------------------------------------------
void vtkTetMesh::GetBounds(double bounds[6]) const
{
  std::memcpy(bounds, this->Bounds, sizeof(this->Bounds));
}

//------------------------------------------------------------------------------
void vtkTetMesh::GetShift(double shift[3]) const
{
  std::memcpy(shift, this->Shift, sizeof(this->Shift));
}

//------------------------------------------------------------------------------
vtkTetMeshValidationReport* vtkTetMesh::GetReport()
{
  return this->Report;
}

//------------------------------------------------------------------------------
void vtkTetMesh::GetFacePointIndices(int face, int indices[3])
{
  if (face < 0 || face > 3)
  {
    indices[0] = indices[1] = indices[2] = -1;
    return;
  }
  indices[0] = vtkTetMesh::FacePoints[face][0];
  indices[1] = vtkTetMesh::FacePoints[face][1];
  indices[2] = vtkTetMesh::FacePoints[face][2];
}

//------------------------------------------------------------------------------
bool vtkTetMesh::CheckTet(vtkIdType tet, const char* method)
{
  if (tet < 0 || tet >= this->GetNumberOfTetrahedra())
  {
    vtkErrorMacro(<< method << ": tetrahedron " << tet << " out of range [0, "
                  << this->GetNumberOfTetrahedra() << ")");
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkTetMesh::GetTetPointIds(vtkIdType tet, vtkIdType ids[4])
{
  if (!this->CheckTet(tet, "GetTetPointIds"))
  {
    ids[0] = ids[1] = ids[2] = ids[3] = -1;
    return;
  }
  for (int k = 0; k < 4; ++k)
  {
    ids[k] = static_cast<vtkIdType>(this->TetPoints[4 * tet + k]);
  }
}

//------------------------------------------------------------------------------
vtkIdType vtkTetMesh::GetNeighborTet(vtkIdType tet, int face)
{
  if (!this->CheckTet(tet, "GetNeighborTet") || face < 0 || face > 3)
  {
    return -1;
  }
  const uint32_t word = this->TetNeighbors[4 * tet + face];
  return word == NoNeighbor ? -1 : static_cast<vtkIdType>(word >> 2);
}

//------------------------------------------------------------------------------
int vtkTetMesh::GetNeighborFace(vtkIdType tet, int face)
{
  if (!this->CheckTet(tet, "GetNeighborFace") || face < 0 || face > 3)
  {
    return -1;
  }
  const uint32_t word = this->TetNeighbors[4 * tet + face];
  return word == NoNeighbor ? -1 : static_cast<int>(word & 3u);
}

//------------------------------------------------------------------------------
vtkIdType vtkTetMesh::GetTetInputCellId(vtkIdType tet)
{
  return this->CheckTet(tet, "GetTetInputCellId")
    ? static_cast<vtkIdType>(this->TetInputCellIds[tet])
    : -1;
}

//------------------------------------------------------------------------------
int vtkTetMesh::GetTetFlags(vtkIdType tet)
{
  return this->CheckTet(tet, "GetTetFlags") ? static_cast<int>(this->TetFlags[tet]) : 0;
}

//------------------------------------------------------------------------------
double vtkTetMesh::ComputeDeterminantFast(vtkIdType tet) const
{
  const uint32_t* ids = this->TetPoints.data() + 4 * tet;
  const double* p0 = this->Points.data() + 3 * static_cast<size_t>(ids[0]);
  double e1[3], e2[3], e3[3], c[3];
  vtkMath::Subtract(this->Points.data() + 3 * static_cast<size_t>(ids[1]), p0, e1);
  vtkMath::Subtract(this->Points.data() + 3 * static_cast<size_t>(ids[2]), p0, e2);
  vtkMath::Subtract(this->Points.data() + 3 * static_cast<size_t>(ids[3]), p0, e3);
  vtkMath::Cross(e2, e3, c);
  return vtkMath::Dot(e1, c);
}

//------------------------------------------------------------------------------
double vtkTetMesh::ComputeSignedVolume(vtkIdType tet)
{
  return this->CheckTet(tet, "ComputeSignedVolume") ? this->ComputeDeterminantFast(tet) / 6.0 : 0.0;
}

//------------------------------------------------------------------------------
void vtkTetMesh::ComputeFaceNormalsFast(vtkIdType tet, double normals[12], bool unit) const
{
  const uint32_t* ids = this->TetPoints.data() + 4 * tet;
  const double* p[4];
  for (int k = 0; k < 4; ++k)
  {
    p[k] = this->Points.data() + 3 * static_cast<size_t>(ids[k]);
  }
  for (int face = 0; face < 4; ++face)
  {
    const double* a = p[FacePoints[face][0]];
    double ab[3], ac[3];
    vtkMath::Subtract(p[FacePoints[face][1]], a, ab);
    vtkMath::Subtract(p[FacePoints[face][2]], a, ac);
    double* n = normals + 3 * face;
    vtkMath::Cross(ab, ac, n);
    if (unit)
    {
      const double length = std::sqrt(vtkMath::Dot(n, n));
      const double scale = length > 0.0 ? 1.0 / length : 0.0;
      n[0] *= scale;
      n[1] *= scale;
      n[2] *= scale;
    }
  }
}

//------------------------------------------------------------------------------
void vtkTetMesh::ComputeFaceNormals(vtkIdType tet, double normals[12], bool unit)
{
  if (!this->CheckTet(tet, "ComputeFaceNormals"))
  {
    std::fill(normals, normals + 12, 0.0);
    return;
  }
  this->ComputeFaceNormalsFast(tet, normals, unit);
}

//------------------------------------------------------------------------------
bool vtkTetMesh::ComputeScalarGradientFast(vtkIdType tet, double gc[4]) const
{
  gc[0] = gc[1] = gc[2] = 0.0;
  if (!this->HasScalars() || (this->TetFlags[tet] & NonFiniteScalars))
  {
    gc[3] = std::numeric_limits<double>::quiet_NaN();
    return false;
  }
  if (this->HasCellScalars)
  {
    gc[3] = this->CellScalars[tet];
    return true;
  }
  const uint32_t* ids = this->TetPoints.data() + 4 * tet;
  const double* p[4];
  double s[4];
  for (int k = 0; k < 4; ++k)
  {
    p[k] = this->Points.data() + 3 * static_cast<size_t>(ids[k]);
    s[k] = this->PointScalars[ids[k]];
  }
  const double mean = 0.25 * (s[0] + s[1] + s[2] + s[3]);
  // Written around the centroid rather than p0: both reproduce the vertex values exactly in
  // exact arithmetic, the centroid form spreads the rounding evenly over the four vertices.
  double centroid[3];
  for (int c = 0; c < 3; ++c)
  {
    centroid[c] = 0.25 * (p[0][c] + p[1][c] + p[2][c] + p[3][c]) - this->Shift[c];
  }
  if (!(this->TetFlags[tet] & Degenerate))
  {
    // Solve e_k . g = s_k - s_0 (k = 1..3) by Cramer's rule with cross products.
    double e1[3], e2[3], e3[3], c23[3], c31[3], c12[3];
    vtkMath::Subtract(p[1], p[0], e1);
    vtkMath::Subtract(p[2], p[0], e2);
    vtkMath::Subtract(p[3], p[0], e3);
    vtkMath::Cross(e2, e3, c23);
    vtkMath::Cross(e3, e1, c31);
    vtkMath::Cross(e1, e2, c12);
    const double det = vtkMath::Dot(e1, c23);
    if (det != 0.0)
    {
      const double d1 = (s[1] - s[0]) / det;
      const double d2 = (s[2] - s[0]) / det;
      const double d3 = (s[3] - s[0]) / det;
      for (int c = 0; c < 3; ++c)
      {
        gc[c] = d1 * c23[c] + d2 * c31[c] + d3 * c12[c];
      }
    }
  }
  gc[3] = mean - vtkMath::Dot(gc, centroid);
  return true;
}

//------------------------------------------------------------------------------
bool vtkTetMesh::ComputeScalarGradient(vtkIdType tet, double gradientAndOffset[4])
{
  if (!this->CheckTet(tet, "ComputeScalarGradient"))
  {
    gradientAndOffset[0] = gradientAndOffset[1] = gradientAndOffset[2] = 0.0;
    gradientAndOffset[3] = std::numeric_limits<double>::quiet_NaN();
    return false;
  }
  return this->ComputeScalarGradientFast(tet, gradientAndOffset);
}

//------------------------------------------------------------------------------
void vtkTetMesh::CopyTetPoints(vtkTypeUInt32Array* out)
{
  if (!out)
  {
    return;
  }
  out->SetNumberOfComponents(4);
  out->SetNumberOfTuples(this->GetNumberOfTetrahedra());
  std::copy(this->TetPoints.begin(), this->TetPoints.end(), out->GetPointer(0));
}

//------------------------------------------------------------------------------
void vtkTetMesh::CopyTetNeighbors(vtkTypeUInt32Array* out)
{
  if (!out)
  {
    return;
  }
  out->SetNumberOfComponents(4);
  out->SetNumberOfTuples(this->GetNumberOfTetrahedra());
  std::copy(this->TetNeighbors.begin(), this->TetNeighbors.end(), out->GetPointer(0));
}

//------------------------------------------------------------------------------
void vtkTetMesh::CopyBoundaryFaces(vtkTypeUInt32Array* out)
{
  if (!out)
  {
    return;
  }
  out->SetNumberOfComponents(1);
  out->SetNumberOfTuples(this->GetNumberOfBoundaryFaces());
  std::copy(this->BoundaryFaces.begin(), this->BoundaryFaces.end(), out->GetPointer(0));
}

//------------------------------------------------------------------------------
void vtkTetMesh::CopyTetInputCellIds(vtkTypeUInt32Array* out)
{
  if (!out)
  {
    return;
  }
  out->SetNumberOfComponents(1);
  out->SetNumberOfTuples(this->GetNumberOfTetrahedra());
  std::copy(this->TetInputCellIds.begin(), this->TetInputCellIds.end(), out->GetPointer(0));
}

//------------------------------------------------------------------------------
void vtkTetMesh::CopyPoints(vtkDoubleArray* out)
{
  if (!out)
  {
    return;
  }
  out->SetNumberOfComponents(3);
  out->SetNumberOfTuples(this->GetNumberOfPoints());
  std::copy(this->Points.begin(), this->Points.end(), out->GetPointer(0));
}

//------------------------------------------------------------------------------
void vtkTetMesh::CopyScalars(vtkDoubleArray* out)
{
  if (!out)
  {
    return;
  }
  const vtkTetMeshVector<double>& values =
    this->HasCellScalars ? this->CellScalars : this->PointScalars;
  out->SetNumberOfComponents(1);
  out->SetNumberOfTuples(static_cast<vtkIdType>(values.size()));
  std::copy(values.begin(), values.end(), out->GetPointer(0));
}

//------------------------------------------------------------------------------
void vtkTetMesh::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "NumberOfPoints: " << this->GetNumberOfPoints() << "\n";
  os << indent << "NumberOfTetrahedra: " << this->GetNumberOfTetrahedra() << "\n";
  os << indent << "NumberOfBoundaryFaces: " << this->GetNumberOfBoundaryFaces() << "\n";
  os << indent << "HasCellScalars: " << (this->HasCellScalars ? "true" : "false") << "\n";
  os << indent << "ScalarRange: (" << this->ScalarRange[0] << ", " << this->ScalarRange[1] << ")\n";
  os << indent << "Bounds: (" << this->Bounds[0] << ", " << this->Bounds[1] << ", "
     << this->Bounds[2] << ", " << this->Bounds[3] << ", " << this->Bounds[4] << ", "
     << this->Bounds[5] << ")\n";
  os << indent << "Shift: (" << this->Shift[0] << ", " << this->Shift[1] << ", " << this->Shift[2]
     << ")\n";
  os << indent << "TopologyTime: " << this->TopologyTime.GetMTime() << "\n";
  os << indent << "PointsTime: " << this->PointsTime.GetMTime() << "\n";
  os << indent << "ScalarsTime: " << this->ScalarsTime.GetMTime() << "\n";
  os << indent << "Report:\n";
  this->Report->PrintSelf(os, indent.GetNextIndent());
}
