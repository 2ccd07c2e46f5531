/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkTetReferenceScene.h

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
/**
 * @class   vtkTetReferenceScene
 * @brief   private: vtkTetReferenceRenderer's volumes and translucent layers, prepared
 *
 * A volume's sources (mesh, property, scalar selection, matrix: the renderer's own settings or a
 * vtkTetReferenceVolume's) become a prepared mesh (vtkTetReferenceMesh, cached until its sources
 * change) and an initialised integrator (cached until the property changes): PrepareMesh() and
 * InitializeIntegrator() do it for the renderer's own volume, Prepare() for a whole scene.
 * CheckLayer() validates a translucent layer; CastRays() renders a scene's pixels through
 * vtkTetReferenceIntermixing. Errors come back as text, for the renderer's vtkErrorMacro.
 */

#ifndef vtkTetReferenceScene_h
#define vtkTetReferenceScene_h

#include "vtkSmartPointer.h"            // For vtkSmartPointer
#include "vtkTetReferenceIntermixing.h" // For vtkTetReferenceIntermixing
#include "vtkTetReferenceMesh.h"        // For vtkTetReferenceMesh
#include "vtkType.h"                    // For vtkIdType, vtkMTimeType

#include <memory> // For std::unique_ptr
#include <string> // For std::string
#include <vector> // For std::vector

class vtkCallbackCommand;
class vtkDataArray;
class vtkDataSet;
class vtkFloatArray;
class vtkTetRayIntegrator;
class vtkTetReferencePixelRays;
class vtkTetReferenceVolume;
class vtkTetScalarSelection;
class vtkVolumeProperty;

class vtkTetReferenceScene
{
public:
  vtkTetReferenceScene();
  ~vtkTetReferenceScene();

  /**
   * What a volume is made of.
   */
  struct Source
  {
    vtkDataSet* Input = nullptr;
    vtkVolumeProperty* Property = nullptr;
    double Matrix[16];
    vtkTetScalarSelection* Selection = nullptr; // the volume's (not resolved: its settings)
  };

  /**
   * What `volume` renders: its input, the property and matrix in force, its scalar selection.
   */
  static Source MakeSource(vtkTetReferenceVolume* volume);

  /**
   * The mesh of `source`, prepared again only when what it depends on changed (`rebuilt` says
   * whether it was). False, with `error`, when it cannot be rendered.
   */
  static bool PrepareMesh(const Source& source, vtkTetReferenceMesh& mesh, bool& rebuilt,
    vtkIdType& degenerate, std::string& error);

  /**
   * `integrator` initialised from `property` unless it already was from this property,
   * unmodified since (`property` and `mtime` remember which).
   */
  static bool InitializeIntegrator(vtkTetRayIntegrator* integrator, vtkVolumeProperty* property,
    vtkVolumeProperty*& cached, vtkMTimeType& mtime);

  /**
   * Prepare the added volumes `sources` (each checked: input, property, scalars, cells): their
   * meshes and integrators, cached from one call to the next by position. False with `error`
   * (naming the volume by its position, counted from `first`) for the first that fails.
   * `tetrahedra` gets the three counts of the meshes (rendered, degenerate, overlapping) added,
   * `preparationTime` the seconds spent on meshes that were prepared again.
   */
  bool Prepare(const std::vector<Source>& sources, int first, vtkIdType tetrahedra[3],
    double& preparationTime, std::string& error);

  /**
   * Forget the added volumes' prepared state.
   */
  void Clear();

  /**
   * The media of the added volumes (after Prepare()), to append to a vtkTetReferenceIntermixing.
   */
  void AppendMedia(std::vector<vtkTetReferenceIntermixing::Medium>& media) const;

  /**
   * Whether a translucent layer fits an image of `pixels` pixels: `rgba` with 4 components
   * (premultiplied, alpha in [0, 1], finite) and `depth` window z values in [0, 1], one per
   * pixel. False with `error` otherwise.
   */
  static bool CheckLayer(
    vtkDataArray* rgba, vtkFloatArray* depth, vtkIdType pixels, std::string& error);

  /**
   * Every pixel of `rays` through `scene` into `rgba` (float or double, the other null) and
   * `counts`.
   */
  static void CastRays(const vtkTetReferenceIntermixing& scene,
    const vtkTetReferencePixelRays& rays, float* rgbaFloat, double* rgbaDouble, int* counts);

private:
  struct Prepared
  {
    vtkTetReferenceMesh Mesh;
    vtkSmartPointer<vtkTetRayIntegrator> Integrator;
    vtkVolumeProperty* Property = nullptr;
    vtkMTimeType PropertyMTime = 0;
  };
  std::vector<std::unique_ptr<Prepared>> Volumes;
  // Takes the errors of the added volumes' integrators (which have no observer of their own
  // otherwise and would print them) into IntegratorError.
  vtkSmartPointer<vtkCallbackCommand> ErrorForwarder;
  std::string IntegratorError;

  vtkTetReferenceScene(const vtkTetReferenceScene&) = delete;
  void operator=(const vtkTetReferenceScene&) = delete;
};

#endif
// VTK-HeaderTest-Exclude: vtkTetReferenceScene.h
