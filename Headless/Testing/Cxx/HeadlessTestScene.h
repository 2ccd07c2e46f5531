/*=========================================================================

  Program:   TiledRayCast
  Module:    HeadlessTestScene.h

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// The lit polygonal scene that the headless-window tests render. The X window, the EGL window and
// Python (Testing/Python/TestHeadlessPython.py builds the same scene) must all match the one
// baseline, TestHeadlessEGLWindow.png.
#ifndef HeadlessTestScene_h
#define HeadlessTestScene_h

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkConeSource.h"
#include "vtkLight.h"
#include "vtkNew.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSphereSource.h"

#include <iostream>
#include <string>

namespace HeadlessTestScene
{
// Adds a renderer with a shiny sphere, a cone and two lights to `window`, sized 300x300.
inline vtkRenderer* Add(vtkRenderWindow* window)
{
  vtkNew<vtkRenderer> renderer;
  renderer->SetBackground(0.1, 0.2, 0.4);

  vtkNew<vtkSphereSource> sphere;
  sphere->SetCenter(-0.6, 0.0, 0.0);
  sphere->SetRadius(0.5);
  sphere->SetThetaResolution(48);
  sphere->SetPhiResolution(32);
  vtkNew<vtkPolyDataMapper> sphereMapper;
  sphereMapper->SetInputConnection(sphere->GetOutputPort());
  vtkNew<vtkActor> sphereActor;
  sphereActor->SetMapper(sphereMapper);
  sphereActor->GetProperty()->SetColor(0.9, 0.3, 0.2);
  sphereActor->GetProperty()->SetSpecular(0.5);
  sphereActor->GetProperty()->SetSpecularPower(30.0);
  renderer->AddActor(sphereActor);

  vtkNew<vtkConeSource> cone;
  cone->SetCenter(0.7, 0.0, 0.0);
  cone->SetHeight(1.0);
  cone->SetRadius(0.45);
  cone->SetResolution(40);
  cone->SetDirection(0.0, 1.0, 0.0);
  vtkNew<vtkPolyDataMapper> coneMapper;
  coneMapper->SetInputConnection(cone->GetOutputPort());
  vtkNew<vtkActor> coneActor;
  coneActor->SetMapper(coneMapper);
  coneActor->GetProperty()->SetColor(0.3, 0.8, 0.3);
  renderer->AddActor(coneActor);

  vtkNew<vtkLight> headlight;
  headlight->SetLightTypeToHeadlight();
  headlight->SetIntensity(0.7);
  renderer->AddLight(headlight);
  vtkNew<vtkLight> sceneLight;
  sceneLight->SetLightTypeToSceneLight();
  sceneLight->SetPosition(3.0, 3.0, 3.0);
  sceneLight->SetFocalPoint(0.0, 0.0, 0.0);
  sceneLight->SetColor(1.0, 0.9, 0.8);
  sceneLight->SetIntensity(0.6);
  renderer->AddLight(sceneLight);

  renderer->ResetCamera();
  renderer->GetActiveCamera()->Azimuth(20.0);
  renderer->GetActiveCamera()->Elevation(15.0);

  window->AddRenderer(renderer);
  window->SetSize(300, 300);
  // Multisampling is the one thing that could make X and EGL images differ.
  window->SetMultiSamples(0);
  return renderer;
}

// Prints what OpenGL the window got (so that the test log tells which renderer ran).
inline void PrintGL(vtkRenderWindow* window, const char* label)
{
  std::string report = window->ReportCapabilities();
  std::string::size_type extensions = report.find("OpenGL extensions");
  std::cout << label << ":\n" << report.substr(0, extensions) << std::flush;
}
}

#endif
