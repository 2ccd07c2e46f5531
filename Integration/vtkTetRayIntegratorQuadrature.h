/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkTetRayIntegratorQuadrature.h

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
/**
 * @class   vtkTetRayIntegratorQuadrature
 * @brief   private: vtkTetRayIntegrator's integration of one piece of a segment, by piece kind
 *
 * A segment's scalar range is cut at the transfer functions' breakpoints into pieces
 * (vtkTetRayIntegratorIntervals); each is integrated by the rule for its kind:
 * IntegrateLinear in closed form where attenuation and colour are linear in the scalar
 * (Gauss-Legendre panels of bounded optical depth, see vtkTetRayIntegrator.h), IntegrateAdaptive
 * by adaptive Gauss-Legendre quadrature of VTK's own evaluations everywhere else.
 */

#ifndef vtkTetRayIntegratorQuadrature_h
#define vtkTetRayIntegratorQuadrature_h

#include "vtkType.h" // For vtkIdType

#include <atomic> // For std::atomic

class vtkTetRayIntegratorFunctions;

class vtkTetRayIntegratorQuadrature
{
public:
  /**
   * Beyond this optical depth the transmittance (< 4.3e-18) no longer changes a double result.
   */
  static constexpr double CutOffDepth = 40.0;

  /**
   * What a piece contributes: its optical depth and premultiplied colour.
   */
  struct PieceResult
  {
    double Depth = 0.0;
    double C[3] = { 0.0, 0.0, 0.0 };
    // Adaptive panels: an estimate of the integration error from how well the samples resolve
    // the attenuation and the emitted light (see Panel()).
    double Unresolved = 0.0;
    // Adaptive panels: the part of such estimates that rounding the samples' scalars to doubles
    // alone can cause (see EstimateRoundingNoise()); bisection cannot reduce an error below it.
    double Noise = 0.0;
  };

  /**
   * A piece followed by another: depths add, the second one is seen through the first.
   */
  static PieceResult Combine(const PieceResult& front, const PieceResult& back);

  /**
   * Closed form on a piece of length len where tau and c are linear.
   */
  static PieceResult IntegrateLinear(
    double len, double tau0, double tau1, const double c0[3], const double c1[3]);

  /**
   * Adaptive quadrature of the functions `f` along a piece of length len where the scalar goes
   * linearly from sa to sb, seen through `transmittance`, to `tolerance`; panels that do not
   * converge are counted in `unconverged`.
   */
  static PieceResult IntegrateAdaptive(vtkTetRayIntegratorFunctions& f, double sa, double sb,
    double len, double transmittance, double tolerance, std::atomic<vtkIdType>& unconverged);

private:
  static PieceResult Panel(
    vtkTetRayIntegratorFunctions& f, double sa, double sb, double len, double a, double b);
  static void EstimateRoundingNoise(const double tau[], const double c[][3], double sa, double sb,
    double len, double a, double b, PieceResult& r);
  static PieceResult Adapt(vtkTetRayIntegratorFunctions& f, double sa, double sb, double len,
    double a, double b, const PieceResult& coarse, double transmittance, double tolerance,
    int level, std::atomic<vtkIdType>& unconverged);
};

#endif
// VTK-HeaderTest-Exclude: vtkTetRayIntegratorQuadrature.h
