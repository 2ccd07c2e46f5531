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
 *
 * Where several media overlap (vtkTetRayIntegratorMixture), a piece is integrated for their sum:
 * attenuation sum(tau_i), emission sum(tau_i c_i). IntegrateLinearMixture is the closed form
 * where every medium is linear, IntegrateAdaptiveMixture the adaptive quadrature of the sums
 * elsewhere (the same panels, estimates and tolerance as a single medium's).
 */

#ifndef vtkTetRayIntegratorQuadrature_h
#define vtkTetRayIntegratorQuadrature_h

#include "vtkType.h" // For vtkIdType

#include <atomic> // For std::atomic
#include <vector> // For std::vector

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

  /**
   * One medium of a mixture along a piece: its functions (a thread's copy) and its scalar, going
   * linearly from S0 at the piece's start to S1 at its end.
   */
  struct Medium
  {
    vtkTetRayIntegratorFunctions* Functions = nullptr;
    double S0 = 0.0, S1 = 0.0;
  };

  /**
   * Closed form for a mixture on a piece of length len where every medium i has linear
   * attenuation (tau0[i] to tau1[i]) and colour (c0[i] to c1[i]): the emission
   * sum(tau_i c_i) times the transmittance of sum(tau_i), integrated by 12-point Gauss-Legendre
   * on panels of optical depth <= 2 (the integrand is positive: no cancellation).
   */
  static PieceResult IntegrateLinearMixture(double len, const std::vector<double>& tau0,
    const std::vector<double>& tau1, const std::vector<double>& c0, const std::vector<double>& c1);

  /**
   * Adaptive quadrature of the mixture `media` along a piece of length len, seen through
   * `transmittance`, to `tolerance` (as IntegrateAdaptive).
   */
  static PieceResult IntegrateAdaptiveMixture(const std::vector<Medium>& media, double len,
    double transmittance, double tolerance, std::atomic<vtkIdType>& unconverged);

private:
  // Panel, EstimateRoundingNoise and Adapt work on an evaluator of the attenuation and colour
  // along the piece (one medium, or a mixture's sums): see the .cxx.
  template <typename Evaluator>
  static PieceResult Panel(Evaluator& f, double len, double a, double b);
  template <typename Evaluator>
  static void EstimateRoundingNoise(const Evaluator& f, const double tau[], const double c[][3],
    double len, double a, double b, PieceResult& r);
  template <typename Evaluator>
  static PieceResult Adapt(Evaluator& f, double len, double a, double b, const PieceResult& coarse,
    double transmittance, double tolerance, int level, std::atomic<vtkIdType>& unconverged);
};

#endif
// VTK-HeaderTest-Exclude: vtkTetRayIntegratorQuadrature.h
