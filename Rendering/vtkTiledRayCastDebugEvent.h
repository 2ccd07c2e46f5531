/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkTiledRayCastDebugEvent.h

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
/**
 * @class   vtkTiledRayCastDebugEvent
 * @brief   a name in GL debuggers (apitrace, RenderDoc) around a phase of the mapper's render
 *
 * Marks "vtkOpenGLTiledRayCastVolumeMapper::<name> begin" on construction and "... end" on
 * destruction, whichever of the mapper's parts draws the phase.
 *
 * Not wrapped, not installed: a private header of the module.
 */

#ifndef vtkTiledRayCastDebugEvent_h
#define vtkTiledRayCastDebugEvent_h

#include "vtkOpenGLRenderUtilities.h" // For MarkDebugEvent

#include <string> // For std::string

class vtkTiledRayCastDebugEvent
{
public:
  explicit vtkTiledRayCastDebugEvent(const char* name)
    : Name(name)
  {
    vtkOpenGLRenderUtilities::MarkDebugEvent(
      std::string("vtkOpenGLTiledRayCastVolumeMapper::") + this->Name + " begin");
  }
  ~vtkTiledRayCastDebugEvent()
  {
    vtkOpenGLRenderUtilities::MarkDebugEvent(
      std::string("vtkOpenGLTiledRayCastVolumeMapper::") + this->Name + " end");
  }
  vtkTiledRayCastDebugEvent(const vtkTiledRayCastDebugEvent&) = delete;
  void operator=(const vtkTiledRayCastDebugEvent&) = delete;

private:
  const char* Name;
};

#endif
// VTK-HeaderTest-Exclude: vtkTiledRayCastDebugEvent.h
