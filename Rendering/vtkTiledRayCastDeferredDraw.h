/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkTiledRayCastDeferredDraw.h

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
/**
 * @class   vtkTiledRayCastDeferredDraw
 * @brief   draws a volume out of VTK's volumetric depth peels, once its renderer has finished
 *
 * A volume that cannot take part in VTK's dual depth peeling (vtkTiledRayCastVolumetricPeel:
 * the fragment pipeline, blend modes other than composite) draws nothing inside the peels (the
 * volume marked with a vtkDualDepthPeelingPass as a render pass), and this object renders it
 * again on the renderer's EndEvent, over the composited scene.
 *
 * Private to the module: not wrapped, not installed.
 */

#ifndef vtkTiledRayCastDeferredDraw_h
#define vtkTiledRayCastDeferredDraw_h

#include "vtkWeakPointer.h" // For vtkWeakPointer

class vtkObject;
class vtkRenderer;
class vtkUnstructuredGridVolumeMapper;
class vtkVolume;

class vtkTiledRayCastDeferredDraw
{
public:
  explicit vtkTiledRayCastDeferredDraw(vtkUnstructuredGridVolumeMapper* mapper);
  ~vtkTiledRayCastDeferredDraw();

  /**
   * Called while VTK's dual depth peeling is peeling `volume` (the mapper found its pass,
   * vtkTiledRayCastVolumetricPeel): true unless this is the deferred draw itself. The mapper's
   * Render() is then called again when `renderer` has finished its frame, and should draw
   * nothing now.
   */
  bool Defer(vtkRenderer* renderer, vtkVolume* volume);

  /**
   * No deferred draw any more (the mapper goes away).
   */
  void Stop();

  /**
   * Whether the deferred draw is drawing the volume now (its mapper's Render() called from the
   * renderer's end).
   */
  bool IsDrawing() const { return this->Drawing; }

private:
  vtkTiledRayCastDeferredDraw(const vtkTiledRayCastDeferredDraw&) = delete;
  void operator=(const vtkTiledRayCastDeferredDraw&) = delete;

  // The renderer's EndEvent.
  static void Draw(vtkObject* renderer, unsigned long, void* deferred, void*);

  vtkUnstructuredGridVolumeMapper* Mapper;
  vtkWeakPointer<vtkRenderer> Renderer;
  vtkWeakPointer<vtkVolume> Volume;
  unsigned long Observer = 0;
  bool Pending = false;
  bool Drawing = false;
};

#endif
// VTK-HeaderTest-Exclude: vtkTiledRayCastDeferredDraw.h
