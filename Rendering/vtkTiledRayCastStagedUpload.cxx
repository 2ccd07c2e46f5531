/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkTiledRayCastStagedUpload.cxx

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "vtkTiledRayCastStagedUpload.h"

#include "vtkOpenGLBufferObject.h"
#include "vtkSMPTools.h"
#include "vtk_glew.h"

#include <algorithm>
#include <cstring>

namespace
{
// Waits for a fence (if any) and deletes it.
void WaitAndDelete(void*& fence)
{
  if (fence)
  {
    GLsync sync = static_cast<GLsync>(fence);
    while (glClientWaitSync(sync, GL_SYNC_FLUSH_COMMANDS_BIT, 1000000000) == GL_TIMEOUT_EXPIRED)
    {
    }
    glDeleteSync(sync);
    fence = nullptr;
  }
}

size_t MinimumStaged = size_t(64) << 20;
size_t Chunk = size_t(64) << 20;
bool StageOnSoftware = false;

// Every core copies its part: one thread's memcpy is a fraction of the host's bandwidth.
void ParallelCopy(void* destination, const void* source, size_t bytes)
{
  const size_t block = size_t(1) << 20;
  const vtkIdType blocks = static_cast<vtkIdType>((bytes + block - 1) / block);
  vtkSMPTools::For(0, blocks, 1,
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType b = begin; b < end; ++b)
      {
        const size_t first = static_cast<size_t>(b) * block;
        std::memcpy(static_cast<char*>(destination) + first,
          static_cast<const char*>(source) + first, std::min(block, bytes - first));
      }
    });
}
}

//------------------------------------------------------------------------------
void vtkTiledRayCastStagedUpload::SetSizes(size_t minimumStagedBytes, size_t chunkBytes)
{
  MinimumStaged = minimumStagedBytes;
  Chunk = std::max<size_t>(chunkBytes, 16); // whole texels
}

//------------------------------------------------------------------------------
void vtkTiledRayCastStagedUpload::SetStageOnSoftwareRasterizers(bool stage)
{
  StageOnSoftware = stage;
}

//------------------------------------------------------------------------------
bool vtkTiledRayCastStagedUpload::GetStageOnSoftwareRasterizers()
{
  return StageOnSoftware;
}

//------------------------------------------------------------------------------
size_t vtkTiledRayCastStagedUpload::GetMinimumStagedBytes()
{
  return MinimumStaged;
}

//------------------------------------------------------------------------------
size_t vtkTiledRayCastStagedUpload::GetChunkBytes()
{
  return Chunk;
}

//------------------------------------------------------------------------------
bool vtkTiledRayCastStagedUpload::MakeHostBuffers()
{
  if (this->Mapped[0] || this->Unavailable)
  {
    return !this->Unavailable;
  }
  if (!(GLEW_VERSION_4_4 || GLEW_ARB_buffer_storage))
  {
    this->Unavailable = true;
    return false;
  }
  const GLbitfield access = GL_MAP_WRITE_BIT | GL_MAP_PERSISTENT_BIT | GL_MAP_COHERENT_BIT;
  this->HostBufferBytes = Chunk;
  glGenBuffers(Slots, this->HostBuffers);
  for (int s = 0; s < Slots; ++s)
  {
    glBindBuffer(GL_COPY_READ_BUFFER, this->HostBuffers[s]);
    glBufferStorage(GL_COPY_READ_BUFFER, static_cast<GLsizeiptr>(this->HostBufferBytes), nullptr,
      access | GL_CLIENT_STORAGE_BIT);
    this->Mapped[s] = glMapBufferRange(
      GL_COPY_READ_BUFFER, 0, static_cast<GLsizeiptr>(this->HostBufferBytes), access);
    if (!this->Mapped[s])
    {
      glBindBuffer(GL_COPY_READ_BUFFER, 0);
      this->ReleaseGraphicsResources();
      this->Unavailable = true; // glBufferData, as VTK does
      return false;
    }
  }
  glBindBuffer(GL_COPY_READ_BUFFER, 0);
  this->Next = 0;
  return true;
}

//------------------------------------------------------------------------------
void vtkTiledRayCastStagedUpload::Upload(
  vtkOpenGLBufferObject* buffer, const void* data, size_t bytes)
{
  buffer->SetType(vtkOpenGLBufferObject::TextureBuffer);
  if (bytes < MinimumStaged || bytes == 0 || (this->SoftwareRasterizer && !StageOnSoftware) ||
    !this->MakeHostBuffers())
  {
    buffer->Upload(static_cast<const char*>(data), bytes, vtkOpenGLBufferObject::TextureBuffer);
    return;
  }
  buffer->GenerateBuffer(vtkOpenGLBufferObject::TextureBuffer);
  glBindBuffer(GL_COPY_WRITE_BUFFER, static_cast<GLuint>(buffer->GetHandle()));
  glBufferData(GL_COPY_WRITE_BUFFER, static_cast<GLsizeiptr>(bytes), nullptr, GL_STATIC_DRAW);
  const size_t chunk = this->HostBufferBytes;
  for (size_t offset = 0; offset < bytes; offset += chunk)
  {
    const size_t piece = std::min(chunk, bytes - offset);
    const int s = this->Next;
    this->Next = (this->Next + 1) % Slots;
    // The GPU's copy out of this host buffer, three chunks ago, must be done.
    WaitAndDelete(this->Fences[s]);
    ParallelCopy(this->Mapped[s], static_cast<const char*>(data) + offset, piece);
    glBindBuffer(GL_COPY_READ_BUFFER, this->HostBuffers[s]);
    glCopyBufferSubData(GL_COPY_READ_BUFFER, GL_COPY_WRITE_BUFFER, 0, static_cast<GLintptr>(offset),
      static_cast<GLsizeiptr>(piece));
    this->Fences[s] = glFenceSync(GL_SYNC_GPU_COMMANDS_COMPLETE, 0);
  }
  glBindBuffer(GL_COPY_READ_BUFFER, 0);
  glBindBuffer(GL_COPY_WRITE_BUFFER, 0);
}

//------------------------------------------------------------------------------
void vtkTiledRayCastStagedUpload::ReleaseGraphicsResources()
{
  if (!this->HostBuffers[0])
  {
    return; // nothing held: no GL call (the context may be gone)
  }
  for (int s = 0; s < Slots; ++s)
  {
    // The copies out of the host buffers finish before the buffers go.
    WaitAndDelete(this->Fences[s]);
    if (this->Mapped[s])
    {
      glBindBuffer(GL_COPY_READ_BUFFER, this->HostBuffers[s]);
      glUnmapBuffer(GL_COPY_READ_BUFFER);
      this->Mapped[s] = nullptr;
    }
  }
  glBindBuffer(GL_COPY_READ_BUFFER, 0);
  glDeleteBuffers(Slots, this->HostBuffers);
  std::fill(this->HostBuffers, this->HostBuffers + Slots, 0u);
}
