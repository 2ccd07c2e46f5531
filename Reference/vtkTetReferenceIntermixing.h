/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkTetReferenceIntermixing.h

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
/**
 * @class   vtkTetReferenceIntermixing
 * @brief   private: vtkTetReferenceRenderer's rays through several volumes and translucent
 *          layers, composited in depth order
 *
 * A scene of several prepared meshes (each with its own integrator: transfer functions, unit
 * distance) and translucent layers (one premultiplied RGBA fragment per pixel at a window depth).
 * Per ray: each mesh gives the tetrahedra the ray crosses (vtkTetReferenceRayCaster, in the
 * mesh's own frame), their intervals are moved to one ray parameter shared by all, and the ray
 * is cut at every interval end and every fragment. Between two cuts the set of media is constant:
 * one medium is integrated by its integrator, several by vtkTetRayIntegrator::IntegrateMixture
 * (sum of the attenuations, emission sum(tau_i c_i)); fragments are composited where they lie.
 * Everything is composited front to back in exact optical depth (a fragment of opacity a adds
 * -log(1 - a)). Overlapping tetrahedra of one mesh are media like any other here (summed), where
 * a single volume's rays (vtkTetReferenceCompositing) composite them in order of entry.
 */

#ifndef vtkTetReferenceIntermixing_h
#define vtkTetReferenceIntermixing_h

#include "vtkTetReferenceRayCaster.h" // For vtkTetReferenceRayCaster::Hit

#include <vector> // For std::vector

class vtkTetRayIntegrator;
class vtkTetReferenceMesh;
class vtkTetReferencePixelRays;

class vtkTetReferenceIntermixing
{
public:
  struct Medium
  {
    const vtkTetReferenceMesh* Mesh = nullptr;
    vtkTetRayIntegrator* Integrator = nullptr;
  };
  struct Layer
  {
    std::vector<double> RGBA;     // premultiplied, 4 per pixel
    const float* Depth = nullptr; // window z per pixel; 1 means no fragment
  };

  // An interval of one medium along the ray (shared ray parameter) with its end scalars.
  struct Segment
  {
    double T0, T1, S0, S1;
    int Medium;
  };
  // A translucent fragment at ray parameter T; Layer orders fragments at the same depth.
  struct Fragment
  {
    double T;
    const double* RGBA;
    int Layer;
  };
  // Per-thread work space of CastRay().
  struct Scratch
  {
    std::vector<vtkTetReferenceRayCaster::Hit> Hits;
    std::vector<Segment> Segments;
    std::vector<Fragment> Fragments;
    std::vector<double> Cuts;
    std::vector<int> Active;
    std::vector<vtkTetRayIntegrator*> Integrators;
    std::vector<double> Front, Back;
  };

  std::vector<Medium> Media;
  std::vector<Layer> Layers;
  double Reference[3] = { 0.0, 0.0, 0.0 }; // a world point near the media (the rays' origin)

  /**
   * Set Reference to the centre of the media's bounds (call once the media are set).
   */
  void SetReference();

  /**
   * The premultiplied RGBA of pixel (i, j) of `rays` (world coordinates: null Center), and the
   * number of tetrahedra its ray crossed (all media).
   */
  void CastRay(const vtkTetReferencePixelRays& rays, int i, int j, Scratch& scratch, double rgba[4],
    int& count) const;

  /**
   * Front-to-back compositing of `segments` and `fragments` (any order; both are sorted here)
   * into premultiplied RGBA; `unitLength` is the world length of a unit of the ray parameter.
   */
  void Composite(Scratch& scratch, double unitLength, double rgba[4]) const;

private:
  void CollectFragments(const vtkTetReferencePixelRays& rays, int i, int j, const double nearP[3],
    const double d[3], double lambdaRef, Scratch& scratch) const;
  void IntegrateInterval(Scratch& scratch, double e0, double e1, double unitLength,
    double segment[4], double& depth) const;
};

#endif
// VTK-HeaderTest-Exclude: vtkTetReferenceIntermixing.h
