/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkTiledRayCastMemoryBudget.h

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
/**
 * @class   vtkTiledRayCastMemoryBudget
 * @brief   how much GPU memory the mesh may take, checked before the build and before upload
 *
 * The budget is the least of the mapper's MaximumGPUMemory (when set) and what the driver reports
 * free (NVIDIA's GL_NVX_gpu_memory_info; unknown elsewhere) plus what the mapper's mesh holds now
 * (it is replaced). A mesh that needs more is refused with an error that names both sizes:
 * before it is built where the input's counts bound its layout from below (an unstructured grid
 * of one linear 3D cell type: a billion tetrahedra are refused in a moment, not after a minute
 * of building and 200 GB of host memory), and in any case once its layout is packed, before any
 * upload (no out-of-memory error from the driver, no half-uploaded mesh).
 *
 * Private to the module: not wrapped, not installed.
 */

#ifndef vtkTiledRayCastMemoryBudget_h
#define vtkTiledRayCastMemoryBudget_h

#include "vtkType.h" // For vtkIdType

#include <string> // For std::string

class vtkDataSet;
class vtkOpenGLRenderWindow;
class vtkTetMeshLayout;

class vtkTiledRayCastMemoryBudget
{
public:
  /**
   * The budget of this frame: `userLimit` bytes (0: none), the free memory `window`'s driver
   * reports, `heldBytes` of which the mesh on the GPU holds now. The driver is asked only when
   * a check needs it (a check runs only when the input changed).
   */
  void Update(vtkOpenGLRenderWindow* window, vtkIdType userLimit, vtkIdType heldBytes);

  /// The bytes the mesh may take, or -1 without a limit.
  vtkIdType GetBytes();

  /// The user's limit given to Update().
  vtkIdType GetUserLimit() const { return this->UserLimit; }

  /**
   * Before the build: false, with `error` set, when the layout of `input` (the paper layout or
   * the compact one) cannot fit, from a lower bound on its tetrahedra and its points. True where
   * the input's counts bound nothing (mixed or nonlinear cells, other data sets).
   */
  bool CheckInput(vtkDataSet* input, bool paperLayout, std::string& error);

  /**
   * After the layout is packed: false, with `error` set, when its arrays (and the visible set
   * and entry faces, `visibleMeshBytes`) do not fit.
   */
  bool CheckLayout(vtkTetMeshLayout* layout, vtkIdType visibleMeshBytes, std::string& error);

private:
  std::string Refusal(vtkIdType needed, const std::string& mesh, const std::string& atLeast) const;

  vtkOpenGLRenderWindow* Window = nullptr;
  vtkIdType UserLimit = 0;
  vtkIdType HeldBytes = 0;
  bool Known = false; // Bytes and Source worked out since Update()
  vtkIdType Bytes = -1;
  std::string Source; // what the budget is: "MaximumGPUMemory" or the driver's free memory
};

#endif
// VTK-HeaderTest-Exclude: vtkTiledRayCastMemoryBudget.h
