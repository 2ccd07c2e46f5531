/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkTiledRayCastOpaqueDepth.cxx

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "vtkTiledRayCastOpaqueDepth.h"

#include "vtkActor2D.h"
#include "vtkObject.h" // For vtkOpenGLError.h, where OpenGL errors are reported
#include "vtkOpenGLError.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkProp.h"
#include "vtkPropCollection.h"
#include "vtkProperty2D.h"
#include "vtkRenderer.h"
#include "vtkTextureObject.h"
#include "vtk_glew.h"

#include <algorithm>
#include <sstream>

//------------------------------------------------------------------------------
vtkTiledRayCastOpaqueDepth::vtkTiledRayCastOpaqueDepth() = default;

//------------------------------------------------------------------------------
vtkTiledRayCastOpaqueDepth::~vtkTiledRayCastOpaqueDepth() = default;

//------------------------------------------------------------------------------
vtkTextureObject* vtkTiledRayCastOpaqueDepth::GetTexture()
{
  return this->Texture;
}

//------------------------------------------------------------------------------
unsigned int vtkTiledRayCastOpaqueDepth::ReadFormat()
{
  GLint readFramebuffer = 0;
  glGetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &readFramebuffer);
  const GLenum attachment = readFramebuffer ? GL_DEPTH_ATTACHMENT : GL_DEPTH;
  GLint depthBits = 0, stencilBits = 0, componentType = GL_UNSIGNED_NORMALIZED;
  glGetFramebufferAttachmentParameteriv(
    GL_READ_FRAMEBUFFER, attachment, GL_FRAMEBUFFER_ATTACHMENT_DEPTH_SIZE, &depthBits);
  if (depthBits > 0)
  {
    glGetFramebufferAttachmentParameteriv(
      GL_READ_FRAMEBUFFER, attachment, GL_FRAMEBUFFER_ATTACHMENT_COMPONENT_TYPE, &componentType);
    glGetFramebufferAttachmentParameteriv(GL_READ_FRAMEBUFFER,
      readFramebuffer ? GL_DEPTH_ATTACHMENT : GL_STENCIL, GL_FRAMEBUFFER_ATTACHMENT_STENCIL_SIZE,
      &stencilBits);
  }
  unsigned int format = 0;
  if (depthBits == 0)
  {
    format = GL_NONE; // no depth buffer: nothing opaque stops the rays
  }
  else if (stencilBits > 0)
  {
    format = componentType == GL_FLOAT ? GL_DEPTH32F_STENCIL8 : GL_DEPTH24_STENCIL8;
  }
  else if (componentType == GL_FLOAT)
  {
    format = GL_DEPTH_COMPONENT32F;
  }
  else
  {
    format = depthBits >= 32 ? GL_DEPTH_COMPONENT32
                             : (depthBits >= 24 ? GL_DEPTH_COMPONENT24 : GL_DEPTH_COMPONENT16);
  }
  return format;
}

//------------------------------------------------------------------------------
bool vtkTiledRayCastOpaqueDepth::Allocate(
  vtkOpenGLRenderWindow* window, unsigned int format, int width, int height, std::string& error)
{
  vtkOpenGLState* state = window->GetState();
  vtkTextureObject* depth = this->Texture;
  // Grows only, like the targets.
  const bool resized = depth->GetWidth() < static_cast<unsigned int>(width) ||
    depth->GetHeight() < static_cast<unsigned int>(height);
  if (format != this->Format || resized || !depth->GetHandle())
  {
    const int allocatedWidth = std::max<int>(width, depth->GetHandle() ? depth->GetWidth() : 0);
    const int allocatedHeight = std::max<int>(height, depth->GetHandle() ? depth->GetHeight() : 0);
    // A framebuffer object skips re-adding the texture object it already holds, though the
    // texture behind it is new: start it afresh.
    this->Framebuffer->ReleaseGraphicsResources(window);
    depth->ReleaseGraphicsResources(window);
    depth->SetContext(window);
    depth->SetMinificationFilter(vtkTextureObject::Nearest);
    depth->SetMagnificationFilter(vtkTextureObject::Nearest);
    depth->SetWrapS(vtkTextureObject::ClampToEdge);
    depth->SetWrapT(vtkTextureObject::ClampToEdge);
    bool ok = true;
    if (format == GL_DEPTH24_STENCIL8)
    {
      ok = depth->AllocateDepthStencil(allocatedWidth, allocatedHeight);
    }
    else
    {
      const bool stencil = format == GL_DEPTH32F_STENCIL8;
      depth->SetInternalFormat(format == GL_NONE ? GL_DEPTH_COMPONENT32F : format);
      depth->SetFormat(stencil ? GL_DEPTH_STENCIL : GL_DEPTH_COMPONENT);
      depth->SetDataType(stencil
          ? GL_FLOAT_32_UNSIGNED_INT_24_8_REV
          : (format == GL_DEPTH_COMPONENT32F || format == GL_NONE ? GL_FLOAT : GL_UNSIGNED_INT));
      ok = depth->Allocate2D(allocatedWidth, allocatedHeight, 1, VTK_FLOAT);
    }
    if (!ok)
    {
      error = "Cannot allocate a texture for the scene's depth. Nothing is drawn.";
      return false;
    }
    state->PushFramebufferBindings();
    this->Framebuffer->SetContext(window);
    this->Framebuffer->Bind();
    this->Framebuffer->AddDepthAttachment(depth);
    state->vtkglDrawBuffer(GL_NONE);
    state->vtkglReadBuffer(GL_NONE);
    state->PopFramebufferBindings();
    this->Format = format;
    this->HoldsFar = false;
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkTiledRayCastOpaqueDepth::SceneMayHaveDepth(vtkRenderer* renderer)
{
  if (renderer->GetPreserveDepthBuffer() || !renderer->GetErase())
  {
    return true; // the depth of the renderers drawn before it
  }
  vtkPropCollection* props = renderer->GetViewProps();
  vtkCollectionSimpleIterator it;
  props->InitTraversal(it);
  while (vtkProp* prop = props->GetNextProp(it))
  {
    if (!prop->GetVisibility() || prop->IsA("vtkVolume"))
    {
      continue; // volumes write no depth (they draw after opaque and translucent geometry)
    }
    vtkActor2D* actor2D = vtkActor2D::SafeDownCast(prop);
    if (actor2D && actor2D->GetProperty()->GetDisplayLocation() == VTK_FOREGROUND_LOCATION)
    {
      continue; // drawn in the overlay, after the volumes
    }
    return true;
  }
  return false;
}

//------------------------------------------------------------------------------
bool vtkTiledRayCastOpaqueDepth::SetFar(
  vtkOpenGLRenderWindow* window, const int imageSize[2], std::string& error)
{
  // The format of a texture that already exists is kept: reallocating to another would only
  // cost a copy when opaque geometry comes back.
  const unsigned int format = this->Texture->GetHandle() ? this->Format : GL_NONE;
  if (!this->Allocate(window, format, imageSize[0], imageSize[1], error))
  {
    return false;
  }
  if (!this->HoldsFar)
  {
    vtkOpenGLState* state = window->GetState();
    state->PushDrawFramebufferBinding();
    this->Framebuffer->Bind(GL_DRAW_FRAMEBUFFER);
    vtkOpenGLState::ScopedglDepthMask depthMask(state);
    state->vtkglDepthMask(GL_TRUE);
    state->vtkglClearDepth(1.0);
    state->vtkglClear(GL_DEPTH_BUFFER_BIT);
    state->PopDrawFramebufferBinding();
    this->HoldsFar = true;
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkTiledRayCastOpaqueDepth::Capture(vtkOpenGLRenderWindow* window, const int origin[2],
  int width, int height, const int imageSize[2], std::string& error)
{
  // Blit the depth of the caller's framebuffer (possibly multisampled) into a texture of ours,
  // as VTK's GPU ray-cast mapper does. A depth blit needs the same format on both sides, so the
  // texture takes the format of the framebuffer's depth attachment, whatever the window or the
  // render pass made it.
  vtkOpenGLState* state = window->GetState();
  const unsigned int format = vtkTiledRayCastOpaqueDepth::ReadFormat();
  if (format == GL_NONE)
  {
    return this->SetFar(window, imageSize, error); // no depth buffer: nothing stops the rays
  }
  if (!this->Allocate(window, format, width, height, error))
  {
    return false;
  }

  // Errors left by earlier GL calls are not this blit's (vtkOpenGLClearErrorMacro is compiled
  // out of release builds of VTK).
  for (int i = 0; i < 16 && glGetError() != GL_NO_ERROR; ++i)
  {
  }
  state->PushDrawFramebufferBinding();
  this->Framebuffer->Bind(GL_DRAW_FRAMEBUFFER);
  this->HoldsFar = false;
  // One depth per ray: at an image sample distance above 1 the nearest of the pixels around the
  // ray (a depth blit may scale, never filter).
  state->vtkglBlitFramebuffer(origin[0], origin[1], origin[0] + width, origin[1] + height, 0, 0,
    imageSize[0], imageSize[1], GL_DEPTH_BUFFER_BIT, GL_NEAREST);
  state->PopDrawFramebufferBinding();
  const GLenum glError = glGetError();
  if (glError != GL_NO_ERROR)
  {
    std::ostringstream msg;
    msg << "Cannot read the depth of the scene's framebuffer (" << vtkOpenGLStrError(glError)
        << ", depth format 0x" << std::hex << format << "). Nothing is drawn.";
    error = msg.str();
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkTiledRayCastOpaqueDepth::ReleaseGraphicsResources(vtkWindow* window)
{
  this->HoldsFar = false;
  this->Framebuffer->ReleaseGraphicsResources(window);
  this->Texture->ReleaseGraphicsResources(window);
}
