/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkTiledRayCastDeferredDraw.cxx

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "vtkTiledRayCastDeferredDraw.h"

#include "vtkCallbackCommand.h"
#include "vtkNew.h"
#include "vtkRenderer.h"
#include "vtkUnstructuredGridVolumeMapper.h"
#include "vtkVolume.h"

//------------------------------------------------------------------------------
vtkTiledRayCastDeferredDraw::vtkTiledRayCastDeferredDraw(vtkUnstructuredGridVolumeMapper* mapper)
  : Mapper(mapper)
{
}

//------------------------------------------------------------------------------
vtkTiledRayCastDeferredDraw::~vtkTiledRayCastDeferredDraw() = default;

//------------------------------------------------------------------------------
bool vtkTiledRayCastDeferredDraw::Defer(vtkRenderer* renderer, vtkVolume* volume)
{
  if (this->Drawing)
  {
    return false;
  }
  if (renderer != this->Renderer)
  {
    this->Stop();
    vtkNew<vtkCallbackCommand> callback;
    callback->SetCallback(&vtkTiledRayCastDeferredDraw::Draw);
    callback->SetClientData(this);
    this->Observer = renderer->AddObserver(vtkCommand::EndEvent, callback);
    this->Renderer = renderer;
  }
  this->Volume = volume;
  this->Pending = true;
  return true;
}

//------------------------------------------------------------------------------
void vtkTiledRayCastDeferredDraw::Draw(vtkObject* renderer, unsigned long, void* deferred, void*)
{
  auto* self = static_cast<vtkTiledRayCastDeferredDraw*>(deferred);
  vtkVolume* volume = self->Volume;
  if (!self->Pending || !volume)
  {
    return;
  }
  self->Pending = false;
  self->Drawing = true;
  self->Mapper->Render(static_cast<vtkRenderer*>(renderer), volume);
  self->Drawing = false;
}

//------------------------------------------------------------------------------
void vtkTiledRayCastDeferredDraw::Stop()
{
  if (vtkRenderer* renderer = this->Renderer)
  {
    renderer->RemoveObserver(this->Observer);
  }
  this->Renderer = nullptr;
  this->Volume = nullptr;
  this->Pending = false;
}
