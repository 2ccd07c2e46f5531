/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkTiledRayCastMeshTextures.cxx

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "vtkTiledRayCastMeshTextures.h"

#include "vtkDataArray.h"
#include "vtkNew.h"
#include "vtkOpenGLBufferObject.h"
#include "vtkOpenGLError.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkShaderProgram.h"
#include "vtkTetMesh.h"
#include "vtkTetMeshLayout.h"
#include "vtkTextureObject.h"
#include "vtk_glew.h"

#include <algorithm>

// A mesh array on the GPU.
struct vtkTiledRayCastMeshTextures::MeshTexture
{
  std::string Uniform;
  int Kind = -1; // vtkTetMeshLayout::ArrayKind: a texture buffer's name never becomes a 2D texture
  vtkNew<vtkOpenGLBufferObject> Buffer;
  vtkNew<vtkTextureObject> Texture;
  vtkIdType Bytes = 0;
};

//------------------------------------------------------------------------------
vtkTiledRayCastMeshTextures::vtkTiledRayCastMeshTextures() = default;

//------------------------------------------------------------------------------
vtkTiledRayCastMeshTextures::~vtkTiledRayCastMeshTextures() = default;

//------------------------------------------------------------------------------
void vtkTiledRayCastMeshTextures::ReleaseGraphicsResources(vtkWindow* window)
{
  for (auto& t : this->Textures)
  {
    t->Texture->ReleaseGraphicsResources(window);
    t->Buffer->ReleaseGraphicsResources();
  }
  this->Textures.clear();
  this->UploadedTime = 0;
  this->Bytes = 0;
}

//------------------------------------------------------------------------------
bool vtkTiledRayCastMeshTextures::Update(vtkOpenGLRenderWindow* window, vtkTetMeshLayout* layout,
  vtkTetMesh* mesh, vtkIdType& uploaded, std::string& error)
{
  if (layout->GetMTime() <= this->UploadedTime && !this->Textures.empty())
  {
    return true; // nothing changed: only the camera moved
  }

  // The layout has checked its arrays against the GPU's limits; the boundary faces too:
  const int n = layout->GetNumberOfArrays();

  vtkOpenGLClearErrorMacro();
  vtkIdType sent = 0;
  // The same arrays: same count, names and kinds (the layouts differ in all three).
  bool sameArrays = static_cast<int>(this->Textures.size()) == n;
  for (int i = 0; sameArrays && i < n; ++i)
  {
    sameArrays = this->Textures[i]->Uniform == std::string("in_") + layout->GetArrayName(i) &&
      this->Textures[i]->Kind == layout->GetArrayKind(i);
  }
  if (!sameArrays)
  {
    const vtkMTimeType uploadedTime = this->UploadedTime;
    this->ReleaseGraphicsResources(window);
    this->UploadedTime = uploadedTime;
  }
  for (int i = 0; i < n; ++i)
  {
    if (!sameArrays)
    {
      this->Textures.emplace_back(new MeshTexture);
    }
    MeshTexture* t = this->Textures[i].get();
    vtkDataArray* array = layout->GetArray(i);
    if (sameArrays && array->GetMTime() <= this->UploadedTime)
    {
      continue; // e.g. only the points moved: topology stays on the GPU
    }
    t->Uniform = std::string("in_") + layout->GetArrayName(i);
    t->Kind = layout->GetArrayKind(i);
    const int comps = array->GetNumberOfComponents();
    const bool isFloat = array->GetDataType() == VTK_FLOAT;
    static const unsigned int floatFormats[5] = { 0, GL_R32F, GL_RG32F, 0, GL_RGBA32F };
    static const unsigned int uintFormats[5] = { 0, GL_R32UI, GL_RG32UI, 0, GL_RGBA32UI };
    if (comps < 1 || comps > 4 || comps == 3 ||
      (!isFloat && array->GetDataType() != VTK_TYPE_UINT32))
    {
      error = "Internal error: a mesh layout array of an unsupported type.";
      return false;
    }
    const vtkIdType bytes = array->GetNumberOfValues() * array->GetDataTypeSize();
    t->Texture->SetContext(window);
    t->Texture->SetInternalFormat(isFloat ? floatFormats[comps] : uintFormats[comps]);
    if (layout->GetArrayKind(i) == vtkTetMeshLayout::TextureBuffer)
    {
      t->Buffer->SetType(vtkOpenGLBufferObject::TextureBuffer);
      if (isFloat)
      {
        t->Buffer->Upload(static_cast<const float*>(array->GetVoidPointer(0)),
          static_cast<size_t>(array->GetNumberOfValues()), vtkOpenGLBufferObject::TextureBuffer);
      }
      else
      {
        t->Buffer->Upload(static_cast<const vtkTypeUInt32*>(array->GetVoidPointer(0)),
          static_cast<size_t>(array->GetNumberOfValues()), vtkOpenGLBufferObject::TextureBuffer);
      }
      t->Texture->CreateTextureBuffer(static_cast<unsigned int>(array->GetNumberOfTuples()), comps,
        isFloat ? VTK_FLOAT : VTK_UNSIGNED_INT, t->Buffer);
    }
    else
    {
      int size[2];
      layout->GetArrayTextureSize(i, size);
      t->Texture->SetFormat(comps == 4 ? GL_RGBA : GL_RED);
      t->Texture->SetDataType(GL_FLOAT);
      t->Texture->SetMinificationFilter(vtkTextureObject::Nearest);
      t->Texture->SetMagnificationFilter(vtkTextureObject::Nearest);
      t->Texture->Create2DFromRaw(size[0], size[1], comps, VTK_FLOAT, array->GetVoidPointer(0));
    }
    t->Bytes = bytes;
    sent += bytes;
  }

  if (glGetError() == GL_OUT_OF_MEMORY)
  {
    error = "The GPU ran out of memory while uploading the mesh. Nothing is drawn.";
    const vtkMTimeType uploadedTime = this->UploadedTime;
    this->ReleaseGraphicsResources(window);
    this->UploadedTime = uploadedTime;
    return false;
  }

  this->Bytes = 0;
  for (auto& t : this->Textures)
  {
    this->Bytes += t->Bytes;
  }
  this->UploadedTime = std::max(layout->GetMTime(), mesh->GetMTime());
  uploaded += sent;
  return true;
}

//------------------------------------------------------------------------------
void vtkTiledRayCastMeshTextures::ActivateTextures(bool activate)
{
  for (auto& t : this->Textures)
  {
    if (activate)
    {
      t->Texture->Activate();
    }
    else
    {
      t->Texture->Deactivate();
    }
  }
}

//------------------------------------------------------------------------------
void vtkTiledRayCastMeshTextures::SetUniforms(vtkShaderProgram* p)
{
  for (auto& t : this->Textures)
  {
    p->SetUniformi(t->Uniform.c_str(), t->Texture->GetTextureUnit());
  }
}
