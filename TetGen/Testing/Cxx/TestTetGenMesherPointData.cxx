/*=========================================================================

  Program:   TiledRayCast
  Module:    TestTetGenMesherPointData.cxx

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// What vtkTetGenMesher does with the input's points and point data: the surface points come
// first and unchanged; PassPointData copies every numeric array onto them (active attributes
// kept) and gives the points TetGen adds NaN (floating point) or 0 (integers);
// GenerateOriginalPointIds maps each output point to its input id (-1 for added points);
// OutputPointsPrecision picks float or double; an isolated input point is dropped.
#include "TetGenTestUtilities.h"

#include "vtkDoubleArray.h"
#include "vtkIdTypeArray.h"
#include "vtkIntArray.h"
#include "vtkPointData.h"
#include "vtkSphereSource.h"
#include "vtkTetGenMesher.h"

#include <cstdlib>

using namespace trc_tetgen_test;

int TestTetGenMesherPointData(int, char*[])
{
  vtkNew<vtkSphereSource> source;
  source->SetThetaResolution(24);
  source->SetPhiResolution(12);
  source->SetRadius(2.0);
  source->Update();
  vtkNew<vtkPolyData> sphere;
  sphere->ShallowCopy(source->GetOutput());
  const vtkIdType n = sphere->GetNumberOfPoints();
  TRC_CHECK(OpenEdges(sphere) == 0);

  vtkNew<vtkDoubleArray> height;
  height->SetName("Height");
  vtkNew<vtkIntArray> label;
  label->SetName("Label");
  label->SetNumberOfComponents(2);
  for (vtkIdType i = 0; i < n; ++i)
  {
    height->InsertNextValue(sphere->GetPoint(i)[2]);
    label->InsertNextTuple2(static_cast<double>(i), static_cast<double>(-i));
  }
  sphere->GetPointData()->SetNormals(nullptr);
  sphere->GetPointData()->SetScalars(height);
  sphere->GetPointData()->AddArray(label);

  vtkNew<vtkTetGenMesher> mesher;
  mesher->SetInputData(sphere);
  mesher->QualityOn();
  mesher->SetMaximumVolume(0.05);
  mesher->Update();
  vtkUnstructuredGrid* mesh = mesher->GetOutput();
  // By default no point data, float points as the sphere's.
  TRC_CHECK(mesh->GetPointData()->GetNumberOfArrays() == 0);
  TRC_CHECK(mesh->GetPoints()->GetDataType() == VTK_FLOAT);
  const vtkIdType total = mesh->GetNumberOfPoints();
  TRC_CHECK(total > n);
  TRC_CHECK(RelativeDifference(Measure(mesh).Volume, EnclosedVolume(sphere)) < 1e-6);

  mesher->PassPointDataOn();
  mesher->GenerateOriginalPointIdsOn();
  mesher->SetOutputPointsPrecision(vtkAlgorithm::DOUBLE_PRECISION);
  mesher->Update();
  mesh = mesher->GetOutput();
  TRC_CHECK(mesh->GetNumberOfPoints() == total);
  TRC_CHECK(mesh->GetPoints()->GetDataType() == VTK_DOUBLE);
  vtkPointData* pd = mesh->GetPointData();
  auto outHeight = vtkDoubleArray::SafeDownCast(pd->GetArray("Height"));
  auto outLabel = vtkIntArray::SafeDownCast(pd->GetArray("Label"));
  auto ids = vtkIdTypeArray::SafeDownCast(pd->GetArray("vtkOriginalPointIds"));
  TRC_CHECK(outHeight && outLabel && ids);
  TRC_CHECK(pd->GetScalars() == outHeight);
  TRC_CHECK(outLabel->GetNumberOfComponents() == 2);
  for (vtkIdType i = 0; i < total; ++i)
  {
    if (i < n)
    {
      double in[3], out[3];
      sphere->GetPoint(i, in);
      mesh->GetPoint(i, out);
      TRC_CHECK(in[0] == out[0] && in[1] == out[1] && in[2] == out[2]);
      TRC_CHECK(ids->GetValue(i) == i);
      TRC_CHECK(outHeight->GetValue(i) == height->GetValue(i));
      TRC_CHECK(outLabel->GetTypedComponent(i, 0) == i && outLabel->GetTypedComponent(i, 1) == -i);
    }
    else
    {
      TRC_CHECK(ids->GetValue(i) == -1);
      TRC_CHECK(std::isnan(outHeight->GetValue(i)));
      TRC_CHECK(outLabel->GetTypedComponent(i, 0) == 0 && outLabel->GetTypedComponent(i, 1) == 0);
    }
  }

  // An isolated input point (used by no facet) does not reach TetGen: the mapping skips it.
  // The stray point comes first, so every facet id moves up by one.
  vtkNew<vtkPoints> shifted;
  shifted->SetDataTypeToFloat();
  shifted->InsertNextPoint(10.0, 10.0, 10.0);
  for (vtkIdType i = 0; i < n; ++i)
  {
    shifted->InsertNextPoint(sphere->GetPoint(i));
  }
  vtkNew<vtkCellArray> polys;
  auto iter = vtk::TakeSmartPointer(sphere->GetPolys()->NewIterator());
  for (iter->GoToFirstCell(); !iter->IsDoneWithTraversal(); iter->GoToNextCell())
  {
    vtkIdType npts;
    const vtkIdType* pts;
    iter->GetCurrentCell(npts, pts);
    std::vector<vtkIdType> moved(pts, pts + npts);
    for (auto& id : moved)
    {
      ++id;
    }
    polys->InsertNextCell(npts, moved.data());
  }
  vtkNew<vtkPolyData> withStray;
  withStray->SetPoints(shifted);
  withStray->SetPolys(polys);
  mesher->SetInputData(withStray);
  mesher->SetOutputPointsPrecision(vtkAlgorithm::SINGLE_PRECISION);
  mesher->PassPointDataOff();
  mesher->Update();
  mesh = mesher->GetOutput();
  TRC_CHECK(mesh->GetPoints()->GetDataType() == VTK_FLOAT);
  TRC_CHECK(mesh->GetNumberOfPoints() == total); // the same mesh, without the stray point
  ids = vtkIdTypeArray::SafeDownCast(mesh->GetPointData()->GetArray("vtkOriginalPointIds"));
  TRC_CHECK(ids && ids->GetValue(0) == 1 && ids->GetValue(n - 1) == n);
  double bounds[6];
  mesh->GetBounds(bounds);
  TRC_CHECK(bounds[1] <= 2.0 && bounds[3] <= 2.0 && bounds[5] <= 2.0);
  return EXIT_SUCCESS;
}
