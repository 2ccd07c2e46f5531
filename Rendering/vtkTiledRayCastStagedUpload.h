/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkTiledRayCastStagedUpload.h

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
/**
 * @class   vtkTiledRayCastStagedUpload
 * @brief   sends large arrays to GPU buffers through mapped host memory, every core copying
 *
 * VTK 9.1's vtkOpenGLBufferObject::Upload hands the whole array to glBufferData, and the driver
 * copies it out of the application's memory on the calling thread: the 35 GB of a billion
 * tetrahedra's layout took most of the first frame beside the mesh build (docs/benchmarks.md,
 * "Upload"). Here a buffer is allocated without data, and the array goes through three host
 * buffers mapped once (persistent, coherent), taken in turn behind fences: all cores copy a
 * chunk in while the GPU copies the one before (glCopyBufferSubData). Arrays below
 * MinimumStagedBytes go through glBufferData as before; the host buffers are made on the first
 * large array and freed by ReleaseGraphicsResources (the mesh textures free them once an
 * upload is done). On a software rasterizer (llvmpipe), whose "GPU memory" is host memory, the
 * staging is a second copy: wavelet6_10m's upload took 1.4 s staged against 0.9 s by
 * glBufferData on this project's 2-core machine, so arrays go through glBufferData there. Needs
 * OpenGL 4.4 or ARB_buffer_storage for the mapped buffers; without it every array goes through
 * glBufferData.
 *
 * Private to the module: not wrapped, not installed.
 */

#ifndef vtkTiledRayCastStagedUpload_h
#define vtkTiledRayCastStagedUpload_h

#include <cstddef> // For size_t

class vtkOpenGLBufferObject;

class vtkTiledRayCastStagedUpload
{
public:
  ///@{
  /**
   * Arrays from MinimumStagedBytes on are staged (default 64 MiB), through host buffers of
   * ChunkBytes each (default 64 MiB). For tests: small values send small meshes through the
   * staged path; they apply to host buffers made from then on (every mapper's).
   */
  static void SetSizes(size_t minimumStagedBytes, size_t chunkBytes);
  static size_t GetMinimumStagedBytes();
  static size_t GetChunkBytes();
  ///@}

  ///@{
  /**
   * Whether the context is a software rasterizer: nothing is staged then, unless
   * StageOnSoftwareRasterizers (for tests: the staged path checked on llvmpipe).
   */
  void SetSoftwareRasterizer(bool software) { this->SoftwareRasterizer = software; }
  static void SetStageOnSoftwareRasterizers(bool stage);
  static bool GetStageOnSoftwareRasterizers();
  ///@}

  vtkTiledRayCastStagedUpload() = default;
  ~vtkTiledRayCastStagedUpload() = default;
  vtkTiledRayCastStagedUpload(const vtkTiledRayCastStagedUpload&) = delete;
  vtkTiledRayCastStagedUpload& operator=(const vtkTiledRayCastStagedUpload&) = delete;

  /**
   * Allocate `buffer` (a texture buffer object) to `bytes` bytes and fill it with `data`; with a
   * current context. GL errors (out of memory) are left for the caller to read.
   */
  void Upload(vtkOpenGLBufferObject* buffer, const void* data, size_t bytes);

  /// Frees the host buffers; with the context current.
  void ReleaseGraphicsResources();

private:
  bool MakeHostBuffers();

  static constexpr int Slots = 3;
  size_t HostBufferBytes = 0;
  unsigned int HostBuffers[Slots] = { 0, 0, 0 };
  void* Mapped[Slots] = { nullptr, nullptr, nullptr };
  void* Fences[Slots] = { nullptr, nullptr, nullptr };
  int Next = 0;
  bool SoftwareRasterizer = false;
  bool Unavailable = false;
};

#endif
