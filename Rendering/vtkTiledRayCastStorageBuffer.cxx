/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkTiledRayCastStorageBuffer.cxx

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "vtkTiledRayCastStorageBuffer.h"

#include "vtk_glew.h"

#include <vector>

//------------------------------------------------------------------------------
bool vtkTiledRayCastStorageBuffer::Allocate(size_t bytes)
{
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
void vtkTiledRayCastStorageBuffer::BindBase(unsigned int index) const
{
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, index, this->Handle);
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
    glDeleteBuffers(1, &this->Handle);
  }
  this->Handle = 0;
  this->Size = 0;
}
