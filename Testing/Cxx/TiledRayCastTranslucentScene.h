/*=========================================================================

  Program:   TiledRayCast
  Module:    TiledRayCastTranslucentScene.h

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// The translucent geometry that TestTiledRayCastTranslucent checks against the exact reference
// and BenchmarkTranslucentGeometry times: a translucent sphere around part of a mesh and a
// translucent plane through it, flat coloured (ambient light only, so that each fragment is
// exactly its colour and opacity whatever the lights, as the reference's layers say), with VTK's
// dual depth peeling turned on for them and for volumes. Plain VTK, no test driver.
#ifndef TiledRayCastTranslucentScene_h
#define TiledRayCastTranslucentScene_h

#include "vtkActor.h"
#include "vtkDataSet.h"
#include "vtkNew.h"
#include "vtkPlaneSource.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"
#include "vtkSphereSource.h"

namespace trcscene
{
struct TranslucentGeometry
{
  vtkNew<vtkSphereSource> SphereSource;
  vtkNew<vtkPlaneSource> PlaneSource;
  vtkSmartPointer<vtkActor> Sphere;
  vtkSmartPointer<vtkActor> Plane;
  double Opacity[2] = { 0.45, 0.3 }; // the sphere's and the plane's

  // The sphere (radius 0.3 of the mesh's diagonal, off its centre) and the plane (tilted
  // through the middle, larger than the mesh) of `mesh`, added to `renderer`, whose depth
  // peeling is turned on for translucent geometry and volumes, up to `peels` peels.
  TranslucentGeometry(vtkDataSet* mesh, vtkRenderer* renderer, int peels = 8)
  {
    double c[3];
    mesh->GetCenter(c);
    const double length = mesh->GetLength();
    this->SphereSource->SetCenter(c[0] + 0.15 * length, c[1] + 0.05 * length, c[2] - 0.05 * length);
    this->SphereSource->SetRadius(0.3 * length);
    this->SphereSource->SetThetaResolution(48);
    this->SphereSource->SetPhiResolution(32);
    this->PlaneSource->SetOrigin(c[0] - length, c[1] - 0.6 * length, c[2] - length);
    this->PlaneSource->SetPoint1(c[0] + length, c[1] - 0.6 * length, c[2] - length);
    this->PlaneSource->SetPoint2(c[0] - length, c[1] + 0.6 * length, c[2] + length);
    const double sphereColor[3] = { 0.2, 0.6, 1.0 };
    const double planeColor[3] = { 1.0, 0.85, 0.3 };
    this->Sphere = FlatActor(this->SphereSource, sphereColor, this->Opacity[0]);
    this->Plane = FlatActor(this->PlaneSource, planeColor, this->Opacity[1]);
    renderer->AddActor(this->Sphere);
    renderer->AddActor(this->Plane);
    renderer->SetUseDepthPeeling(1);
    renderer->SetUseDepthPeelingForVolumes(1);
    renderer->SetMaximumNumberOfPeels(peels);
    renderer->SetOcclusionRatio(0.0);
  }

  void Show(bool sphere, bool plane)
  {
    this->Sphere->SetVisibility(sphere);
    this->Plane->SetVisibility(plane);
  }

  static vtkSmartPointer<vtkActor> FlatActor(
    vtkPolyDataAlgorithm* source, const double color[3], double opacity)
  {
    vtkNew<vtkPolyDataMapper> mapper;
    mapper->SetInputConnection(source->GetOutputPort());
    auto actor = vtkSmartPointer<vtkActor>::New();
    actor->SetMapper(mapper);
    vtkProperty* property = actor->GetProperty();
    property->SetAmbient(1.0);
    property->SetDiffuse(0.0);
    property->SetSpecular(0.0);
    property->SetAmbientColor(color[0], color[1], color[2]);
    property->SetColor(color[0], color[1], color[2]);
    property->SetOpacity(opacity);
    return actor;
  }
};
}

#endif
