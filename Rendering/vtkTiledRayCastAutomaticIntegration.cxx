/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkTiledRayCastAutomaticIntegration.cxx

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "vtkTiledRayCastAutomaticIntegration.h"

#include "vtkNew.h"
#include "vtkTiledRayCastIntegrationChoice.h"
#include "vtkTiledRayCastPreIntegrationTable.h"
#include "vtkTiledRayCastTransferFunction.h"
#include "vtkVolumeProperty.h"

#include <atomic>
#include <chrono>

//------------------------------------------------------------------------------
// One choice: its own copies of what it reads, so that the caller's objects can change (or go)
// while it runs.
struct vtkTiledRayCastAutomaticIntegration::Job
{
  vtkTiledRayCastIntegrationChoice Predictor; // the segments, sampled by Start()
  vtkNew<vtkVolumeProperty> Property;
  Settings Inputs;
  Choice Result;
  std::atomic<bool> Abandoned{ false };

  void Run()
  {
    vtkNew<vtkTiledRayCastTransferFunction> transferFunction;
    transferFunction->Update(this->Property, this->Inputs.ScalarRange);
    if (!this->Predictor.SetProperty(this->Property))
    {
      return; // partial pre-integration; the mapper reports what cannot be integrated
    }
    // Cheapest first (measured on the H200: the 2D table, the 3D table, partial
    // pre-integration); a table is taken if its predicted error is within the budget.
    for (int mode : { vtkTiledRayCastVolumeMapper::PRE_INTEGRATION_2D,
           vtkTiledRayCastVolumeMapper::PRE_INTEGRATION_3D })
    {
      if (this->Abandoned)
      {
        return;
      }
      vtkSmartPointer<vtkTiledRayCastPreIntegrationTable> table =
        vtkSmartPointer<vtkTiledRayCastPreIntegrationTable>::New();
      vtkTiledRayCastAutomaticIntegration::Configure(table, this->Inputs, mode);
      if (!table->Update(this->Property, transferFunction, this->Inputs.ScalarRange))
      {
        return;
      }
      const double error = this->Predictor.PredictError(table);
      this->Result.TablesTried.push_back({ mode, error, this->Predictor.GetWorstSegmentError() });
      if (error <= this->Inputs.MaximumError)
      {
        this->Result.Mode = mode;
        this->Result.PredictedError = error;
        this->Result.Table = table;
        return;
      }
    }
  }
};

//------------------------------------------------------------------------------
vtkTiledRayCastAutomaticIntegration::vtkTiledRayCastAutomaticIntegration() = default;

//------------------------------------------------------------------------------
void vtkTiledRayCastAutomaticIntegration::Configure(
  vtkTiledRayCastPreIntegrationTable* table, const Settings& settings, int mode)
{
  const bool is3D = mode == vtkTiledRayCastVolumeMapper::PRE_INTEGRATION_3D;
  table->SetDimension(is3D ? 3 : 2);
  table->SetRequestedScalarSize(settings.RequestedScalarSize);
  table->SetRequestedLengthSize(settings.RequestedLengthSize);
  table->SetMaximumSize(is3D ? settings.Max3DTextureSize : settings.MaxTextureSize);
  table->SetMaximumLength(settings.MaximumLength);
  table->SetReferenceLength(settings.ReferenceLength);
}

//------------------------------------------------------------------------------
vtkTiledRayCastAutomaticIntegration::~vtkTiledRayCastAutomaticIntegration()
{
  if (this->Current)
  {
    this->Current->Abandoned = true;
    this->CurrentDone.wait();
  }
  this->ReapAbandoned(true);
}

//------------------------------------------------------------------------------
void vtkTiledRayCastAutomaticIntegration::ReapAbandoned(bool wait)
{
  for (auto it = this->Abandoned.begin(); it != this->Abandoned.end();)
  {
    if (wait || it->second.wait_for(std::chrono::seconds(0)) == std::future_status::ready)
    {
      it->second.wait();
      it = this->Abandoned.erase(it);
    }
    else
    {
      ++it;
    }
  }
}

//------------------------------------------------------------------------------
void vtkTiledRayCastAutomaticIntegration::Start(vtkTetMesh* mesh, vtkDataArray* movedPoints,
  double objectToWorldNorm, vtkVolumeProperty* property, const Settings& settings)
{
  this->Abandon();
  auto job = std::make_shared<Job>();
  job->Predictor.SampleSegments(mesh, movedPoints, objectToWorldNorm);
  job->Property->DeepCopy(property); // its functions too
  job->Inputs = settings;
  this->Current = job;
  this->CurrentDone = std::async(std::launch::async, [job]() { job->Run(); });
}

//------------------------------------------------------------------------------
void vtkTiledRayCastAutomaticIntegration::Abandon()
{
  if (this->Current)
  {
    this->Current->Abandoned = true;
    this->Abandoned.emplace_back(std::move(this->Current), std::move(this->CurrentDone));
  }
  this->ReapAbandoned(false);
}

//------------------------------------------------------------------------------
bool vtkTiledRayCastAutomaticIntegration::Take(Choice& choice, bool wait)
{
  this->ReapAbandoned(false);
  if (!this->Current)
  {
    return false;
  }
  if (!wait && this->CurrentDone.wait_for(std::chrono::seconds(0)) != std::future_status::ready)
  {
    return false;
  }
  this->CurrentDone.wait();
  choice = this->Current->Result;
  this->Current.reset();
  return true;
}
