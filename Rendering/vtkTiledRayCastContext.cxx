/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkTiledRayCastContext.cxx

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "vtkTiledRayCastContext.h"

#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkTiledRayCastComputeShader.h"
#include "vtk_glew.h"

#include <sstream>
#include <string>

//------------------------------------------------------------------------------
// The programs need explicit output locations (several render targets, written by name): GLSL
// 3.30, or 1.50 with GL_ARB_explicit_attrib_location. They bring their version line themselves
// rather than VTK's //VTK::System::Dec, because VTK 9.1's vtkOpenGLShaderCache replaces that tag
// with "#version 150" whatever the context (no explicit locations), and the compute pipeline
// compiles the same fragment shaders as GLSL 4.30 (storage buffers and image atomics); for the
// same reason they declare their outputs themselves, not by //VTK::Output::Dec, which only
// declares what gl_FragData[n] writes.
const char* vtkTiledRayCastContext::FragmentPipelineVersion(vtkOpenGLRenderWindow* window)
{
  int major = 0, minor = 0;
  window->GetOpenGLVersion(major, minor);
  if (major > 3 || (major == 3 && minor >= 3))
  {
    return "#version 330 core\n";
  }
  if (major == 3 && minor == 2 && GLEW_ARB_explicit_attrib_location)
  {
    return "#version 150\n"
           "#extension GL_ARB_explicit_attrib_location : require\n";
  }
  return nullptr;
}

//------------------------------------------------------------------------------
bool vtkTiledRayCastContext::Check(vtkOpenGLRenderWindow* window)
{
  if (window == this->Window)
  {
    return this->Usable;
  }
  this->Window = window;
  this->Usable = false;
  const char* version = vtkTiledRayCastContext::FragmentPipelineVersion(window);
  if (!version)
  {
    int major = 0, minor = 0;
    window->GetOpenGLVersion(major, minor);
    std::ostringstream msg;
    msg << "The OpenGL context (version " << major << "." << minor
        << ") lacks what tiled ray casting needs: OpenGL 3.3, or 3.2 with "
           "GL_ARB_explicit_attrib_location. Nothing is drawn.";
    this->Error = msg.str();
    return false;
  }
  this->VersionHeader = version;
  window->GetState()->vtkglGetIntegerv(GL_MAX_TEXTURE_SIZE, &this->MaxTextureSize);
  window->GetState()->vtkglGetIntegerv(GL_MAX_TEXTURE_BUFFER_SIZE, &this->MaxTextureBufferSize);
  window->GetState()->vtkglGetIntegerv(GL_MAX_3D_TEXTURE_SIZE, &this->Max3DTextureSize);
  this->ComputeSupported = vtkTiledRayCastComputeShader::IsSupported(window);
  this->MaxComputeTextureUnits = 0;
  if (this->ComputeSupported)
  {
    window->GetState()->vtkglGetIntegerv(
      GL_MAX_COMPUTE_TEXTURE_IMAGE_UNITS, &this->MaxComputeTextureUnits);
  }
  const std::string renderer = window->GetState()->GetRenderer();
  this->SoftwareRasterizer = renderer.find("llvmpipe") != std::string::npos ||
    renderer.find("softpipe") != std::string::npos ||
    renderer.find("SwiftShader") != std::string::npos;
  this->Usable = true;
  return true;
}
