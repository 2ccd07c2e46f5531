/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkTiledRayCastStorageBuffer.cxx

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "vtkTiledRayCastStorageBuffer.h"

#include "vtk_glew.h"

#include <cstring>
#include <vector>

//------------------------------------------------------------------------------
bool vtkTiledRayCastStorageBuffer::Allocate(size_t bytes)
{
  if (this->Mapped)
  {
    this->ReleaseGraphicsResources(); // immutable storage: start a new buffer
  }
  if (!this->Handle)
  {
    glGenBuffers(1, &this->Handle);
  }
  // Errors left by earlier calls are not this allocation's.
  for (int i = 0; i < 16 && glGetError() != GL_NO_ERROR; ++i)
  {
  }
  glBindBuffer(GL_SHADER_STORAGE_BUFFER, this->Handle);
  glBufferData(GL_SHADER_STORAGE_BUFFER, static_cast<GLsizeiptr>(bytes), nullptr, GL_DYNAMIC_COPY);
  glBindBuffer(GL_SHADER_STORAGE_BUFFER, 0);
  if (glGetError() == GL_OUT_OF_MEMORY)
  {
    this->ReleaseGraphicsResources();
    return false;
  }
  this->Size = bytes;
  return true;
}

//------------------------------------------------------------------------------
bool vtkTiledRayCastStorageBuffer::AllocateForReading(size_t bytes)
{
  if (!GLEW_VERSION_4_4 && !GLEW_ARB_buffer_storage)
  {
    return this->Allocate(bytes); // read with glGetBufferSubData
  }
  // Storage is immutable: a new size needs a new buffer.
  this->ReleaseGraphicsResources();
  glGenBuffers(1, &this->Handle);
  for (int i = 0; i < 16 && glGetError() != GL_NO_ERROR; ++i)
  {
  }
  // Coherent: the GPU's writes are visible to the CPU once a fence after them has signalled.
  const GLbitfield flags =
    GL_MAP_READ_BIT | GL_MAP_PERSISTENT_BIT | GL_MAP_COHERENT_BIT | GL_CLIENT_STORAGE_BIT;
  glBindBuffer(GL_COPY_WRITE_BUFFER, this->Handle);
  glBufferStorage(GL_COPY_WRITE_BUFFER, static_cast<GLsizeiptr>(bytes), nullptr, flags);
  this->Mapped = glGetError() == GL_NO_ERROR
    ? glMapBufferRange(GL_COPY_WRITE_BUFFER, 0, static_cast<GLsizeiptr>(bytes),
        GL_MAP_READ_BIT | GL_MAP_PERSISTENT_BIT | GL_MAP_COHERENT_BIT)
    : nullptr;
  glBindBuffer(GL_COPY_WRITE_BUFFER, 0);
  if (!this->Mapped)
  {
    this->ReleaseGraphicsResources();
    return false;
  }
  this->Size = bytes;
  return true;
}

//------------------------------------------------------------------------------
void vtkTiledRayCastStorageBuffer::BindBase(unsigned int index) const
{
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, index, this->Handle);
}

//------------------------------------------------------------------------------
void vtkTiledRayCastStorageBuffer::BindBufferBase(unsigned int index, unsigned int handle)
{
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, index, handle);
}

//------------------------------------------------------------------------------
size_t vtkTiledRayCastStorageBuffer::GetMaximumBindingSize()
{
  GLint64 size = 0;
  glGetInteger64v(GL_MAX_SHADER_STORAGE_BLOCK_SIZE, &size);
  return size > 0 ? static_cast<size_t>(size) : 0;
}

//------------------------------------------------------------------------------
void vtkTiledRayCastStorageBuffer::CopyTo(vtkTiledRayCastStorageBuffer& destination, size_t offset,
  size_t destinationOffset, size_t bytes) const
{
  glBindBuffer(GL_COPY_READ_BUFFER, this->Handle);
  glBindBuffer(GL_COPY_WRITE_BUFFER, destination.Handle);
  glCopyBufferSubData(GL_COPY_READ_BUFFER, GL_COPY_WRITE_BUFFER, static_cast<GLintptr>(offset),
    static_cast<GLintptr>(destinationOffset), static_cast<GLsizeiptr>(bytes));
  glBindBuffer(GL_COPY_READ_BUFFER, 0);
  glBindBuffer(GL_COPY_WRITE_BUFFER, 0);
}

//------------------------------------------------------------------------------
void vtkTiledRayCastStorageBuffer::Write(size_t offset, size_t bytes, const void* data)
{
  std::vector<unsigned char> zeros;
  if (!data)
  {
    zeros.assign(bytes, 0);
    data = zeros.data();
  }
  glBindBuffer(GL_SHADER_STORAGE_BUFFER, this->Handle);
  glBufferSubData(
    GL_SHADER_STORAGE_BUFFER, static_cast<GLintptr>(offset), static_cast<GLsizeiptr>(bytes), data);
  glBindBuffer(GL_SHADER_STORAGE_BUFFER, 0);
}

//------------------------------------------------------------------------------
void vtkTiledRayCastStorageBuffer::Read(size_t offset, size_t bytes, void* data) const
{
  if (this->Mapped)
  {
    std::memcpy(data, static_cast<const unsigned char*>(this->Mapped) + offset, bytes);
    return;
  }
  glBindBuffer(GL_SHADER_STORAGE_BUFFER, this->Handle);
  glGetBufferSubData(
    GL_SHADER_STORAGE_BUFFER, static_cast<GLintptr>(offset), static_cast<GLsizeiptr>(bytes), data);
  glBindBuffer(GL_SHADER_STORAGE_BUFFER, 0);
}

//------------------------------------------------------------------------------
void vtkTiledRayCastStorageBuffer::MarkWritten()
{
  if (this->Fence)
  {
    glDeleteSync(static_cast<GLsync>(this->Fence));
  }
  this->Fence = glFenceSync(GL_SYNC_GPU_COMMANDS_COMPLETE, 0);
}

//------------------------------------------------------------------------------
bool vtkTiledRayCastStorageBuffer::IsWritten(bool wait)
{
  if (!this->Fence)
  {
    return true;
  }
  GLsync fence = static_cast<GLsync>(this->Fence);
  // The first wait flushes, so that a fence never waits on commands still in the CPU's queue.
  GLenum result = glClientWaitSync(fence, GL_SYNC_FLUSH_COMMANDS_BIT, 0);
  while (wait && result == GL_TIMEOUT_EXPIRED)
  {
    result = glClientWaitSync(fence, 0, 1000000); // 1 ms
  }
  if (result == GL_TIMEOUT_EXPIRED)
  {
    return false;
  }
  glDeleteSync(fence);
  this->Fence = nullptr;
  return true;
}

//------------------------------------------------------------------------------
void vtkTiledRayCastStorageBuffer::ReleaseGraphicsResources()
{
  if (this->Fence)
  {
    glDeleteSync(static_cast<GLsync>(this->Fence));
    this->Fence = nullptr;
  }
  if (this->Handle)
  {
    if (this->Mapped)
    {
      glBindBuffer(GL_COPY_WRITE_BUFFER, this->Handle);
      glUnmapBuffer(GL_COPY_WRITE_BUFFER);
      glBindBuffer(GL_COPY_WRITE_BUFFER, 0);
      this->Mapped = nullptr;
    }
    glDeleteBuffers(1, &this->Handle);
  }
  this->Handle = 0;
  this->Size = 0;
}
