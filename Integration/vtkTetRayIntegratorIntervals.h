/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkTetRayIntegratorIntervals.h

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
/**
 * @class   vtkTetRayIntegratorIntervals
 * @brief   private: vtkTetRayIntegrator's set-up, the breakpoints of the transfer functions and
 *          the kind of each elementary interval between them
 *
 * The breakpoints are where the integrand may bend: the nodes of every function, the midpoints
 * of pieces that are not linear (midpoint or sharpness set, log scale), the half-way white of
 * diverging colour maps, and the kinks of HSV, Lab and diverging interpolation found from VTK's
 * own colours (FindBreaks, one step per kind of piece). Between two breakpoints an elementary
 * interval is linear (attenuation and colour linear in the scalar: closed form, the values at
 * its ends stored) or not (adaptive quadrature); BuildIntervals tells them apart, checking on
 * VTK's evaluations that a linear one really is.
 */

#ifndef vtkTetRayIntegratorIntervals_h
#define vtkTetRayIntegratorIntervals_h

#include <algorithm> // For std::upper_bound
#include <cstddef>   // For size_t
#include <vector>    // For std::vector

class vtkColorTransferFunction;
class vtkPiecewiseFunction;
class vtkTetRayIntegratorFunctions;

class vtkTetRayIntegratorIntervals
{
public:
  // Elementary interval i is (Breaks[i-1], Breaks[i]) with Breaks[-1] = -inf and
  // Breaks[n] = +inf; on a linear interval the values at its ends are stored.
  struct Interval
  {
    bool Linear = false;
    bool Bounded = false;
    double X0 = 0.0, X1 = 0.0;
    double Tau0 = 0.0, Tau1 = 0.0;
    double C0[3] = { 0.0, 0.0, 0.0 };
    double C1[3] = { 0.0, 0.0, 0.0 };
  };
  std::vector<double> Breaks;
  std::vector<Interval> Intervals;

  /**
   * The sorted breakpoints of the functions `f` (a snapshot of the property's).
   */
  void FindBreaks(const vtkTetRayIntegratorFunctions& f);

  /**
   * The elementary intervals between the breakpoints, and which of them are linear.
   */
  void BuildIntervals(vtkTetRayIntegratorFunctions& f);

  /**
   * The elementary interval that holds scalar s.
   */
  size_t IntervalIndex(double s) const;

  /**
   * Attenuation and colour at s on a linear interval.
   */
  void LinearValues(const Interval& iv, double s, double& tau, double c[3]) const;

private:
  // Node positions and per-interval linearity of one transfer function.
  struct NodeLayout
  {
    std::vector<double> X;
    std::vector<char> LinearPiece; // piece k is [X[k], X[k+1]]

    // Whether the function is linear on an open elementary interval that contains x (x strictly
    // between two consecutive breakpoints, so never equal to a node).
    bool LinearAt(double x) const
    {
      if (this->X.size() < 2 || x < this->X.front() || x > this->X.back())
      {
        return true; // constant outside the node range (clamped or zero)
      }
      const size_t k = std::upper_bound(this->X.begin(), this->X.end(), x) - this->X.begin();
      return this->LinearPiece[k - 1] != 0;
    }
  };

  NodeLayout ColorLayout;
  NodeLayout OpacityLayout;

  void AddPiecewiseNodes(vtkPiecewiseFunction* f, NodeLayout& layout);
  void AddColorNodes(vtkColorTransferFunction* f);
  void AddColorKinks(vtkColorTransferFunction* f);
  void SetLinearValues(vtkTetRayIntegratorFunctions& f, Interval& iv, double probe);
};

#endif
// VTK-HeaderTest-Exclude: vtkTetRayIntegratorIntervals.h
