/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkTiledRayCastVisibleMesh.h

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
/**
 * @class   vtkTiledRayCastVisibleMesh
 * @brief   on the GPU: the faces rays enter the mesh by, and which tetrahedra they may cross
 *
 * Owns the texture buffer of entry faces ((t << 2) | face) that the first-hit, peeling and
 * entry-list passes draw, and, while the transfer function leaves part of the mesh empty
 * (vtkTiledRayCastEmptySpace), the bit per tetrahedron that the walk and the near-plane slice
 * test. Without empty space the faces are the mesh's boundary faces and there are no bits:
 * the shaders are then those without skipping (GetShaderDefinitions() is empty).
 *
 * Uploads only what changed: the faces when the mesh's topology or the visible set changed,
 * the bits when the visible set changed. Private to the module: not wrapped, not installed.
 */

#ifndef vtkTiledRayCastVisibleMesh_h
#define vtkTiledRayCastVisibleMesh_h

#include "vtkNew.h"                    // For vtkNew
#include "vtkTiledRayCastEmptySpace.h" // For vtkTiledRayCastEmptySpace

#include <string> // For std::string

class vtkOpenGLBufferObject;
class vtkOpenGLRenderWindow;
class vtkShaderProgram;
class vtkTetMesh;
class vtkTextureObject;
class vtkTiledRayCastTransferFunction;
class vtkWindow;

class vtkTiledRayCastVisibleMesh
{
public:
  vtkTiledRayCastVisibleMesh();
  ~vtkTiledRayCastVisibleMesh();

  /**
   * Classify `mesh` against `transferFunction` (null: no skipping) and upload what changed.
   * Adds the bytes uploaded to `uploaded`. False, with `error` set, when the GPU is out of
   * memory or the faces exceed `maximumTextureBufferSize` texels.
   */
  bool Update(vtkOpenGLRenderWindow* window, vtkTetMesh* mesh,
    vtkTiledRayCastTransferFunction* transferFunction, vtkIdType maximumTextureBufferSize,
    vtkIdType& uploaded, std::string& error);

  /**
   * Shader code to put before the mesh access code: "#define TRC_SKIP_EMPTY_SPACE" when some
   * tetrahedron is invisible, otherwise nothing.
   */
  std::string GetShaderDefinitions() const;

  bool GetSkipsEmptySpace() const { return this->EmptySpace.GetSkipsEmptySpace(); }
  vtkIdType GetNumberOfFaces() const { return this->NumberOfFaces; }
  vtkIdType GetNumberOfVisibleTetrahedra() const
  {
    return this->EmptySpace.GetNumberOfVisibleTetrahedra();
  }
  /// Bytes held on the GPU (faces and bits).
  vtkIdType GetBytes() const { return this->Bytes; }
  /// Seconds the last classification took (0 when nothing changed).
  double GetBuildTime() const { return this->EmptySpace.GetBuildTime(); }

  /**
   * The faces rays enter by (`faces`, for the entry pass) and the visible bits (`bits`, for the
   * traversal, when skipping empty space).
   */
  void ActivateTextures(bool activate, bool faces = true, bool bits = true);
  void SetUniforms(vtkShaderProgram* program);
  void ReleaseGraphicsResources(vtkWindow* window);

private:
  vtkTiledRayCastVisibleMesh(const vtkTiledRayCastVisibleMesh&) = delete;
  void operator=(const vtkTiledRayCastVisibleMesh&) = delete;

  vtkTiledRayCastEmptySpace EmptySpace;
  vtkNew<vtkOpenGLBufferObject> FaceBuffer;
  vtkNew<vtkTextureObject> FaceTexture;
  vtkNew<vtkOpenGLBufferObject> BitBuffer;
  vtkNew<vtkTextureObject> BitTexture;
  vtkTetMesh* UploadedMesh = nullptr;
  vtkMTimeType UploadedTopologyTime = 0;
  vtkIdType NumberOfFaces = 0;
  vtkIdType Bytes = 0;
};

#endif
// VTK-HeaderTest-Exclude: vtkTiledRayCastVisibleMesh.h
