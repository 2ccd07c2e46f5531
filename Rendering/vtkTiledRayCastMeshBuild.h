/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkTiledRayCastMeshBuild.h

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
/**
 * @class   vtkTiledRayCastMeshBuild
 * @brief   the mapper's CPU mesh: its input built into a vtkTetMesh, packed into a layout
 *
 * Update() has vtkTetMeshBuilder rebuild only what changed (nothing, the scalars, the points
 * or everything) from the mapper's input (a grid, or a composite input merged by
 * vtkTiledRayCastMeshInput), reports the builder's findings in the mapper's validation report
 * (warning once per new report), and repacks the layout the mapper asks for (compact or
 * paper) within the GPU's limits or the user's lower ones. The builder's and the layouts' own
 * errors and warnings are silenced: the mapper reports them once. The builder's progress is the
 * mapper's. What the frames need of the mesh (bounds, shift, scalar range, edge lengths) is
 * kept in public members, updated when the mesh changes.
 *
 * No OpenGL. Private to the module: not wrapped, not installed.
 */

#ifndef vtkTiledRayCastMeshBuild_h
#define vtkTiledRayCastMeshBuild_h

#include "vtkNew.h"                   // For vtkNew
#include "vtkSmartPointer.h"          // For vtkSmartPointer
#include "vtkTetMeshBuildState.h"     // For vtkTetMeshBuildState::Stamp
#include "vtkTiledRayCastMeshInput.h" // For vtkTiledRayCastMeshInput
#include "vtkType.h"                  // For vtkIdType, vtkMTimeType

#include <string> // For std::string
#include <vector> // For std::vector

class vtkCallbackCommand;
class vtkDataObject;
class vtkPointSet;
class vtkTetMesh;
class vtkTetMeshBuilder;
class vtkTetMeshLayout;
class vtkTiledRayCastMemoryBudget;
class vtkTiledRayCastVolumeMapper;
class vtkVolumeProperty;

class vtkTiledRayCastMeshBuild
{
public:
  explicit vtkTiledRayCastMeshBuild(vtkTiledRayCastVolumeMapper* mapper);
  ~vtkTiledRayCastMeshBuild();

  /**
   * Build the mesh of `input` (the scalars `property` selects) and its layout, within textures
   * of `maxTextureSize` and texture buffers of `maxTextureBufferSize` texels (the GPU's
   * limits) and within `budget` (checked before the build where the input tells, and on the
   * layout). False, with `error` set, when nothing can be drawn.
   */
  bool Update(vtkDataObject* input, vtkVolumeProperty* property, int maxTextureSize,
    int maxTextureBufferSize, vtkTiledRayCastMemoryBudget& budget, std::string& error);

  /**
   * The input's points when, since the last Update(), they alone moved (same cells, scalars
   * and settings; a plain grid, the compact layout, the same limits): the mapper may then move
   * them on the GPU (vtkTiledRayCastPointMotion) and call MovedPoints() instead of Update().
   * Null otherwise: Update() must run.
   */
  vtkPointSet* GetMovedPointsOnly(vtkDataObject* input, vtkVolumeProperty* property,
    int maxTextureSize, int maxTextureBufferSize, const vtkTiledRayCastMemoryBudget& budget);

  /**
   * After the points of `input` were moved on the GPU: the frame's bounds, shift and edge
   * lengths from the new points (`longestEdge` measured on the GPU), and the statistics
   * (MeshRebuildPointsOnGPU, `seconds` of build time). Shift() gives the shift to move them by.
   */
  void MovedPoints(vtkPointSet* input, double longestEdge, double seconds);
  static void ShiftOf(vtkPointSet* input, double shift[3]);

  /// The builder's degeneracy tolerance (what a full build classifies tetrahedra by).
  double GetDegeneracyTolerance() const;

  /**
   * Whether the layout object was replaced since the last call (its arrays must all be
   * uploaded again).
   */
  bool TakeNewLayout()
  {
    const bool changed = this->NewLayout;
    this->NewLayout = false;
    return changed;
  }

  vtkTetMesh* GetMesh();
  vtkTetMeshLayout* GetLayout();

  int LayoutKind = -1; // vtkTiledRayCastVolumeMapper's
  vtkIdType TextureBufferLimit = 0;
  vtkIdType NumberOfTets = 0;
  bool HasCellScalars = false;
  double MeshBounds[6] = { 0, 0, 0, 0, 0, 0 }; // in shifted object coordinates
  double Shift[3] = { 0, 0, 0 };
  double ScalarRange[2] = { 0, 1 };
  double LongestEdge = 0; // in object coordinates
  double TypicalEdge = 0; // idem

private:
  vtkTiledRayCastMeshBuild(const vtkTiledRayCastMeshBuild&) = delete;
  void operator=(const vtkTiledRayCastMeshBuild&) = delete;

  vtkTiledRayCastVolumeMapper* Mapper;
  vtkNew<vtkCallbackCommand> Silencer;
  vtkNew<vtkCallbackCommand> BuildProgress;
  vtkNew<vtkTetMeshBuilder> Builder;
  vtkTiledRayCastMeshInput Input;
  vtkSmartPointer<vtkTetMeshLayout> Layout;
  int LayoutTextureLimit = 0;
  vtkMTimeType MeshTime = 0;
  vtkMTimeType ReportedTime = 0;
  // The input and user limit last found within the GPU memory budget: checked again only when
  // one changes (the check reads every cell type).
  const void* BudgetInput = nullptr;
  std::vector<vtkTetMeshBuildState::Stamp> BudgetTopology;
  vtkIdType BudgetPoints = -1;
  vtkIdType BudgetUserLimit = -1;
  bool NewLayout = false;
  void SetFrameValues(const double bounds[6], const double shift[3]);
};

#endif
// VTK-HeaderTest-Exclude: vtkTiledRayCastMeshBuild.h
