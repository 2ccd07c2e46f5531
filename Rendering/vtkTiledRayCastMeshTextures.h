/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkTiledRayCastMeshTextures.h

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
/**
 * @class   vtkTiledRayCastMeshTextures
 * @brief   on the GPU: the arrays of the mesh's layout, as textures and texture buffers
 *
 * One texture per array of a vtkTetMeshLayout (compact or paper), named in the shaders by the
 * array's name with "in_" before it: a texture buffer, or a 2D texture for the paper layout's
 * arrays. An array larger than one texture buffer is split as the layout says
 * (vtkTetMeshLayout::GetNumberOfTextureBuffers()): its parts are "in_<name>", "in_<name>_1", ...
 * Uploads only the arrays whose MTime is newer than the last upload (a moving mesh sends its points
 * only; a camera move nothing); a layout of other arrays (names, count or kinds) starts afresh.
 * Texture buffers of 64 MiB and more go through vtkTiledRayCastStagedUpload on a GPU (not on a
 * software rasterizer).
 *
 * Private to the module: not wrapped, not installed.
 */

#ifndef vtkTiledRayCastMeshTextures_h
#define vtkTiledRayCastMeshTextures_h

#include "vtkTiledRayCastStagedUpload.h" // For vtkTiledRayCastStagedUpload
#include "vtkType.h"                     // For vtkIdType, vtkMTimeType

#include <memory> // For std::unique_ptr
#include <string> // For std::string
#include <vector> // For std::vector

class vtkDataArray;
class vtkOpenGLRenderWindow;
class vtkShaderProgram;
class vtkTetMesh;
class vtkTetMeshLayout;
class vtkWindow;

class vtkTiledRayCastMeshTextures
{
public:
  vtkTiledRayCastMeshTextures();
  ~vtkTiledRayCastMeshTextures();

  /**
   * Upload what changed in `layout` (packed from `mesh`) since the last upload; adds the bytes
   * uploaded to `uploaded`. False, with `error` set, when an array has a type the shaders cannot
   * read, or when the GPU runs out of memory (the textures are then released).
   */
  bool Update(vtkOpenGLRenderWindow* window, vtkTetMeshLayout* layout, vtkTetMesh* mesh,
    vtkIdType& uploaded, std::string& error);

  /**
   * Whether the context is a software rasterizer (large arrays are then not staged:
   * vtkTiledRayCastStagedUpload).
   */
  void SetSoftwareRasterizer(bool software) { this->Staging.SetSoftwareRasterizer(software); }

  /**
   * Upload every array on the next Update (a new layout object).
   */
  void Invalidate() { this->UploadedTime = 0; }

  /**
   * Whether every array of `layout` is on the GPU as the layout holds it now (Update would upload
   * nothing).
   */
  bool IsCurrent(vtkTetMeshLayout* layout) const;

  /**
   * The GL buffer behind part `part` of texture-buffer array `array` (0 when there is none), for
   * a compute shader that writes the array in place (vtkTiledRayCastPointMotion).
   */
  unsigned int GetBufferHandle(int array, int part) const;

  /// Bytes held on the GPU.
  vtkIdType GetBytes() const { return this->Bytes; }

  /// Textures and texture buffers held (more than the arrays where one is split).
  int GetNumberOfTextures() const;

  void ActivateTextures(bool activate);

  /**
   * The texture unit of each array, as its "in_" uniform.
   */
  void SetUniforms(vtkShaderProgram* program);

  void ReleaseGraphicsResources(vtkWindow* window);

private:
  vtkTiledRayCastMeshTextures(const vtkTiledRayCastMeshTextures&) = delete;
  void operator=(const vtkTiledRayCastMeshTextures&) = delete;

  struct MeshTexture;
  void UploadTextureBuffers(
    vtkOpenGLRenderWindow* window, MeshTexture* t, vtkDataArray* array, vtkIdType bufferSize);

  std::vector<std::unique_ptr<MeshTexture>> Textures;
  // Large arrays go through it (every core copying into mapped host memory).
  vtkTiledRayCastStagedUpload Staging;
  vtkMTimeType UploadedTime = 0;
  vtkIdType Bytes = 0;
};

#endif
// VTK-HeaderTest-Exclude: vtkTiledRayCastMeshTextures.h
