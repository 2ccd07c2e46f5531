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

// A mesh array on the GPU: one texture, or texture buffers of the layout's size each (an array
// larger than the GPU's largest texture buffer is split), uniforms "in_<name>", "in_<name>_1", ...
struct vtkTiledRayCastMeshTextures::MeshTexture
{
  std::string Name;
  int Kind = -1; // vtkTetMeshLayout::ArrayKind: a texture buffer's name never becomes a 2D texture
  struct Part
  {
    vtkNew<vtkOpenGLBufferObject> Buffer;
    vtkNew<vtkTextureObject> Texture;
  };
  std::vector<std::unique_ptr<Part>> Parts;
  vtkIdType Bytes = 0;

  std::string Uniform(size_t part) const
  {
    return "in_" + this->Name + (part > 0 ? "_" + std::to_string(part) : std::string());
  }

  void Release(vtkWindow* window)
  {
    for (auto& part : this->Parts)
    {
      part->Texture->ReleaseGraphicsResources(window);
      part->Buffer->ReleaseGraphicsResources();
    }
    this->Parts.clear();
  }
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
    t->Release(window);
  }
  this->Textures.clear();
  this->Staging.ReleaseGraphicsResources();
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
    sameArrays = this->Textures[i]->Name == layout->GetArrayName(i) &&
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
    t->Name = layout->GetArrayName(i);
    t->Kind = layout->GetArrayKind(i);
    const int comps = array->GetNumberOfComponents();
    const bool isFloat = array->GetDataType() == VTK_FLOAT;
    if (comps < 1 || comps > 4 || comps == 3 ||
      (!isFloat && array->GetDataType() != VTK_TYPE_UINT32))
    {
      error = "Internal error: a mesh layout array of an unsupported type.";
      return false;
    }
    const vtkIdType bytes = array->GetNumberOfValues() * array->GetDataTypeSize();
    const size_t parts = static_cast<size_t>(layout->GetNumberOfTextureBuffers(i));
    if (t->Parts.size() != parts)
    {
      t->Release(window);
      for (size_t k = 0; k < parts; ++k)
      {
        t->Parts.emplace_back(new MeshTexture::Part);
      }
    }
    if (t->Kind == vtkTetMeshLayout::TextureBuffer)
    {
      this->UploadTextureBuffers(window, t, array, layout->GetTextureBufferSize());
    }
    else
    {
      int size[2];
      layout->GetArrayTextureSize(i, size);
      vtkTextureObject* texture = t->Parts[0]->Texture;
      texture->SetContext(window);
      texture->SetInternalFormat(comps == 4 ? GL_RGBA32F : GL_R32F);
      texture->SetFormat(comps == 4 ? GL_RGBA : GL_RED);
      texture->SetDataType(GL_FLOAT);
      texture->SetMinificationFilter(vtkTextureObject::Nearest);
      texture->SetMagnificationFilter(vtkTextureObject::Nearest);
      texture->Create2DFromRaw(size[0], size[1], comps, VTK_FLOAT, array->GetVoidPointer(0));
    }
    t->Bytes = bytes;
    sent += bytes;
  }

  // The host buffers of large arrays go once the GPU has copied out of them: the upload is
  // complete when Update returns.
  this->Staging.ReleaseGraphicsResources();
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
void vtkTiledRayCastMeshTextures::UploadTextureBuffers(
  vtkOpenGLRenderWindow* window, MeshTexture* t, vtkDataArray* array, vtkIdType bufferSize)
{
  const int comps = array->GetNumberOfComponents();
  const bool isFloat = array->GetDataType() == VTK_FLOAT;
  static const unsigned int floatFormats[5] = { 0, GL_R32F, GL_RG32F, 0, GL_RGBA32F };
  static const unsigned int uintFormats[5] = { 0, GL_R32UI, GL_RG32UI, 0, GL_RGBA32UI };
  const vtkIdType texels = array->GetNumberOfTuples();
  for (size_t k = 0; k < t->Parts.size(); ++k)
  {
    const vtkIdType first = static_cast<vtkIdType>(k) * bufferSize;
    const vtkIdType count = std::max<vtkIdType>(0, std::min(bufferSize, texels - first));
    const size_t values = static_cast<size_t>(count * comps);
    vtkOpenGLBufferObject* buffer = t->Parts[k]->Buffer;
    vtkTextureObject* texture = t->Parts[k]->Texture;
    // Both types are 4 bytes a value.
    this->Staging.Upload(buffer, array->GetVoidPointer(first * comps), 4 * values);
    texture->SetContext(window);
    texture->SetInternalFormat(isFloat ? floatFormats[comps] : uintFormats[comps]);
    texture->CreateTextureBuffer(
      static_cast<unsigned int>(count), comps, isFloat ? VTK_FLOAT : VTK_UNSIGNED_INT, buffer);
  }
}

//------------------------------------------------------------------------------
bool vtkTiledRayCastMeshTextures::IsCurrent(vtkTetMeshLayout* layout) const
{
  return layout && !this->Textures.empty() && this->UploadedTime > 0 &&
    layout->GetMTime() <= this->UploadedTime &&
    static_cast<int>(this->Textures.size()) == layout->GetNumberOfArrays();
}

//------------------------------------------------------------------------------
unsigned int vtkTiledRayCastMeshTextures::GetBufferHandle(int array, int part) const
{
  if (array < 0 || array >= static_cast<int>(this->Textures.size()))
  {
    return 0;
  }
  const MeshTexture* t = this->Textures[array].get();
  if (t->Kind != vtkTetMeshLayout::TextureBuffer || part < 0 ||
    part >= static_cast<int>(t->Parts.size()))
  {
    return 0;
  }
  return static_cast<unsigned int>(t->Parts[part]->Buffer->GetHandle());
}

//------------------------------------------------------------------------------
int vtkTiledRayCastMeshTextures::GetNumberOfTextures() const
{
  size_t count = 0;
  for (const auto& t : this->Textures)
  {
    count += t->Parts.size();
  }
  return static_cast<int>(count);
}

//------------------------------------------------------------------------------
void vtkTiledRayCastMeshTextures::ActivateTextures(bool activate)
{
  for (auto& t : this->Textures)
  {
    for (auto& part : t->Parts)
    {
      if (activate)
      {
        part->Texture->Activate();
      }
      else
      {
        part->Texture->Deactivate();
      }
    }
  }
}

//------------------------------------------------------------------------------
void vtkTiledRayCastMeshTextures::SetUniforms(vtkShaderProgram* p)
{
  for (auto& t : this->Textures)
  {
    for (size_t k = 0; k < t->Parts.size(); ++k)
    {
      p->SetUniformi(t->Uniform(k).c_str(), t->Parts[k]->Texture->GetTextureUnit());
    }
  }
}
