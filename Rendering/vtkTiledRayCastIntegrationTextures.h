/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkTiledRayCastIntegrationTextures.h

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
/**
 * @class   vtkTiledRayCastIntegrationTextures
 * @brief   on the GPU: what the walk integrates a segment with, in each integration mode
 *
 * Partial pre-integration reads the transfer function's node list (a texture buffer of RGBA32F
 * texels, vtkTiledRayCastTransferFunction) and Moreland and Angel's Psi table (512x512, the same
 * static table as VTK's partial pre-integration); the table modes read a 2D or 3D RGBA32F
 * pre-integration table (vtkTiledRayCastPreIntegrationTable). Uploads only what changed: the
 * node list when the transfer function's MTime is newer, the Psi table once, the table when it
 * was rebuilt or the mode changed.
 *
 * Private to the module: not wrapped, not installed.
 */

#ifndef vtkTiledRayCastIntegrationTextures_h
#define vtkTiledRayCastIntegrationTextures_h

#include "vtkNew.h"  // For vtkNew
#include "vtkType.h" // For vtkIdType, vtkMTimeType

#include <string> // For std::string

class vtkObject;
class vtkOpenGLBufferObject;
class vtkOpenGLRenderWindow;
class vtkShaderProgram;
class vtkTextureObject;
class vtkTiledRayCastPreIntegrationTable;
class vtkTiledRayCastTransferFunction;
class vtkWindow;

class vtkTiledRayCastIntegrationTextures
{
public:
  vtkTiledRayCastIntegrationTextures();
  ~vtkTiledRayCastIntegrationTextures();

  /**
   * Partial pre-integration: the node list of `transferFunction` and the Psi table, where not
   * on the GPU yet. Adds the bytes uploaded to `uploaded`.
   */
  void UpdateNodes(vtkOpenGLRenderWindow* window, vtkTiledRayCastTransferFunction* transferFunction,
    vtkIdType& uploaded);

  /**
   * A table mode (vtkTiledRayCastVolumeMapper::PRE_INTEGRATION_2D or _3D): `table`, already
   * updated, where not on the GPU yet (an explicit mode's table cut by its build-time budget
   * never comes here: vtkTiledRayCastIntegration draws partial pre-integration instead). Adds
   * the bytes uploaded to `uploaded`; false, with `error` set, when the texture cannot be
   * created.
   */
  bool UpdateTable(vtkOpenGLRenderWindow* window, vtkTiledRayCastPreIntegrationTable* table,
    int mode, vtkIdType& uploaded, std::string& error);

  /**
   * The textures of `mode` (partial pre-integration: the nodes, and the Psi table unless `psi`
   * is false: a group's volumes share the first one's).
   */
  void ActivateTextures(int mode, bool activate, bool psi = true);

  /**
   * The uniforms of `mode`'s textures: for partial pre-integration the node list (and its node
   * count) and the Psi table; for the table modes the table and how scalars (shifted by
   * `scalarShift` and scaled by `scalarScale` on the GPU) and lengths map into it.
   */
  void SetUniforms(vtkShaderProgram* program, int mode,
    vtkTiledRayCastTransferFunction* transferFunction, vtkTiledRayCastPreIntegrationTable* table,
    double scalarShift, double scalarScale);

  void ReleaseGraphicsResources(vtkWindow* window);

private:
  vtkTiledRayCastIntegrationTextures(const vtkTiledRayCastIntegrationTextures&) = delete;
  void operator=(const vtkTiledRayCastIntegrationTextures&) = delete;

  vtkNew<vtkOpenGLBufferObject> NodeBuffer;
  vtkNew<vtkTextureObject> NodeTexture;
  vtkNew<vtkTextureObject> PsiTexture;
  vtkNew<vtkTextureObject> TableTexture;
  vtkMTimeType UploadedNodesTime = 0;
  vtkMTimeType UploadedTableTime = 0;
  // The table object uploaded: the automatic mode hands over tables built on another thread.
  const void* UploadedTable = nullptr;
  int UploadedTableMode = -1;
};

#endif
// VTK-HeaderTest-Exclude: vtkTiledRayCastIntegrationTextures.h
