/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkTiledRayCastAutomaticIntegration.h

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
/**
 * @class   vtkTiledRayCastAutomaticIntegration
 * @brief   makes the automatic integration mode's choice on a worker thread
 *
 * The choice (vtkTiledRayCastIntegrationChoice: the cheapest table whose predicted error fits
 * the budget) integrates thousands of segments exactly and builds the tables it tries: 10 ms for
 * a smooth transfer function, up to a second for a spiky one whose tables both fail (two cores,
 * measured). Made in Render(), that would stall every frame in which a user edits the transfer
 * function. So Start() copies what the choice needs (the property with its functions, the
 * mesh's segments, the settings) and makes it on a worker thread; until Take() returns it, the
 * mapper draws with partial pre-integration, which is exact: no frame is ever drawn with a table
 * that was not checked against the budget. A choice still running when the inputs change again
 * is abandoned (it stops after the table it is building) and its result dropped.
 *
 * GL-free. Private to the module: not wrapped, not installed.
 */

#ifndef vtkTiledRayCastAutomaticIntegration_h
#define vtkTiledRayCastAutomaticIntegration_h

#include "vtkSmartPointer.h"             // For vtkSmartPointer
#include "vtkTiledRayCastVolumeMapper.h" // For the integration modes

#include <future> // For std::future
#include <memory> // For std::shared_ptr
#include <vector> // For std::vector

class vtkDataArray;
class vtkTetMesh;
class vtkTiledRayCastPreIntegrationTable;
class vtkVolumeProperty;

class vtkTiledRayCastAutomaticIntegration
{
public:
  vtkTiledRayCastAutomaticIntegration();
  ~vtkTiledRayCastAutomaticIntegration();

  /**
   * What a table is built for: the explicit table modes' (vtkTiledRayCastIntegration) and the
   * choice's alike, through Configure().
   */
  struct Settings
  {
    double ScalarRange[2] = { 0, 1 };
    double MaximumError = 1.0; // in 1/255
    int RequestedScalarSize = 0;
    int RequestedLengthSize = 0;
    int MaxTextureSize = 2048;
    int Max3DTextureSize = 256;
    double MaximumLength = 1.0;
    double ReferenceLength = 1.0;
  };

  /**
   * Set `table` up for `mode` (PRE_INTEGRATION_2D or PRE_INTEGRATION_3D) and `settings` (it is
   * built by its Update()).
   */
  static void Configure(
    vtkTiledRayCastPreIntegrationTable* table, const Settings& settings, int mode);

  /**
   * A table the choice tried: its mode, predicted error and worst single segment, in 1/255.
   */
  struct Tried
  {
    int Mode;
    double PredictedError;
    double WorstSegmentError;
  };

  /**
   * A choice: the mode, its predicted error in 1/255 (0 for partial pre-integration), and the
   * table of a table mode, built for the property given to Start().
   */
  struct Choice
  {
    int Mode = vtkTiledRayCastVolumeMapper::PARTIAL_PRE_INTEGRATION;
    double PredictedError = 0.0;
    std::vector<Tried> TablesTried; // in order: the 2D table, then the 3D table
    vtkSmartPointer<vtkTiledRayCastPreIntegrationTable> Table;
  };

  /**
   * Start choosing for `mesh` (its segments are sampled here, on the calling thread, at
   * `movedPoints` where not null: see vtkTiledRayCastIntegrationChoice::SampleSegments),
   * `property` (copied) and `settings`; a choice in progress is abandoned.
   */
  void Start(vtkTetMesh* mesh, vtkDataArray* movedPoints, double objectToWorldNorm,
    vtkVolumeProperty* property, const Settings& settings);

  /**
   * The choice of the latest Start(), once made: true and `choice` set, once. With `wait`,
   * blocks until it is made; without, false while it is being made (or when none was started).
   */
  bool Take(Choice& choice, bool wait);

  /**
   * Give up the choice of the latest Start(), if any: it stops at its next table, and Take()
   * has nothing until the next Start().
   */
  void Abandon();

private:
  vtkTiledRayCastAutomaticIntegration(const vtkTiledRayCastAutomaticIntegration&) = delete;
  void operator=(const vtkTiledRayCastAutomaticIntegration&) = delete;

  struct Job;
  // Drop the abandoned jobs that have finished (an abandoned job's future blocks when destroyed).
  void ReapAbandoned(bool wait);

  std::shared_ptr<Job> Current;
  std::future<void> CurrentDone;
  std::vector<std::pair<std::shared_ptr<Job>, std::future<void>>> Abandoned;
};

#endif
// VTK-HeaderTest-Exclude: vtkTiledRayCastAutomaticIntegration.h
