/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkTiledRayCastIntegrationChoice.h

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
/**
 * @class   vtkTiledRayCastIntegrationChoice
 * @brief   predicts the image error of the table modes, for the automatic integration mode
 *
 * vtkTiledRayCastVolumeMapper::AUTOMATIC_INTEGRATION takes the cheapest integration whose
 * predicted error stays within MaximumError: the 2D table, else the 3D table, else partial
 * pre-integration (exact up to float arithmetic). The prediction is made from the mesh and the
 * transfer function, not from a view:
 *
 * - **Segments of this mesh**: chords of 4096 tetrahedra drawn at random (a fixed seed), each
 *   through a random point in a random direction, give the front and back scalars and world
 *   lengths that rays meet (sampled once per mesh, points, scalars and matrix norm).
 * - **Each segment's error**: the table's answer, emulated on the CPU as the shader reads it
 *   (bilinear or trilinear between entries, the same splitting of long or thick segments),
 *   against the exact integral (vtkTetRayIntegrator), premultiplied colour and alpha.
 * - **A pixel's error**: 512 rays each composed of as many segments as a ray crosses in this
 *   mesh (1.5 cbrt(tets), measured 1.0-1.4 cbrt on the benchmark meshes), drawn from the
 *   samples, composited front to back both ways; the largest difference of a channel over the
 *   rays and over single segments, in 1/255, times a safety factor of 2.
 *
 * What the samples miss: rays that stay where a table is worst (grazing a narrow opacity band,
 * the longest chords of huge tets); the factor covers what was measured (docs/mapper.md,
 * "Automatic integration"), and the scene tests check the choice against the exact reference.
 * GL-free. Private to the module.
 */

#ifndef vtkTiledRayCastIntegrationChoice_h
#define vtkTiledRayCastIntegrationChoice_h

#include "vtkNew.h"  // For vtkNew
#include "vtkType.h" // For vtkMTimeType

#include <vector> // For std::vector

class vtkDataArray;
class vtkTetMesh;
class vtkTetRayIntegrator;
class vtkTiledRayCastPreIntegrationTable;
class vtkVolumeProperty;

class vtkTiledRayCastIntegrationChoice
{
public:
  vtkTiledRayCastIntegrationChoice();
  ~vtkTiledRayCastIntegrationChoice();

  /**
   * Draw the mesh's segments (again only when the mesh, the points or the norm changed).
   * Lengths are in world units: object lengths times `objectToWorldNorm`. Where `movedPoints`
   * is not null, the points are read there instead of the mesh's: the input's coordinates
   * after the mesh was built, the topology and the tets' flags unchanged (the mesh's point
   * order maps its points to them).
   */
  void SampleSegments(vtkTetMesh* mesh, vtkDataArray* movedPoints, double objectToWorldNorm);

  /**
   * The exact integrator of `property` (call when the property's functions changed). False
   * when the property cannot be integrated.
   */
  bool SetProperty(vtkVolumeProperty* property);

  /**
   * The predicted largest pixel error, in 1/255, of an image drawn with `table` (2D or 3D, built
   * for the property of SetProperty()); the scalars of the table are the mesh's, unshifted.
   */
  double PredictError(vtkTiledRayCastPreIntegrationTable* table);

  /// The largest error of one segment in the last prediction, in 1/255.
  double GetWorstSegmentError() const { return this->WorstSegmentError; }

  /// Segments sampled, and the segments per ray of the simulated rays.
  int GetNumberOfSegments() const { return static_cast<int>(this->Segments.size()); }
  int GetSegmentsPerRay() const { return this->SegmentsPerRay; }

private:
  vtkTiledRayCastIntegrationChoice(const vtkTiledRayCastIntegrationChoice&) = delete;
  void operator=(const vtkTiledRayCastIntegrationChoice&) = delete;

  struct Segment
  {
    double Front, Back, Length;
  };
  std::vector<Segment> Segments;
  int SegmentsPerRay = 1;
  vtkMTimeType SampledMeshTime = 0;
  vtkTetMesh* SampledMesh = nullptr;
  vtkDataArray* SampledPoints = nullptr;
  vtkMTimeType SampledPointsTime = 0;
  double SampledNorm = 0;
  vtkNew<vtkTetRayIntegrator> Exact;
  double WorstSegmentError = 0;
};

#endif
// VTK-HeaderTest-Exclude: vtkTiledRayCastIntegrationChoice.h
