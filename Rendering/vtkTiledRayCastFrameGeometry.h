/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkTiledRayCastFrameGeometry.h

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
/**
 * @class   vtkTiledRayCastFrameGeometry
 * @brief   how a frame's pixels map to rays in the mesh's coordinates
 *
 * Computed once per frame on the CPU, in double precision, from the renderer's camera, the
 * volume's matrix and the shift of the GPU layout's coordinates; handed to the shaders as
 * float uniforms (vtkTiledRayCastCommonFS.glsl). A pixel's ray is
 * x(lambda) = origin + lambda * dir, both affine in the pixel's NDC position: value = v0 + ndc.x
 * * vx + ndc.y * vy for RayOrigin, RayDir, WNear and WFar (rows 0, 1, 2). lambda = mu - mu_c,
 * mu running from 0 on the near plane to 1 on the far plane and mu_c the plane through the
 * mesh's centre, so that lambda stays small where the mesh is. VTK's camera matrices are
 * row-major and applied on the left; vtkVolume::GetMatrix() maps object to world coordinates.
 *
 * No OpenGL. Private to the module: not wrapped, not installed.
 */

#ifndef vtkTiledRayCastFrameGeometry_h
#define vtkTiledRayCastFrameGeometry_h

class vtkPlaneCollection;
class vtkRenderer;
class vtkVolume;

class vtkTiledRayCastFrameGeometry
{
public:
  /**
   * Fills every member for this renderer's active camera and aspect ratio and this volume's
   * matrix. shift: what the GPU layout subtracted from the mesh's points; meshBounds: the
   * mesh's bounds in those shifted coordinates. Returns Valid: false when the matrices give no
   * finite rays (a singular camera or volume matrix).
   */
  bool Compute(
    vtkRenderer* renderer, vtkVolume* volume, const double shift[3], const double meshBounds[6]);

  /**
   * The mapper's clipping planes (world coordinates, VTK's: the side a plane's normal points to
   * is kept) in shifted object coordinates, normalised, for the volume's matrix of the last
   * Compute(): at most MaximumClippingPlanes. Call after Compute(). Returns false when there are
   * more planes (the first MaximumClippingPlanes are kept). ClippedAway: the mesh's bounds lie
   * wholly on the removed side of a plane, so nothing is left to draw.
   */
  bool ComputeClippingPlanes(vtkPlaneCollection* planes, const double meshBounds[6]);
  static constexpr int MaximumClippingPlanes = 6;
  int NumberOfClippingPlanes = 0;
  float ClippingPlanes[MaximumClippingPlanes][4] = {}; // n.x + d >= 0 is kept
  bool ClippedAway = false;

  float RayOrigin[3][3] = {};
  float RayDir[3][3] = {};
  float WNear[3] = {};            // clip-space w of the rays' near-plane points
  float WFar[3] = {};             // and of their far-plane points
  float LambdaNear = 0;           // lambda of the near plane (-mu_c)
  float ObjectToWorld[9] = {};    // column-major linear part of the volume's matrix
  double ObjectToWorldNorm = 1;   // its Frobenius norm: bounds how much it stretches lengths
  float ObjectToClip[16] = {};    // column-major, shifted object coordinates to clip
  double ShiftedObjectToWorld[16] = {}; // row-major, the volume's matrix after the shift
  float NearPlane[4] = {};        // n.x + d, positive beyond the near plane
  bool NearPlaneCutsMesh = false; // the camera may be inside the mesh
  // The fraction of the viewport that the mesh's bounds cover on screen (1 when they reach
  // behind the eye), and the view direction in object coordinates (NearPlane's normal): what
  // tells a camera jump from a camera move.
  double BoundsCoverage = 0;
  bool Mirrored = false;          // the volume's matrix reverses orientation
  bool Valid = false;

private:
  double ComputeBoundsCoverage(const double meshBounds[6]) const;
};

#endif
// VTK-HeaderTest-Exclude: vtkTiledRayCastFrameGeometry.h
