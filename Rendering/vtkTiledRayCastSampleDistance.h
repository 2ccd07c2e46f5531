/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkTiledRayCastSampleDistance.h

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
/**
 * @class   vtkTiledRayCastSampleDistance
 * @brief   the image sample distance of each frame: fixed, or fitted to the allocated time
 *
 * vtkTiledRayCastVolumeMapper's AutoAdjustSampleDistances. A frame's cost grows with its rays,
 * so a frame rendered at sample distance d in t seconds predicts t d^2 seconds at distance 1;
 * the distance of the next frame is the one whose predicted time fits the time the renderer
 * allocated the volume, within the user's bounds. The prediction follows the measured frames
 * with a running mean (half old, half new), so one slow frame does not make the next one coarse
 * and the distance does not swing from frame to frame. Nothing is predicted before the first
 * measured frame: that frame uses the minimum distance. GL-free. Private to the module.
 */

#ifndef vtkTiledRayCastSampleDistance_h
#define vtkTiledRayCastSampleDistance_h

class vtkTiledRayCastSampleDistance
{
public:
  /**
   * The distance for the next frame: `fixed` when not adjusting, otherwise the fitted one.
   * Distances below 1 are 1 (no supersampling); the bounds are sorted if given in the wrong
   * order.
   */
  double Choose(bool adjust, double fixed, double minimum, double maximum,
    double allocatedSeconds) const;

  /**
   * A frame rendered at sample distance `distance` took `seconds`.
   */
  void Measured(double distance, double seconds);

  /// Forget what was measured (a new mesh, a new window).
  void Reset() { this->FullFrameSeconds = -1.0; }

  /// The predicted time of a frame at distance 1, or -1 before any measure.
  double GetFullFrameSeconds() const { return this->FullFrameSeconds; }

  /**
   * The size in rays of a viewport of `width` x `height` pixels at distance `distance` (at
   * least one ray each way).
   */
  static void ComputeImageSize(int width, int height, double distance, int size[2]);

private:
  double FullFrameSeconds = -1.0;
};

#endif
// VTK-HeaderTest-Exclude: vtkTiledRayCastSampleDistance.h
