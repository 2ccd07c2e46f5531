/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkTetReferencePixelRays.h

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
/**
 * @class   vtkTetReferencePixelRays
 * @brief   private: vtkTetReferenceRenderer's camera rays, one through each pixel
 *
 * The ray of pixel (i, j) runs from the near plane (NDC z = -1) to the far plane (+1) of the
 * camera's composite projection through the pixel's sample position (docs/design.md), as
 * origin + lambda d, lambda in [0, 1]. The opaque depth and the clipping planes cut the part of
 * it that volumes are seen on. Get() gives the ray in one prepared mesh's frame (world
 * coordinates minus its centre), measured from its point nearest that centre; GetWorld() gives
 * it in world coordinates, for scenes of several meshes and translucent layers, each mesh then
 * placing the ray in its own frame (vtkTetReferenceIntermixing).
 */

#ifndef vtkTetReferencePixelRays_h
#define vtkTetReferencePixelRays_h

#include <array>  // For std::array
#include <vector> // For std::vector

class vtkCamera;
class vtkPlaneCollection;

class vtkTetReferencePixelRays
{
public:
  int Width = 0, Height = 0;
  double OffsetX = 0.5, OffsetY = 0.5;
  const float* Depth = nullptr; // the opaque depth, Width x Height window z values, or null
  double Inverse[16];           // clip coordinates to world coordinates
  // Subtracted from every point Get() gives (a prepared mesh's centre); null in GetWorld().
  const double* Center = nullptr;

  /**
   * Every member for `camera`'s rays through the pixels of a width x height image, sampled at
   * `offset` in each pixel, ending at `depth` (or null), in the frame of `center` (or null:
   * world coordinates), cut by `planes` (or null).
   */
  void SetUp(vtkCamera* camera, int width, int height, const double offset[2], const float* depth,
    const double* center, vtkPlaneCollection* planes);

  /**
   * The clipping planes (world coordinates, the side the normal points to kept), in the frame of
   * Center (world coordinates where it is null); call after Center is set.
   */
  void SetClippingPlanes(vtkPlaneCollection* planes);

  /**
   * The ray of pixel (i, j) in the frame of Center: origin + z d for z in (zmin, zmax), origin
   * its point nearest Center. False for a pixel with no ray (a degenerate direction, opaque
   * geometry at the near plane, or clipped away).
   */
  bool Get(int i, int j, double origin[3], double d[3], double& zmin, double& zmax) const;

  /**
   * The ray of pixel (i, j) in world coordinates: nearP + lambda d, lambda in [0, 1] from the
   * near to the far plane. Volumes are seen for lambda in (volumeMin, volumeMax): `volumes` is
   * false when the opaque depth or the clipping planes leave nothing of the ray for them.
   * Returns false when the pixel has no ray at all (a degenerate direction). Needs a null
   * Center.
   */
  bool GetWorld(int i, int j, double nearP[3], double d[3], double& volumeMin, double& volumeMax,
    bool& volumes) const;

  /**
   * The ray parameter lambda (as GetWorld()) at window depth z on the ray of pixel (i, j).
   */
  double LambdaAtDepth(int i, int j, const double nearP[3], const double d[3], double z) const;

private:
  // Clipping planes in the rays' frame, (n, d) with n.x + d >= 0 kept.
  std::vector<std::array<double, 4>> Clipping;

  void Unproject(double x, double y, double z, double p[3]) const;
  // Pixel (i, j)'s NDC position (x, y), its near-plane point and direction d (far minus near
  // point), dd = |d|^2; false for a degenerate direction.
  bool Direction(
    int i, int j, double& x, double& y, double nearP[3], double d[3], double& dd) const;
  // The part (lambdaMin, lambdaMax) of the ray nearP + lambda d of pixel `pixel` (at NDC x, y)
  // left by the opaque depth and the clipping planes; false when nothing is left.
  bool Range(double x, double y, long long pixel, const double nearP[3], const double d[3],
    double dd, double& lambdaMin, double& lambdaMax) const;
};

#endif
// VTK-HeaderTest-Exclude: vtkTetReferencePixelRays.h
