/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkTiledRayCastComputeShader.cxx

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "vtkTiledRayCastComputeShader.h"

#include "vtkObjectFactory.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkTextureObject.h"
#include "vtk_glew.h"

#include <vector>

vtkStandardNewMacro(vtkTiledRayCastComputeShader);

//------------------------------------------------------------------------------
vtkTiledRayCastComputeShader::vtkTiledRayCastComputeShader() = default;

//------------------------------------------------------------------------------
vtkTiledRayCastComputeShader::~vtkTiledRayCastComputeShader() = default;

//------------------------------------------------------------------------------
bool vtkTiledRayCastComputeShader::IsSupported(vtkOpenGLRenderWindow* window)
{
  int major = 0, minor = 0;
  window->GetOpenGLVersion(major, minor);
  return major > 4 || (major == 4 && minor >= 3);
}

//------------------------------------------------------------------------------
bool vtkTiledRayCastComputeShader::Build(const std::string& source)
{
  this->ReleaseProgram();
  this->Source = source;
  auto log = [](GLuint object, bool program)
  {
    GLint length = 0;
    program ? glGetProgramiv(object, GL_INFO_LOG_LENGTH, &length)
            : glGetShaderiv(object, GL_INFO_LOG_LENGTH, &length);
    std::vector<char> text(static_cast<size_t>(length) + 1, '\0');
    program ? glGetProgramInfoLog(object, length, nullptr, text.data())
            : glGetShaderInfoLog(object, length, nullptr, text.data());
    return std::string(text.data());
  };

  const GLuint shader = glCreateShader(GL_COMPUTE_SHADER);
  const char* text = source.c_str();
  glShaderSource(shader, 1, &text, nullptr);
  glCompileShader(shader);
  GLint ok = GL_FALSE;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (!ok)
  {
    this->Error = "compute shader compilation failed:\n" + log(shader, false);
    glDeleteShader(shader);
    return false;
  }
  const GLuint program = glCreateProgram();
  glAttachShader(program, shader);
  glLinkProgram(program);
  glDetachShader(program, shader);
  glDeleteShader(shader);
  glGetProgramiv(program, GL_LINK_STATUS, &ok);
  if (!ok)
  {
    this->Error = "compute program link failed:\n" + log(program, true);
    glDeleteProgram(program);
    return false;
  }
  this->Handle = static_cast<int>(program);
  this->Linked = true;
  this->Compiled = true;
  this->Error.clear();
  return true;
}

//------------------------------------------------------------------------------
void vtkTiledRayCastComputeShader::Use(vtkOpenGLRenderWindow* window)
{
  window->GetShaderCache()->ReleaseCurrentShader();
  glUseProgram(static_cast<GLuint>(this->Handle));
  this->Bound = true;
}

//------------------------------------------------------------------------------
void vtkTiledRayCastComputeShader::Dispatch(unsigned int groupsX, unsigned int groupsY)
{
  if (groupsX > 0 && groupsY > 0)
  {
    glDispatchCompute(groupsX, groupsY, 1);
  }
}

//------------------------------------------------------------------------------
bool vtkTiledRayCastComputeShader::SetDepthClamp(bool on)
{
  const bool was = glIsEnabled(GL_DEPTH_CLAMP) == GL_TRUE;
  if (on != was)
  {
    on ? glEnable(GL_DEPTH_CLAMP) : glDisable(GL_DEPTH_CLAMP);
  }
  return was;
}

//------------------------------------------------------------------------------
void vtkTiledRayCastComputeShader::ReleaseProgram()
{
  if (this->Handle)
  {
    if (this->Bound)
    {
      glUseProgram(0);
    }
    glDeleteProgram(static_cast<GLuint>(this->Handle));
  }
  this->Handle = 0;
  this->Linked = false;
  this->Compiled = false;
  this->Bound = false;
  this->Source.clear();
  // Uniform locations belong to the deleted program.
  this->ClearMaps();
}

//------------------------------------------------------------------------------
void vtkTiledRayCastComputeShader::BindImage(
  unsigned int unit, vtkTextureObject* texture, unsigned int access, unsigned int format)
{
  glBindImageTexture(unit, texture->GetHandle(), 0, GL_FALSE, 0, access, format);
}

//------------------------------------------------------------------------------
void vtkTiledRayCastComputeShader::UnbindImage(unsigned int unit)
{
  glBindImageTexture(unit, 0, 0, GL_FALSE, 0, GL_READ_ONLY, GL_R32UI);
}

//------------------------------------------------------------------------------
void vtkTiledRayCastComputeShader::Barrier(unsigned int bits)
{
  glMemoryBarrier(bits);
}

//------------------------------------------------------------------------------
bool vtkTiledRayCastComputeShader::CanClearImages()
{
  return GLEW_VERSION_4_4 || GLEW_ARB_clear_texture;
}

//------------------------------------------------------------------------------
void vtkTiledRayCastComputeShader::ClearImage(vtkTextureObject* texture)
{
  glClearTexImage(texture->GetHandle(), 0, GL_RED_INTEGER, GL_UNSIGNED_INT, nullptr);
}
