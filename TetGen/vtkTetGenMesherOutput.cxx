/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkTetGenMesherOutput.cxx

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "vtkTetGenMesherOutput.h"

#include "vtkAlgorithm.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCellType.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkIdTypeArray.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSMPTools.h"
#include "vtkSmartPointer.h"
#include "vtkTetGenMesher.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <limits>

// As in vtkTetGenMesher.cxx: TetGen's header after every VTK header, with TETLIBRARY.
#ifndef TETLIBRARY
#define TETLIBRARY
#endif
#include <tetgen.h>

namespace
{
// Copies TetGen's double coordinates into a float or double array.
template <typename ValueT>
void CopyCoordinates(const double* source, vtkIdType numberOfPoints, ValueT* target)
{
  vtkSMPTools::For(0, numberOfPoints, [&](vtkIdType begin, vtkIdType end) {
    for (vtkIdType i = 3 * begin; i < 3 * end; ++i)
    {
      target[i] = static_cast<ValueT>(source[i]);
    }
  });
}
}

//------------------------------------------------------------------------------
bool vtkTetGenMesherOutput::Fill(vtkTetGenMesher* mesher, vtkPolyData* input, const tetgenio& out,
  const std::vector<vtkIdType>& usedPointIds, const std::vector<double>& coordinates,
  vtkUnstructuredGrid* output, std::string& error)
{
  const vtkIdType numberOfSurfacePoints = static_cast<vtkIdType>(usedPointIds.size());
  const vtkIdType numberOfPoints = out.numberofpoints;
  const vtkIdType numberOfTets = out.numberoftetrahedra;
  if (numberOfTets <= 0 || out.numberofcorners != 4 || !out.tetrahedronlist)
  {
    error = "TetGen produced no tetrahedra: the holes remove every region, or the surface "
            "encloses no volume.";
    return false;
  }
  if (numberOfPoints < numberOfSurfacePoints ||
    !std::equal(coordinates.begin(), coordinates.end(), out.pointlist))
  {
    error = "TetGen renumbered the surface points; the output cannot be matched to the input.";
    return false;
  }

  vtkNew<vtkPoints> points;
  int pointType = input->GetPoints()->GetDataType();
  if (mesher->GetOutputPointsPrecision() == vtkAlgorithm::SINGLE_PRECISION)
  {
    pointType = VTK_FLOAT;
  }
  else if (mesher->GetOutputPointsPrecision() == vtkAlgorithm::DOUBLE_PRECISION ||
    (pointType != VTK_FLOAT && pointType != VTK_DOUBLE))
  {
    pointType = VTK_DOUBLE;
  }
  points->SetDataType(pointType);
  points->SetNumberOfPoints(numberOfPoints);
  if (pointType == VTK_FLOAT)
  {
    CopyCoordinates(
      out.pointlist, numberOfPoints, vtkFloatArray::SafeDownCast(points->GetData())->GetPointer(0));
  }
  else
  {
    CopyCoordinates(out.pointlist, numberOfPoints,
      vtkDoubleArray::SafeDownCast(points->GetData())->GetPointer(0));
  }
  output->SetPoints(points);
  vtkTetGenMesherOutput::MakeCells(out, output);

  if (mesher->GetRegionAttributes() && out.numberoftetrahedronattributes > 0 &&
    out.tetrahedronattributelist)
  {
    vtkNew<vtkDoubleArray> attribute;
    attribute->SetName("RegionAttribute");
    attribute->SetNumberOfValues(numberOfTets);
    const int stride = out.numberoftetrahedronattributes;
    for (vtkIdType t = 0; t < numberOfTets; ++t)
    {
      attribute->SetValue(t, out.tetrahedronattributelist[stride * t]);
    }
    output->GetCellData()->AddArray(attribute);
  }
  if (mesher->GetPassPointData())
  {
    vtkTetGenMesherOutput::CopyPointData(input, usedPointIds, output);
  }
  if (mesher->GetGenerateOriginalPointIds())
  {
    vtkNew<vtkIdTypeArray> originalIds;
    originalIds->SetName("vtkOriginalPointIds");
    originalIds->SetNumberOfValues(numberOfPoints);
    originalIds->Fill(-1);
    for (vtkIdType i = 0; i < numberOfSurfacePoints; ++i)
    {
      originalIds->SetValue(i, usedPointIds[i]);
    }
    output->GetPointData()->AddArray(originalIds);
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkTetGenMesherOutput::MakeCells(const tetgenio& out, vtkUnstructuredGrid* output)
{
  // TetGen 1.5 already lists its tetrahedra with det[p1-p0, p2-p0, p3-p0] > 0 (the torus of the
  // tests has no exception), but docs/design.md makes positive orientation a promise of every
  // mesh, so it is checked per tetrahedron rather than assumed of TetGen.
  const vtkIdType numberOfTets = out.numberoftetrahedra;
  const int firstNumber = out.firstnumber;
  vtkNew<vtkIdTypeArray> offsets;
  offsets->SetNumberOfValues(numberOfTets + 1);
  vtkNew<vtkIdTypeArray> connectivity;
  connectivity->SetNumberOfValues(4 * numberOfTets);
  const int* tets = out.tetrahedronlist;
  const double* xyz = out.pointlist;
  vtkIdType* conn = connectivity->GetPointer(0);
  vtkIdType* offs = offsets->GetPointer(0);
  vtkSMPTools::For(0, numberOfTets, [&](vtkIdType begin, vtkIdType end) {
    for (vtkIdType t = begin; t < end; ++t)
    {
      vtkIdType ids[4];
      for (int k = 0; k < 4; ++k)
      {
        ids[k] = tets[4 * t + k] - firstNumber;
      }
      const double* p0 = xyz + 3 * ids[0];
      double e[3][3];
      for (int k = 0; k < 3; ++k)
      {
        const double* p = xyz + 3 * ids[k + 1];
        e[k][0] = p[0] - p0[0];
        e[k][1] = p[1] - p0[1];
        e[k][2] = p[2] - p0[2];
      }
      if (vtkMath::Determinant3x3(e[0], e[1], e[2]) < 0.0)
      {
        std::swap(ids[2], ids[3]);
      }
      std::copy_n(ids, 4, conn + 4 * t);
      offs[t] = 4 * t;
    }
  });
  offs[numberOfTets] = 4 * numberOfTets;
  vtkNew<vtkCellArray> cells;
  cells->SetData(offsets, connectivity);
  output->SetCells(VTK_TETRA, cells);
}

//------------------------------------------------------------------------------
void vtkTetGenMesherOutput::CopyPointData(
  vtkPolyData* input, const std::vector<vtkIdType>& usedPointIds, vtkUnstructuredGrid* output)
{
  const vtkIdType numberOfPoints = output->GetNumberOfPoints();
  vtkPointData* inPD = input->GetPointData();
  vtkPointData* outPD = output->GetPointData();
  for (int a = 0; a < inPD->GetNumberOfArrays(); ++a)
  {
    vtkDataArray* source = inPD->GetArray(a);
    if (!source)
    {
      continue; // only numeric arrays can say "no value" (NaN or 0)
    }
    auto target = vtk::TakeSmartPointer(source->NewInstance());
    target->SetName(source->GetName());
    target->SetNumberOfComponents(source->GetNumberOfComponents());
    target->SetNumberOfTuples(numberOfPoints);
    const bool real = target->GetDataType() == VTK_FLOAT || target->GetDataType() == VTK_DOUBLE;
    for (int c = 0; c < target->GetNumberOfComponents(); ++c)
    {
      target->FillComponent(c, real ? std::numeric_limits<double>::quiet_NaN() : 0.0);
    }
    for (size_t i = 0; i < usedPointIds.size(); ++i)
    {
      target->SetTuple(static_cast<vtkIdType>(i), usedPointIds[i], source);
    }
    const int index = outPD->AddArray(target);
    for (int attributeType = 0; attributeType < vtkDataSetAttributes::NUM_ATTRIBUTES;
         ++attributeType)
    {
      if (inPD->GetAttribute(attributeType) == source)
      {
        outPD->SetActiveAttribute(index, attributeType);
      }
    }
  }
}
