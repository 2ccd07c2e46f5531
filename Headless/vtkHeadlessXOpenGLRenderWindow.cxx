/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkHeadlessXOpenGLRenderWindow.cxx

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "vtkHeadlessXOpenGLRenderWindow.h"

#include "vtkHeadlessContextSwitch.h"
#include "vtkObjectFactory.h"

vtkStandardNewMacro(vtkHeadlessXOpenGLRenderWindow);

//------------------------------------------------------------------------------
vtkHeadlessXOpenGLRenderWindow::vtkHeadlessXOpenGLRenderWindow() = default;

//------------------------------------------------------------------------------
vtkHeadlessXOpenGLRenderWindow::~vtkHeadlessXOpenGLRenderWindow()
{
  // The base destructor finalizes too, but by then this class's Finalize() is no longer the
  // one called: finalize here, where the EGL context can still be released first.
  this->Finalize();
}

//------------------------------------------------------------------------------
void vtkHeadlessXOpenGLRenderWindow::Initialize()
{
  vtkHeadlessContextSwitch::ReleaseEGL();
  this->Superclass::Initialize();
}

//------------------------------------------------------------------------------
void vtkHeadlessXOpenGLRenderWindow::Finalize()
{
  vtkHeadlessContextSwitch::ReleaseEGL();
  this->Superclass::Finalize();
}

//------------------------------------------------------------------------------
void vtkHeadlessXOpenGLRenderWindow::Start()
{
  vtkHeadlessContextSwitch::ReleaseEGL();
  this->Superclass::Start();
}

//------------------------------------------------------------------------------
void vtkHeadlessXOpenGLRenderWindow::Render()
{
  vtkHeadlessContextSwitch::ReleaseEGL();
  this->Superclass::Render();
}

//------------------------------------------------------------------------------
void vtkHeadlessXOpenGLRenderWindow::MakeCurrent()
{
  if (!this->IsCurrent())
  {
    vtkHeadlessContextSwitch::ReleaseEGL();
  }
  this->Superclass::MakeCurrent();
}

//------------------------------------------------------------------------------
void vtkHeadlessXOpenGLRenderWindow::PushContext()
{
  if (!this->IsCurrent())
  {
    vtkHeadlessContextSwitch::ReleaseEGL();
  }
  this->Superclass::PushContext();
}

//------------------------------------------------------------------------------
void vtkHeadlessXOpenGLRenderWindow::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}
