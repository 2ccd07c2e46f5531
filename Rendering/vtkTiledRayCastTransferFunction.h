/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkTiledRayCastTransferFunction.h

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
/**
 * @class   vtkTiledRayCastTransferFunction
 * @brief   a volume property's transfer functions as the GPU integrates them
 *
 * Turns the first component of a vtkVolumeProperty into a sorted list of nodes
 * (scalar, colour, attenuation) between which colour and attenuation are linear, the form the
 * mapper's shaders split segments at (partial pre-integration) and that its pre-integration
 * tables are computed from. Attenuation is opacity divided by the scalar opacity unit distance,
 * per world unit (VTK's unstructured-grid convention, docs/design.md).
 *
 * The list is **exact** when the transfer functions are piecewise linear: every node of the
 * opacity and colour functions with midpoint 0.5 and sharpness 0, colour interpolated in RGB,
 * linear scale, no above/below-range colours (the common case, and what VTK's own partial
 * pre-integration assumes). Clamping off is exact too: a function drops to zero at its range
 * ends, stored as two nodes at the same scalar (left and right values). Any other transfer
 * function (midpoints, sharpness, HSV/Lab/diverging/step colour spaces, log scale,
 * above/below-range colours) is evaluated through VTK's own GetValue()/GetColor() and
 * linearised adaptively until linear interpolation is within Tolerance of it everywhere
 * sampled (colour in [0,1] units; attenuation relative to its largest value), with at most
 * MaximumNumberOfNodes nodes; GetExact() then returns false. A discretized colour map
 * (vtkDiscretizableColorTransferFunction with Discretize on, linear scale: ParaView's default)
 * is piecewise constant and is exact too, with a node pair at each of its steps, whatever its
 * colour space, as long as the opacity function is piecewise linear.
 *
 * Rebuilt by Update() only when the property, one of its functions, or the scalar range
 * changed.
 */

#ifndef vtkTiledRayCastTransferFunction_h
#define vtkTiledRayCastTransferFunction_h

#include "vtkObject.h"
#include "vtkRenderingTiledRayCastModule.h" // For export macro

#include <vector> // For std::vector

class vtkVolumeProperty;

class VTKRENDERINGTILEDRAYCAST_EXPORT vtkTiledRayCastTransferFunction : public vtkObject
{
public:
  static vtkTiledRayCastTransferFunction* New();
  vtkTypeMacro(vtkTiledRayCastTransferFunction, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * Rebuild the node list from the property's first component if the property, its transfer
   * functions or the scalar range changed since the last call. The scalar range (of the data)
   * bounds the adaptive linearisation. Returns true when the node list changed.
   */
  bool Update(vtkVolumeProperty* property, const double scalarRange[2]);

  ///@{
  /**
   * Tolerance of the linearisation of transfer functions that are not piecewise linear, and
   * the largest number of nodes it may produce. Defaults 1e-3 and 4096.
   */
  vtkSetClampMacro(Tolerance, double, 1e-9, 1.0);
  vtkGetMacro(Tolerance, double);
  vtkSetClampMacro(MaximumNumberOfNodes, int, 2, 1 << 20);
  vtkGetMacro(MaximumNumberOfNodes, int);
  ///@}

  /**
   * True when the node list represents the transfer functions exactly.
   */
  vtkGetMacro(Exact, bool);

  ///@{
  /**
   * The nodes, sorted by scalar. Two nodes may share a scalar (a step). Below the first node
   * and above the last, colour and attenuation are constant.
   */
  int GetNumberOfNodes() const { return static_cast<int>(this->Scalars.size()); }
  double GetNodeScalar(int i) const;
  double GetNodeAttenuation(int i) const;
  void GetNodeColor(int i, double rgb[3]) const;
  ///@}

  /**
   * Colour and attenuation at scalar s from the node list (linear between nodes).
   */
  void Evaluate(double s, double rgb[3], double& attenuation) const;

  /**
   * The largest attenuation of the list (per world unit).
   */
  vtkGetMacro(MaximumAttenuation, double);

  /**
   * The scalar opacity unit distance the attenuations were divided by (the property's, or 1 where
   * that is not positive): opacity = attenuation * UnitDistance.
   */
  vtkGetMacro(UnitDistance, double);

  /**
   * The narrowest feature: the smallest positive distance between two consecutive node scalars
   * that lie within the data's scalar range (the range width if there is none). Tables indexed
   * by scalar must be finer than this.
   */
  vtkGetMacro(NarrowestFeature, double);

#ifndef __VTK_WRAP__
  /**
   * The nodes as the shader reads them: two RGBA32F texels per node,
   * (s, attenuation, 0, 0) and (r, g, b, 0).
   */
  const std::vector<float>& GetNodeTexels() const
  {
    return this->Texels;
  }
#endif

protected:
  vtkTiledRayCastTransferFunction();
  ~vtkTiledRayCastTransferFunction() override;

  void Build(vtkVolumeProperty* property, const double scalarRange[2]);
  void AddNode(double s, const double rgb[3], double attenuation);
  // Statistics of the node list and the shader's texels, once the nodes are in place.
  void FinishBuild(const double scalarRange[2]);

  double Tolerance = 1e-3;
  int MaximumNumberOfNodes = 4096;
  bool Exact = true;
  double MaximumAttenuation = 0;
  double UnitDistance = 1;
  double NarrowestFeature = 0;
  std::vector<double> Scalars;
  std::vector<double> Colors;
  std::vector<double> Attenuations;
  std::vector<float> Texels;

  vtkVolumeProperty* LastProperty = nullptr;
  vtkMTimeType LastPropertyTime = 0;
  double LastRange[2] = { 0, 0 };

private:
  vtkTiledRayCastTransferFunction(const vtkTiledRayCastTransferFunction&) = delete;
  void operator=(const vtkTiledRayCastTransferFunction&) = delete;
};

#endif
