/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkTiledRayCastVisibleMesh.cxx

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "vtkTiledRayCastVisibleMesh.h"

#include "vtkOpenGLBufferObject.h"
#include "vtkOpenGLError.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkShaderProgram.h"
#include "vtkTetMesh.h"
#include "vtkTextureObject.h"
#include "vtk_glew.h"

namespace
{
// Upload `count` words (one when there are none: a texture buffer cannot be empty; nothing
// reads it then) into a one-channel unsigned texture buffer.
void UploadWords(vtkOpenGLRenderWindow* window, vtkOpenGLBufferObject* buffer,
  vtkTextureObject* texture, const uint32_t* words, vtkIdType count)
{
  const uint32_t none = 0;
  const vtkIdType stored = count > 0 ? count : 1;
  buffer->SetType(vtkOpenGLBufferObject::TextureBuffer);
  buffer->Upload(
    count > 0 ? words : &none, static_cast<size_t>(stored), vtkOpenGLBufferObject::TextureBuffer);
  texture->SetContext(window);
  texture->SetInternalFormat(GL_R32UI);
  texture->CreateTextureBuffer(static_cast<unsigned int>(stored), 1, VTK_UNSIGNED_INT, buffer);
}
}

//------------------------------------------------------------------------------
vtkTiledRayCastVisibleMesh::vtkTiledRayCastVisibleMesh() = default;
vtkTiledRayCastVisibleMesh::~vtkTiledRayCastVisibleMesh() = default;

//------------------------------------------------------------------------------
bool vtkTiledRayCastVisibleMesh::Update(vtkOpenGLRenderWindow* window, vtkTetMesh* mesh,
  vtkTiledRayCastTransferFunction* transferFunction, vtkIdType maximumTextureBufferSize,
  vtkIdType& uploaded, std::string& error)
{
  const bool changed = this->EmptySpace.Update(mesh, transferFunction);
  const bool newTopology = mesh != this->UploadedMesh ||
    mesh->GetTopologyTime() != this->UploadedTopologyTime || !this->FaceTexture->GetHandle();
  if (!changed && !newTopology)
  {
    return true;
  }
  const bool skips = this->EmptySpace.GetSkipsEmptySpace();
  const uint32_t* faces =
    skips ? this->EmptySpace.GetEntryFaces().data() : mesh->GetBoundaryFaces();
  const vtkIdType numFaces = skips ? static_cast<vtkIdType>(this->EmptySpace.GetEntryFaces().size())
                                   : mesh->GetNumberOfBoundaryFaces();
  if (numFaces > maximumTextureBufferSize)
  {
    error = "The mesh has more " +
      std::string(skips ? "faces around its visible part" : "boundary faces") + " (" +
      std::to_string(numFaces) + ") than the texture buffer limit (" +
      std::to_string(maximumTextureBufferSize) + ")";
    return false;
  }

  vtkOpenGLClearErrorMacro();
  UploadWords(window, this->FaceBuffer, this->FaceTexture, faces, numFaces);
  this->NumberOfFaces = numFaces;
  this->Bytes = 4 * std::max<vtkIdType>(numFaces, 1);
  uploaded += this->Bytes;
  if (skips)
  {
    const std::vector<uint32_t>& bits = this->EmptySpace.GetVisibleBits();
    UploadWords(
      window, this->BitBuffer, this->BitTexture, bits.data(), static_cast<vtkIdType>(bits.size()));
    this->Bytes += 4 * static_cast<vtkIdType>(bits.size());
    uploaded += 4 * static_cast<vtkIdType>(bits.size());
  }
  else
  {
    this->BitTexture->ReleaseGraphicsResources(window);
    this->BitBuffer->ReleaseGraphicsResources();
  }
  if (glGetError() == GL_OUT_OF_MEMORY)
  {
    error = "The GPU ran out of memory while uploading the mesh's faces";
    this->ReleaseGraphicsResources(window);
    return false;
  }
  this->UploadedMesh = mesh;
  this->UploadedTopologyTime = mesh->GetTopologyTime();
  return true;
}

//------------------------------------------------------------------------------
std::string vtkTiledRayCastVisibleMesh::GetShaderDefinitions() const
{
  return this->GetSkipsEmptySpace() ? "#define TRC_SKIP_EMPTY_SPACE\n" : "";
}

//------------------------------------------------------------------------------
void vtkTiledRayCastVisibleMesh::ActivateTextures(bool activate, bool faces, bool bits)
{
  vtkTextureObject* textures[2] = { faces ? this->FaceTexture.GetPointer() : nullptr,
    bits && this->GetSkipsEmptySpace() ? this->BitTexture.GetPointer() : nullptr };
  for (vtkTextureObject* t : textures)
  {
    if (t && activate)
    {
      t->Activate();
    }
    else if (t)
    {
      t->Deactivate();
    }
  }
}

//------------------------------------------------------------------------------
void vtkTiledRayCastVisibleMesh::SetUniforms(vtkShaderProgram* program)
{
  program->SetUniformi("in_boundaryFaces", this->FaceTexture->GetTextureUnit());
  if (this->GetSkipsEmptySpace())
  {
    program->SetUniformi("in_visibleTets", this->BitTexture->GetTextureUnit());
  }
}

//------------------------------------------------------------------------------
void vtkTiledRayCastVisibleMesh::ReleaseGraphicsResources(vtkWindow* window)
{
  this->FaceTexture->ReleaseGraphicsResources(window);
  this->FaceBuffer->ReleaseGraphicsResources();
  this->BitTexture->ReleaseGraphicsResources(window);
  this->BitBuffer->ReleaseGraphicsResources();
  this->UploadedMesh = nullptr;
  this->UploadedTopologyTime = 0;
}
