/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkTiledRayCastStorageBuffer.h

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
/**
 * @class   vtkTiledRayCastStorageBuffer
 * @brief   an OpenGL shader storage buffer: allocate, bind, clear, read back
 *
 * VTK 9.1's vtkOpenGLBufferObject knows array, element and texture buffers and uploads whole
 * arrays only; the compute pipeline needs buffers that shaders write, that are bound to
 * indexed storage-buffer binding points, zeroed in part every frame without a new allocation,
 * and read back in part, once the commands that wrote it have completed (a fence). The raw GL
 * for that is here, in one small class.
 *
 * A buffer the CPU reads every frame (AllocateForReading) lives in host memory, mapped once
 * where the context has buffer storage (OpenGL 4.4 or ARB_buffer_storage): reading it is then
 * a copy in memory. glGetBufferSubData on a buffer in GPU memory costs a round trip to the GPU
 * (0.25 ms of CPU time a frame on an H200, measured), during which nothing is submitted.
 *
 * Needs a current OpenGL 4.3 context. Private to the module: not wrapped, not installed.
 */

#ifndef vtkTiledRayCastStorageBuffer_h
#define vtkTiledRayCastStorageBuffer_h

#include <cstddef> // For size_t

class vtkTiledRayCastStorageBuffer
{
public:
  vtkTiledRayCastStorageBuffer() = default;
  ~vtkTiledRayCastStorageBuffer() = default;

  /**
   * (Re)allocate to this many bytes, contents undefined; false when the GPU is out of memory.
   */
  bool Allocate(size_t bytes);
  size_t GetSize() const { return this->Size; }

  /**
   * (Re)allocate as a buffer that the GPU copies into and the CPU reads (Read), in host memory
   * mapped for reading where the context can (see the class description); false when out of
   * memory. Shaders should not write it: atomics over the bus are slow.
   */
  bool AllocateForReading(size_t bytes);

  /**
   * Bind to storage-buffer binding point `index`.
   */
  void BindBase(unsigned int index) const;

  ///@{
  /**
   * Bind another object's GL buffer (the handle of a vtkOpenGLBufferObject, such as a texture
   * buffer's storage) to storage-buffer binding point `index`, so that a compute shader writes
   * what the other passes read as a texture buffer; and the largest buffer a shader may bind
   * (GL_MAX_SHADER_STORAGE_BLOCK_SIZE, in bytes).
   */
  static void BindBufferBase(unsigned int index, unsigned int handle);
  static size_t GetMaximumBindingSize();
  ///@}

  /**
   * Copy `bytes` bytes at `offset` into `destination` at `destinationOffset`, on the GPU
   * (issue a buffer-update barrier first if shaders wrote them).
   */
  void CopyTo(vtkTiledRayCastStorageBuffer& destination, size_t offset, size_t destinationOffset,
    size_t bytes) const;

  /**
   * Write `bytes` bytes at `offset` (zeros when data is null).
   */
  void Write(size_t offset, size_t bytes, const void* data = nullptr);

  /**
   * Read `bytes` bytes at `offset`, waiting for the GPU's writes (issue a buffer-update
   * barrier first).
   */
  void Read(size_t offset, size_t bytes, void* data) const;

  ///@{
  /**
   * A fence after the commands that write the buffer (MarkWritten), and whether they have
   * completed (IsWritten: true when no fence is pending; with wait, blocks until they have).
   */
  void MarkWritten();
  bool IsWritten(bool wait);
  ///@}

  /**
   * Delete the GL buffer and fence (the context must be current).
   */
  void ReleaseGraphicsResources();

private:
  vtkTiledRayCastStorageBuffer(const vtkTiledRayCastStorageBuffer&) = delete;
  void operator=(const vtkTiledRayCastStorageBuffer&) = delete;

  unsigned int Handle = 0;
  size_t Size = 0;
  const void* Mapped = nullptr; // AllocateForReading's persistent mapping, if any
  void* Fence = nullptr;        // GLsync
};

#endif
