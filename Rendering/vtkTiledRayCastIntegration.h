/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkTiledRayCastIntegration.h

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
/**
 * @class   vtkTiledRayCastIntegration
 * @brief   what the walk integrates with: the transfer function, the mode, its table and textures
 *
 * Update() rebuilds the transfer function's node list (vtkTiledRayCastTransferFunction) where
 * the property changed, takes the automatic mode's choice again where its inputs changed
 * (vtkTiledRayCastIntegrationChoice: the cheapest table whose predicted error is within the
 * mapper's budget, else partial pre-integration), builds the 2D or 3D table a table mode needs
 * (vtkTiledRayCastPreIntegrationTable, at the resolution and lengths it needs within the GPU's
 * limits) and uploads what changed (vtkTiledRayCastIntegrationTextures). The statistics of the
 * mode, the predicted error, the table and the transfer function are set there.
 *
 * Private to the module: not wrapped, not installed.
 */

#ifndef vtkTiledRayCastIntegration_h
#define vtkTiledRayCastIntegration_h

#include "vtkNew.h"                              // For vtkNew
#include "vtkSmartPointer.h"                     // For vtkSmartPointer
#include "vtkTiledRayCastAutomaticIntegration.h" // For vtkTiledRayCastAutomaticIntegration
#include "vtkTiledRayCastIntegrationTextures.h"  // For vtkTiledRayCastIntegrationTextures
#include "vtkTiledRayCastVolumeMapper.h"         // For the integration modes
#include "vtkType.h"                             // For vtkIdType

#include <string> // For std::string
#include <vector> // For std::vector

class vtkDataArray;
class vtkOpenGLRenderWindow;
class vtkShaderProgram;
class vtkTetMesh;
class vtkTiledRayCastPreIntegrationTable;
class vtkTiledRayCastTransferFunction;
class vtkVolumeProperty;
class vtkWindow;

class vtkTiledRayCastIntegration
{
public:
  vtkTiledRayCastIntegration();
  ~vtkTiledRayCastIntegration();

  /**
   * What the integration of a frame depends on.
   */
  struct Frame
  {
    vtkTiledRayCastVolumeMapper* Mapper = nullptr; // its settings, statistics and warnings
    vtkOpenGLRenderWindow* Window = nullptr;
    vtkTetMesh* Mesh = nullptr;
    double ScalarRange[2] = { 0, 1 };
    double LongestEdge = 0; // in object coordinates
    double TypicalEdge = 0; // idem
    double ObjectToWorldNorm = 1;
    int MaxTextureSize = 0;
    int Max3DTextureSize = 0;
    // Whether a choice of the automatic mode in progress is waited for (SynchronousStatistics);
    // the first choice always is.
    bool WaitForChoice = false;
    // The input's coordinates where they moved on the GPU since Mesh was built
    // (vtkTiledRayCastPointMotion: Mesh holds older points; its point order maps to these), or
    // null: a new automatic choice samples its segments' points there, a few thousand reads,
    // instead of the CPU rebuilding every point.
    vtkDataArray* MovedPoints = nullptr;
  };

  /**
   * Update the transfer function, the automatic choice, the table and the textures for this
   * frame. False, with `error` set, when the table's texture cannot be created.
   */
  bool Update(const Frame& frame, vtkVolumeProperty* property, std::string& error);

  /**
   * The integration the shaders do: the mapper's setting, or partial pre-integration's node
   * list under a blend mode other than compositing (vtkTiledRayCastBlendModes.glsl evaluates
   * it). AUTOMATIC_INTEGRATION is the mode the automatic choice took. An explicit table mode
   * whose table had to be built coarser than asked to keep within its build-time budget
   * (vtkTiledRayCastPreIntegrationTable::GetReducedFromScalarSize) is drawn with partial
   * pre-integration, which is exact: such a table cannot hold the feature that made it slow.
   */
  int GetMode(vtkTiledRayCastVolumeMapper* mapper) const;

  /**
   * Partial pre-integration whatever the automatic mode chose: for a volume integrated with
   * others in one traversal (vtkTiledRayCastVolumeGroup), whose mixture reads every volume's
   * node list. An explicit table mode is not overridden (such a volume is not grouped).
   */
  void SetForcePartial(bool force) { this->ForcePartial = force; }

  vtkTiledRayCastTransferFunction* GetTransferFunction() { return this->TransferFunction; }

  /// Bytes the mode's textures hold on the GPU.
  vtkIdType GetBytes() const { return this->Bytes; }

  void ActivateTextures(int mode, bool activate, bool psi = true)
  {
    this->Textures.ActivateTextures(mode, activate, psi);
  }

  /**
   * The uniforms of `mode`'s textures (vtkTiledRayCastIntegrationTextures::SetUniforms).
   */
  void SetUniforms(vtkShaderProgram* program, int mode, double scalarShift, double scalarScale);

  void ReleaseGraphicsResources(vtkWindow* window);

private:
  vtkTiledRayCastIntegration(const vtkTiledRayCastIntegration&) = delete;
  void operator=(const vtkTiledRayCastIntegration&) = delete;

  // The automatic mode's choice, made again (on a worker thread) when the transfer function,
  // the mesh, the lengths or the budget changed; partial pre-integration until it is made.
  void ChooseIntegration(const Frame& frame, vtkVolumeProperty* property);
  void UpdateExplicitTable(const Frame& frame, vtkVolumeProperty* property);
  // What a table is built for in this frame: the lengths as they are (explicit table modes),
  // or in steps of 2^(1/8) (`quantized`: the automatic mode's choice and its key).
  static vtkTiledRayCastAutomaticIntegration::Settings TableSettings(
    const Frame& frame, bool quantized);

  vtkNew<vtkTiledRayCastTransferFunction> TransferFunction;
  // The table of a table mode: built here for an explicit mode, by the choice for the automatic
  // mode (then exactly the one its prediction read).
  vtkSmartPointer<vtkTiledRayCastPreIntegrationTable> Table;
  vtkTiledRayCastIntegrationTextures Textures;
  vtkTiledRayCastAutomaticIntegration Automatic;
  bool ChoiceMade = false; // since this object exists
  bool ForcePartial = false;
  bool TableTooCoarse = false;           // an explicit table mode's table, cut by its budget
  vtkMTimeType WarnedTooCoarseTable = 0; // the table configuration last said so of
  int AutomaticMode = vtkTiledRayCastVolumeMapper::PARTIAL_PRE_INTEGRATION;
  double PredictedError = 0.0;
  std::vector<double> ChoiceKey;
  // The key changed in the last frame this object chose for; and a choice waits for a frame that
  // keeps its key (the key changed in consecutive frames: points moving, a transfer function
  // dragged).
  bool ChoiceKeyJustChanged = false;
  bool ChoiceDeferred = false;
  vtkIdType Bytes = 0;
};

#endif
// VTK-HeaderTest-Exclude: vtkTiledRayCastIntegration.h
