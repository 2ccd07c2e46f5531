/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkTiledRayCastPhaseTimers.cxx

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "vtkTiledRayCastPhaseTimers.h"

#include "vtkOpenGLRenderTimer.h"
#include "vtkTiledRayCastStatistics.h"
#include "vtk_glew.h"

//------------------------------------------------------------------------------
vtkTiledRayCastPhaseTimers::vtkTiledRayCastPhaseTimers() = default;

//------------------------------------------------------------------------------
vtkTiledRayCastPhaseTimers::~vtkTiledRayCastPhaseTimers() = default;

//------------------------------------------------------------------------------
bool vtkTiledRayCastPhaseTimers::Segments::Ready() const
{
  for (size_t i = 0; i < this->Used; ++i)
  {
    if (!this->Timers[i]->Ready())
    {
      return false;
    }
  }
  return true;
}

//------------------------------------------------------------------------------
double vtkTiledRayCastPhaseTimers::Segments::GetMilliseconds() const
{
  double ms = 0;
  for (size_t i = 0; i < this->Used; ++i)
  {
    ms += this->Timers[i]->GetElapsedMilliseconds();
  }
  return ms;
}

//------------------------------------------------------------------------------
bool vtkTiledRayCastPhaseTimers::BeginFrame()
{
  this->Timing = !this->Pending;
  if (this->Timing)
  {
    for (Segments& s : this->Phases)
    {
      s.Used = 0;
    }
  }
  return this->Timing;
}

//------------------------------------------------------------------------------
void vtkTiledRayCastPhaseTimers::Start(Phase phase)
{
  if (!this->Timing)
  {
    return;
  }
  Segments& s = this->Phases[phase];
  if (s.Used == s.Timers.size())
  {
    s.Timers.emplace_back(new vtkOpenGLRenderTimer);
  }
  s.Timers[s.Used]->Start();
}

//------------------------------------------------------------------------------
void vtkTiledRayCastPhaseTimers::Stop(Phase phase)
{
  if (this->Timing)
  {
    Segments& s = this->Phases[phase];
    s.Timers[s.Used++]->Stop();
  }
}

//------------------------------------------------------------------------------
bool vtkTiledRayCastPhaseTimers::Ready() const
{
  for (const Segments& s : this->Phases)
  {
    if (!s.Ready())
    {
      return false;
    }
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkTiledRayCastPhaseTimers::Read(bool wait, vtkTiledRayCastStatistics* stats)
{
  if (!this->Pending)
  {
    return false;
  }
  if (wait)
  {
    // vtkOpenGLRenderTimer only polls: finish the frame's work, then poll until the results
    // have arrived.
    glFinish();
    while (!this->Ready())
    {
    }
  }
  else if (!this->Ready())
  {
    return false;
  }
  stats->SetFirstHitTime(this->Phases[FirstHit].GetMilliseconds());
  stats->SetPeelingTime(this->Phases[Peeling].GetMilliseconds());
  stats->SetRayCastingTime(this->Phases[RayCasting].GetMilliseconds());
  stats->SetCompositingTime(this->Phases[Compositing].GetMilliseconds());
  stats->SetTotalGPUTime(this->Phases[Total].GetMilliseconds());
  this->Pending = false;
  return true;
}

//------------------------------------------------------------------------------
void vtkTiledRayCastPhaseTimers::ReleaseGraphicsResources()
{
  for (Segments& s : this->Phases)
  {
    for (auto& t : s.Timers)
    {
      t->ReleaseGraphicsResources();
    }
    s.Timers.clear();
    s.Used = 0;
  }
  this->Pending = false;
}
