/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkTiledRayCastMemberUniforms.cxx

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "vtkTiledRayCastMemberUniforms.h"

#include "vtkObjectFactory.h"
#include "vtk_glew.h"

#include <algorithm>
#include <cstring>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkTiledRayCastMemberUniforms);

//------------------------------------------------------------------------------
vtkTiledRayCastMemberUniforms::vtkTiledRayCastMemberUniforms() = default;

//------------------------------------------------------------------------------
vtkTiledRayCastMemberUniforms::~vtkTiledRayCastMemberUniforms()
{
  // The handle is the group program's: never released from here.
  this->Unmap();
}

//------------------------------------------------------------------------------
void vtkTiledRayCastMemberUniforms::Unmap()
{
  this->ClearMaps();
  this->Handle = 0;
  this->Linked = false;
  this->Compiled = false;
}

//------------------------------------------------------------------------------
void vtkTiledRayCastMemberUniforms::Map(vtkShaderProgram* program, const std::string& suffix,
  const std::vector<std::string>& shared, const std::vector<std::string>& plain,
  const std::vector<std::string>& indexed, int index)
{
  this->Unmap();
  if (!program || program->GetHandle() == 0)
  {
    return;
  }
  const GLuint handle = static_cast<GLuint>(program->GetHandle());
  GLint count = 0;
  GLint longest = 0;
  glGetProgramiv(handle, GL_ACTIVE_UNIFORMS, &count);
  glGetProgramiv(handle, GL_ACTIVE_UNIFORM_MAX_LENGTH, &longest);
  std::vector<char> buffer(static_cast<size_t>(longest) + 1, '\0');
  for (GLint i = 0; i < count; ++i)
  {
    GLsizei length = 0;
    GLint size = 0;
    GLenum type = 0;
    glGetActiveUniform(handle, static_cast<GLuint>(i), static_cast<GLsizei>(buffer.size()), &length,
      &size, &type, buffer.data());
    std::string name(buffer.data(), static_cast<size_t>(length));
    const GLint location = glGetUniformLocation(handle, name.c_str());
    // Arrays are reported as name[0]: vtkShaderProgram sets them by the name alone.
    const size_t bracket = name.find('[');
    if (bracket != std::string::npos)
    {
      name.resize(bracket);
    }
    if (location < 0)
    {
      continue;
    }
    if (index >= 0 && std::find(indexed.begin(), indexed.end(), name) != indexed.end())
    {
      // This volume's element (for an array of arrays, its inner array's first element).
      const std::string element = name + "[" + std::to_string(index) + "]";
      GLint at = glGetUniformLocation(handle, element.c_str());
      at = at >= 0 ? at : glGetUniformLocation(handle, (element + "[0]").c_str());
      if (at >= 0 && this->UniformLocs.find(name.c_str()) == this->UniformLocs.end())
      {
        this->UniformLocs.insert(std::make_pair(strdup(name.c_str()), static_cast<int>(at)));
      }
      continue;
    }
    if (std::find(plain.begin(), plain.end(), name) != plain.end())
    {
      this->UniformLocs.insert(std::make_pair(strdup(name.c_str()), static_cast<int>(location)));
      continue;
    }
    if (name.size() <= suffix.size() ||
      name.compare(name.size() - suffix.size(), suffix.size(), suffix) != 0)
    {
      continue;
    }
    name.resize(name.size() - suffix.size());
    if (std::find(shared.begin(), shared.end(), name) != shared.end())
    {
      continue;
    }
    this->UniformLocs.insert(std::make_pair(strdup(name.c_str()), static_cast<int>(location)));
  }
  // The shared ones are known as absent, so that a setter does not look for them in the program
  // (where the group's own declaration of them would be found); so are the indexed ones this
  // volume has no element of, whose plain name in a program of shared code is the first volume's.
  auto markAbsent = [this](const std::string& name)
  {
    if (this->UniformLocs.find(name.c_str()) == this->UniformLocs.end())
    {
      this->UniformLocs.insert(std::make_pair(strdup(name.c_str()), -1));
    }
  };
  std::for_each(shared.begin(), shared.end(), markAbsent);
  if (index >= 0)
  {
    std::for_each(indexed.begin(), indexed.end(), markAbsent);
  }
  this->Handle = static_cast<int>(handle);
  this->Linked = true;
  this->Compiled = true;
}
