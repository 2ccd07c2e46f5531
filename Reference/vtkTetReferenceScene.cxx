/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkTetReferenceScene.cxx

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "vtkTetReferenceScene.h"

#include "vtkCallbackCommand.h"
#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkDataSet.h"
#include "vtkFloatArray.h"
#include "vtkNew.h"
#include "vtkSMPThreadLocal.h"
#include "vtkSMPTools.h"
#include "vtkTetRayIntegrator.h"
#include "vtkTetReferencePixelRays.h"
#include "vtkTetReferenceVolume.h"
#include "vtkTetScalarSelection.h"
#include "vtkTimerLog.h"
#include "vtkVolumeProperty.h"

#include <cmath>

//------------------------------------------------------------------------------
vtkTetReferenceScene::vtkTetReferenceScene()
  : ErrorForwarder(vtkSmartPointer<vtkCallbackCommand>::New())
{
  this->ErrorForwarder->SetClientData(&this->IntegratorError);
  this->ErrorForwarder->SetCallback(
    [](vtkObject*, unsigned long, void* clientData, void* callData)
    {
      // VTK's message reads "ERROR: In <file>, line <n>\n<class> (<address>): <text>\n": keep
      // the text.
      std::string text = callData ? static_cast<const char*>(callData) : "";
      const size_t begin = text.find("): ");
      text = begin == std::string::npos ? text : text.substr(begin + 3);
      *static_cast<std::string*>(clientData) = text.substr(0, text.find_last_not_of("\n") + 1);
    });
}

//------------------------------------------------------------------------------
vtkTetReferenceScene::~vtkTetReferenceScene() = default;

//------------------------------------------------------------------------------
vtkTetReferenceScene::Source vtkTetReferenceScene::MakeSource(vtkTetReferenceVolume* volume)
{
  Source source;
  source.Input = volume->GetInput();
  source.Property = volume->GetPropertyInForce();
  volume->GetMatrixInForce(source.Matrix);
  source.Selection = volume->GetScalarSelection();
  return source;
}

//------------------------------------------------------------------------------
bool vtkTetReferenceScene::PrepareMesh(const Source& source, vtkTetReferenceMesh& mesh,
  bool& rebuilt, vtkIdType& degenerate, std::string& error)
{
  rebuilt = false;
  // The one scalar the property takes from the selected array (the mapper's rule), resolved on
  // a copy: the mesh is prepared, and kept, for what it reads, the property's choice included.
  vtkNew<vtkTetScalarSelection> selection;
  selection->CopySettings(source.Selection);
  int cellFlag = -1;
  vtkDataArray* array = selection->GetScalars(source.Input, cellFlag);
  if (array &&
    !selection->Resolve(array->GetNumberOfComponents(), array->GetName(), source.Property))
  {
    error = std::string("Not rendered: ") + selection->GetErrorMessage() + ".";
    return false;
  }
  selection->SetVectorModeToResolved();
  if (mesh.IsPreparedFrom(source.Input, selection, source.Matrix))
  {
    return true;
  }
  rebuilt = true;
  degenerate = 0;
  return mesh.Prepare(source.Input, selection, source.Matrix, degenerate, error);
}

//------------------------------------------------------------------------------
bool vtkTetReferenceScene::InitializeIntegrator(vtkTetRayIntegrator* integrator,
  vtkVolumeProperty* property, vtkVolumeProperty*& cached, vtkMTimeType& mtime)
{
  if (cached != property || mtime != property->GetMTime() || !integrator->IsInitialized())
  {
    if (!integrator->Initialize(property))
    {
      cached = nullptr;
      return false;
    }
    cached = property;
    mtime = property->GetMTime();
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkTetReferenceScene::Prepare(const std::vector<Source>& sources, int first,
  vtkIdType tetrahedra[3], double& preparationTime, std::string& error)
{
  while (this->Volumes.size() < sources.size())
  {
    this->Volumes.emplace_back(new Prepared);
    this->Volumes.back()->Integrator = vtkSmartPointer<vtkTetRayIntegrator>::New();
    this->Volumes.back()->Integrator->AddObserver(vtkCommand::ErrorEvent, this->ErrorForwarder);
  }
  this->Volumes.resize(sources.size());
  for (size_t v = 0; v < sources.size(); ++v)
  {
    const Source& source = sources[v];
    Prepared& prepared = *this->Volumes[v];
    const std::string name = "Volume " + std::to_string(first + static_cast<int>(v)) + ": ";
    if (!source.Input)
    {
      error = name + "no input.";
      return false;
    }
    if (source.Input->GetNumberOfPoints() == 0 || source.Input->GetNumberOfCells() == 0)
    {
      error = name + "the input is empty.";
      return false;
    }
    if (!source.Property)
    {
      error = name + "no volume property.";
      return false;
    }
    vtkNew<vtkTimerLog> timer;
    timer->StartTimer();
    bool rebuilt = false;
    vtkIdType degenerate = 0;
    if (!PrepareMesh(source, prepared.Mesh, rebuilt, degenerate, error))
    {
      error = name + error;
      prepared.Mesh = vtkTetReferenceMesh();
      return false;
    }
    timer->StopTimer();
    preparationTime += rebuilt ? timer->GetElapsedTime() : 0.0;
    this->IntegratorError.clear();
    if (!InitializeIntegrator(
          prepared.Integrator, source.Property, prepared.Property, prepared.PropertyMTime))
    {
      error = name + "the volume property cannot be integrated (" + this->IntegratorError + ").";
      return false;
    }
    tetrahedra[0] += static_cast<vtkIdType>(prepared.Mesh.Transparent.size());
    tetrahedra[1] += rebuilt ? degenerate : 0;
    tetrahedra[2] += static_cast<vtkIdType>(prepared.Mesh.NumberOfOverlapping);
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkTetReferenceScene::Clear()
{
  this->Volumes.clear();
}

//------------------------------------------------------------------------------
void vtkTetReferenceScene::AppendMedia(std::vector<vtkTetReferenceIntermixing::Medium>& media) const
{
  for (const std::unique_ptr<Prepared>& v : this->Volumes)
  {
    media.push_back({ &v->Mesh, v->Integrator });
  }
}

//------------------------------------------------------------------------------
bool vtkTetReferenceScene::CheckLayer(
  vtkDataArray* rgba, vtkFloatArray* depth, vtkIdType pixels, std::string& error)
{
  if (!rgba || !depth)
  {
    error = "it needs both RGBA and depth arrays.";
    return false;
  }
  if (rgba->GetNumberOfComponents() != 4 || rgba->GetNumberOfTuples() != pixels)
  {
    error = "the RGBA array has " + std::to_string(rgba->GetNumberOfTuples()) + " tuples of " +
      std::to_string(rgba->GetNumberOfComponents()) + " components; the image has " +
      std::to_string(pixels) + " pixels (4 components each).";
    return false;
  }
  if (depth->GetNumberOfValues() != pixels)
  {
    error = "the depth array has " + std::to_string(depth->GetNumberOfValues()) +
      " values; the image has " + std::to_string(pixels) + " pixels.";
    return false;
  }
  for (vtkIdType p = 0; p < pixels; ++p)
  {
    const float z = depth->GetValue(p);
    const double a = rgba->GetComponent(p, 3);
    const bool finite = std::isfinite(rgba->GetComponent(p, 0)) &&
      std::isfinite(rgba->GetComponent(p, 1)) && std::isfinite(rgba->GetComponent(p, 2));
    if (!(z >= 0.0f && z <= 1.0f) || !(a >= 0.0 && a <= 1.0) || !finite)
    {
      error = "pixel " + std::to_string(p) + " has depth " + std::to_string(z) + " and RGBA (" +
        std::to_string(rgba->GetComponent(p, 0)) + ", " + std::to_string(rgba->GetComponent(p, 1)) +
        ", " + std::to_string(rgba->GetComponent(p, 2)) + ", " + std::to_string(a) +
        "): depths must lie in [0, 1], alpha in [0, 1], colours be finite.";
      return false;
    }
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkTetReferenceScene::CastRays(const vtkTetReferenceIntermixing& scene,
  const vtkTetReferencePixelRays& rays, float* rgbaFloat, double* rgbaDouble, int* counts)
{
  vtkSMPThreadLocal<vtkTetReferenceIntermixing::Scratch> scratch;
  const int width = rays.Width;
  vtkSMPTools::For(0, rays.Height, 1,
    [&](vtkIdType rowBegin, vtkIdType rowEnd)
    {
      vtkTetReferenceIntermixing::Scratch& local = scratch.Local();
      for (vtkIdType j = rowBegin; j < rowEnd; ++j)
      {
        for (int i = 0; i < width; ++i)
        {
          const vtkIdType pixel = j * width + i;
          double result[4];
          scene.CastRay(rays, i, static_cast<int>(j), local, result, counts[pixel]);
          for (int k = 0; k < 4; ++k)
          {
            if (rgbaFloat)
            {
              rgbaFloat[4 * pixel + k] = static_cast<float>(result[k]);
            }
            else
            {
              rgbaDouble[4 * pixel + k] = result[k];
            }
          }
        }
      }
    });
}
