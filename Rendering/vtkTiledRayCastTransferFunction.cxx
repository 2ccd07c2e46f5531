/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkTiledRayCastTransferFunction.cxx

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "vtkTiledRayCastTransferFunction.h"

#include "vtkTetMesh.h"

#include "vtkColorTransferFunction.h"
#include "vtkDiscretizableColorTransferFunction.h"
#include "vtkObjectFactory.h"
#include "vtkPiecewiseFunction.h"
#include "vtkVolumeProperty.h"

#include <algorithm>
#include <cmath>
#include <limits>

vtkStandardNewMacro(vtkTiledRayCastTransferFunction);

namespace
{
// The first component's functions of a volume property, evaluated with VTK's own semantics.
struct PropertyFunctions
{
  vtkPiecewiseFunction* Opacity = nullptr;
  vtkColorTransferFunction* Color = nullptr; // RGB colour, or
  vtkPiecewiseFunction* Gray = nullptr;      // gray colour
  double UnitDistance = 1.0;

  explicit PropertyFunctions(vtkVolumeProperty* property)
  {
    this->Opacity = property->GetScalarOpacity(0);
    if (property->GetColorChannels(0) == 1)
    {
      this->Gray = property->GetGrayTransferFunction(0);
    }
    else
    {
      this->Color = property->GetRGBTransferFunction(0);
    }
    this->UnitDistance = property->GetScalarOpacityUnitDistance(0);
  }

  vtkMTimeType GetMTime() const
  {
    vtkMTimeType t = this->Opacity->GetMTime();
    t = std::max(t, this->Color ? this->Color->GetMTime() : this->Gray->GetMTime());
    return t;
  }

  // Scalars of every node of both functions.
  void CollectNodeScalars(std::vector<double>& scalars) const
  {
    double node[6];
    for (int i = 0; i < this->Opacity->GetSize(); ++i)
    {
      this->Opacity->GetNodeValue(i, node);
      scalars.push_back(node[0]);
    }
    if (this->Color)
    {
      for (int i = 0; i < this->Color->GetSize(); ++i)
      {
        this->Color->GetNodeValue(i, node);
        scalars.push_back(node[0]);
      }
    }
    else
    {
      for (int i = 0; i < this->Gray->GetSize(); ++i)
      {
        this->Gray->GetNodeValue(i, node);
        scalars.push_back(node[0]);
      }
    }
  }

  static bool IsLinear(vtkPiecewiseFunction* f)
  {
    double node[4];
    for (int i = 0; i < f->GetSize(); ++i)
    {
      f->GetNodeValue(i, node);
      if (node[2] != 0.5 || node[3] != 0.0)
      {
        return false;
      }
    }
    return true;
  }

  // True when colour and opacity are linear between nodes, so that the nodes alone describe
  // them exactly.
  bool IsPiecewiseLinear() const
  {
    if (!IsLinear(this->Opacity))
    {
      return false;
    }
    if (this->Gray)
    {
      return IsLinear(this->Gray);
    }
    if (this->Color->GetColorSpace() != VTK_CTF_RGB || this->Color->GetScale() != VTK_CTF_LINEAR ||
      this->Color->GetUseAboveRangeColor() || this->Color->GetUseBelowRangeColor())
    {
      return false;
    }
    double node[6];
    for (int i = 0; i < this->Color->GetSize(); ++i)
    {
      this->Color->GetNodeValue(i, node);
      if (node[4] != 0.5 || node[5] != 0.0)
      {
        return false;
      }
    }
    return true;
  }

  // A function that does not clamp is zero outside its node range: at either end of the range,
  // the side facing outwards takes the value zero.
  static bool IsOutside(double s, int side, bool clamping, const double range[2], int size)
  {
    if (clamping || size == 0)
    {
      return false;
    }
    return (s == range[0] && side < 0) || (s == range[1] && side > 0);
  }

  // Colour and attenuation at s; side -1/+1 selects the left/right limit at a discontinuity.
  void Evaluate(double s, int side, double rgb[3], double& attenuation) const
  {
    double range[2];
    this->Opacity->GetRange(range);
    double opacity =
      IsOutside(s, side, this->Opacity->GetClamping() != 0, range, this->Opacity->GetSize())
      ? 0.0
      : this->Opacity->GetValue(s);
    attenuation = std::max(opacity, 0.0) / this->UnitDistance;
    if (this->Color)
    {
      this->Color->GetRange(range);
      if (IsOutside(s, side, this->Color->GetClamping() != 0, range, this->Color->GetSize()))
      {
        rgb[0] = rgb[1] = rgb[2] = 0.0;
      }
      else
      {
        this->Color->GetColor(s, rgb);
      }
    }
    else
    {
      this->Gray->GetRange(range);
      const double g =
        IsOutside(s, side, this->Gray->GetClamping() != 0, range, this->Gray->GetSize())
        ? 0.0
        : this->Gray->GetValue(s);
      rgb[0] = rgb[1] = rgb[2] = g;
    }
  }
};

// A discretized colour map (vtkDiscretizableColorTransferFunction with Discretize on, the
// default of ParaView's colour maps) is piecewise constant: NumberOfValues equal steps across
// its node range, constant beyond. With an opacity function linear between its nodes, nodes at
// every step and opacity node, each with its left and right values, represent both exactly;
// linearising the steps instead would need thousands of nodes and still be approximate. Each
// step's colour is VTK's own (GetColor inside the step), and the steps are checked to be
// constant where they are assumed to be (a scale or lookup this does not model is left to the
// general linearisation). Fills the node lists and returns true, or returns false and leaves
// them empty.
bool BuildDiscretizedNodes(const PropertyFunctions& functions, int maxNodes,
  std::vector<double>& scalars, std::vector<double>& colors, std::vector<double>& attenuations)
{
  auto* map = vtkDiscretizableColorTransferFunction::SafeDownCast(functions.Color);
  if (!map || !map->GetDiscretize() || map->GetIndexedLookup() ||
    map->GetScale() != VTK_CTF_LINEAR || !PropertyFunctions::IsLinear(functions.Opacity) ||
    map->GetSize() == 0)
  {
    return false;
  }
  map->Build(); // the lookup table GetColor reads, if the map changed since it was built
  const int steps = map->GetNumberOfValues();
  double range[2];
  map->GetRange(range);
  if (steps < 1 || !(range[1] > range[0]))
  {
    return false;
  }
  std::vector<double> breaks;
  for (int k = 0; k <= steps; ++k)
  {
    breaks.push_back(range[0] + (range[1] - range[0]) * k / steps);
  }
  double node[4];
  for (int i = 0; i < functions.Opacity->GetSize(); ++i)
  {
    functions.Opacity->GetNodeValue(i, node);
    breaks.push_back(node[0]);
  }
  std::sort(breaks.begin(), breaks.end());
  breaks.erase(std::unique(breaks.begin(), breaks.end()), breaks.end());
  if (2 * static_cast<int>(breaks.size()) > maxNodes)
  {
    return false;
  }

  // The colour of each interval between breaks (and beyond both ends), checked constant.
  const size_t n = breaks.size();
  const double margin = range[1] - range[0];
  std::vector<double> interval(3 * (n + 1));
  for (size_t i = 0; i <= n; ++i)
  {
    const double a = i == 0 ? breaks.front() - margin : breaks[i - 1];
    const double b = i == n ? breaks.back() + margin : breaks[i];
    map->GetColor(0.5 * (a + b), &interval[3 * i]);
    for (double q : { 0.125, 0.875 })
    {
      double rgb[3];
      map->GetColor(a + q * (b - a), rgb);
      if (rgb[0] != interval[3 * i] || rgb[1] != interval[3 * i + 1] ||
        rgb[2] != interval[3 * i + 2])
      {
        return false;
      }
    }
  }

  for (size_t i = 0; i < n; ++i)
  {
    double left[4], right[4];
    functions.Evaluate(breaks[i], -1, left, left[3]);
    functions.Evaluate(breaks[i], +1, right, right[3]);
    const double* colorLeft = &interval[3 * i];
    const double* colorRight = &interval[3 * (i + 1)];
    scalars.push_back(breaks[i]);
    colors.insert(colors.end(), colorLeft, colorLeft + 3);
    attenuations.push_back(left[3]);
    if (right[3] != left[3] || !std::equal(colorLeft, colorLeft + 3, colorRight))
    {
      scalars.push_back(breaks[i]);
      colors.insert(colors.end(), colorRight, colorRight + 3);
      attenuations.push_back(right[3]);
    }
  }
  return true;
}

// Largest difference between two (colour, attenuation) values, attenuation relative to scale.
double Difference(const double a[4], const double b[4], double attenuationScale)
{
  double d = std::abs(a[3] - b[3]) / attenuationScale;
  for (int c = 0; c < 3; ++c)
  {
    d = std::max(d, std::abs(a[c] - b[c]));
  }
  return d;
}
}

//------------------------------------------------------------------------------
vtkTiledRayCastTransferFunction::vtkTiledRayCastTransferFunction() = default;

//------------------------------------------------------------------------------
vtkTiledRayCastTransferFunction::~vtkTiledRayCastTransferFunction() = default;

//------------------------------------------------------------------------------
bool vtkTiledRayCastTransferFunction::Update(
  vtkVolumeProperty* property, const double scalarRange[2])
{
  if (!property)
  {
    vtkErrorMacro("No volume property.");
    return false;
  }
  PropertyFunctions functions(property);
  const vtkMTimeType t = std::max(property->GetMTime(), functions.GetMTime());
  if (property == this->LastProperty && t == this->LastPropertyTime &&
    scalarRange[0] == this->LastRange[0] && scalarRange[1] == this->LastRange[1] &&
    !this->Scalars.empty())
  {
    return false;
  }
  this->Build(property, scalarRange);
  this->LastProperty = property;
  this->LastPropertyTime = t;
  this->LastRange[0] = scalarRange[0];
  this->LastRange[1] = scalarRange[1];
  this->Modified();
  return true;
}

//------------------------------------------------------------------------------
void vtkTiledRayCastTransferFunction::AddNode(double s, const double rgb[3], double attenuation)
{
  this->Scalars.push_back(s);
  this->Colors.insert(this->Colors.end(), rgb, rgb + 3);
  this->Attenuations.push_back(attenuation);
}

//------------------------------------------------------------------------------
void vtkTiledRayCastTransferFunction::Build(
  vtkVolumeProperty* property, const double scalarRange[2])
{
  this->Scalars.clear();
  this->Colors.clear();
  this->Attenuations.clear();

  PropertyFunctions functions(property);
  if (!(functions.UnitDistance > 0.0))
  {
    vtkWarningMacro(
      "Scalar opacity unit distance " << functions.UnitDistance << " is not positive: using 1.");
    functions.UnitDistance = 1.0;
  }
  this->UnitDistance = functions.UnitDistance;
  this->Exact = functions.IsPiecewiseLinear();
  if (!this->Exact &&
    BuildDiscretizedNodes(
      functions, this->MaximumNumberOfNodes, this->Scalars, this->Colors, this->Attenuations))
  {
    this->Exact = true;
    this->FinishBuild(scalarRange);
    return;
  }

  std::vector<double> breaks;
  functions.CollectNodeScalars(breaks);
  std::sort(breaks.begin(), breaks.end());
  breaks.erase(std::unique(breaks.begin(), breaks.end()), breaks.end());
  if (breaks.empty())
  {
    // No node at all: VTK's functions are then constant (zero).
    breaks.push_back(scalarRange[0]);
  }

  // Attenuation scale for the linearisation tolerance.
  double attenuationScale = 0.0;
  for (double s : breaks)
  {
    double rgb[3], tau;
    functions.Evaluate(s, 0, rgb, tau);
    attenuationScale = std::max(attenuationScale, tau);
  }
  if (!this->Exact)
  {
    // Sample across the data's range too: between or beyond nodes the function may peak.
    const double lo = std::min(scalarRange[0], breaks.front());
    const double hi = std::max(scalarRange[1], breaks.back());
    for (int i = 0; i <= 256; ++i)
    {
      double rgb[3], tau;
      functions.Evaluate(lo + (hi - lo) * i / 256.0, 0, rgb, tau);
      attenuationScale = std::max(attenuationScale, tau);
    }
  }
  if (!(attenuationScale > 0.0))
  {
    attenuationScale = 1.0;
  }

  // Each break contributes its left and right values (one node when they agree); between two
  // breaks the functions are linear (exact case) or linearised by bisection.
  const int maxNodes = this->MaximumNumberOfNodes;
  const double tolerance = this->Tolerance;
  struct Interval
  {
    double A, B;
    double FA[4], FB[4];
    int Depth;
  };
  std::vector<Interval> stack;
  for (size_t k = 0; k < breaks.size(); ++k)
  {
    const double s = breaks[k];
    double left[4], right[4];
    functions.Evaluate(s, -1, left, left[3]);
    functions.Evaluate(s, +1, right, right[3]);
    if (k > 0 && !this->Exact)
    {
      // Linearise (breaks[k-1], s) between the previous node's right value and our left one.
      const double a = breaks[k - 1];
      Interval first;
      first.A = a;
      first.B = s;
      std::copy(this->Colors.end() - 3, this->Colors.end(), first.FA);
      first.FA[3] = this->Attenuations.back();
      std::copy(left, left + 4, first.FB);
      first.Depth = 0;
      // Depth-first in increasing s: nodes are appended in order.
      stack.clear();
      stack.push_back(first);
      const double minWidth = 1e-9 * std::max(1.0, std::abs(s - a));
      while (!stack.empty())
      {
        Interval iv = stack.back();
        stack.pop_back();
        // Test the midpoint and the quarter points so that a narrow bump is not missed.
        bool split = false;
        if (static_cast<int>(this->Scalars.size()) < maxNodes - 2 && iv.B - iv.A > minWidth &&
          iv.Depth < 40)
        {
          for (double q : { 0.25, 0.5, 0.75 })
          {
            double f[4], lin[4];
            functions.Evaluate(iv.A + q * (iv.B - iv.A), 0, f, f[3]);
            for (int c = 0; c < 4; ++c)
            {
              lin[c] = iv.FA[c] + q * (iv.FB[c] - iv.FA[c]);
            }
            if (Difference(f, lin, attenuationScale) > tolerance)
            {
              split = true;
              break;
            }
          }
        }
        if (split)
        {
          Interval lower = iv, upper = iv;
          const double m = 0.5 * (iv.A + iv.B);
          double fm[4];
          functions.Evaluate(m, 0, fm, fm[3]);
          lower.B = upper.A = m;
          std::copy(fm, fm + 4, lower.FB);
          std::copy(fm, fm + 4, upper.FA);
          lower.Depth = upper.Depth = iv.Depth + 1;
          stack.push_back(upper); // popped after lower: increasing order
          stack.push_back(lower);
        }
        else if (iv.B < s)
        {
          this->AddNode(iv.B, iv.FB, iv.FB[3]);
        }
      }
    }
    this->AddNode(s, left, left[3]);
    if (Difference(left, right, attenuationScale) > 0.0)
    {
      this->AddNode(s, right, right[3]);
    }
  }
  if (!this->Exact && static_cast<int>(this->Scalars.size()) >= maxNodes - 2)
  {
    vtkWarningMacro("The transfer function needs more than " << maxNodes
                                                             << " linear pieces to be represented "
                                                                "within the tolerance "
                                                             << tolerance << ".");
  }
  this->FinishBuild(scalarRange);
}

//------------------------------------------------------------------------------
void vtkTiledRayCastTransferFunction::FinishBuild(const double scalarRange[2])
{

  // Statistics and the shader's texels.
  this->MaximumAttenuation = 0.0;
  for (double tau : this->Attenuations)
  {
    this->MaximumAttenuation = std::max(this->MaximumAttenuation, tau);
  }
  const double width = scalarRange[1] - scalarRange[0];
  this->NarrowestFeature = width > 0 ? width : 1.0;
  for (size_t i = 1; i < this->Scalars.size(); ++i)
  {
    const double d = this->Scalars[i] - this->Scalars[i - 1];
    const bool inside =
      this->Scalars[i] >= scalarRange[0] && this->Scalars[i - 1] <= scalarRange[1];
    if (d > 0 && inside)
    {
      this->NarrowestFeature = std::min(this->NarrowestFeature, d);
    }
  }
  // The shader's node scalars are shifted and scaled as the mesh's (vtkTetMesh::GetScalarShift,
  // GetScalarScale), in double before they become float.
  const double shift = vtkTetMesh::ComputeScalarShift(scalarRange);
  const double scale = vtkTetMesh::ComputeScalarScale(scalarRange);
  const size_t n = this->Scalars.size();
  this->Texels.assign(8 * n, 0.0f);
  for (size_t i = 0; i < n; ++i)
  {
    this->Texels[8 * i + 0] = static_cast<float>((this->Scalars[i] - shift) * scale);
    this->Texels[8 * i + 1] = static_cast<float>(this->Attenuations[i]);
    this->Texels[8 * i + 4] = static_cast<float>(this->Colors[3 * i + 0]);
    this->Texels[8 * i + 5] = static_cast<float>(this->Colors[3 * i + 1]);
    this->Texels[8 * i + 6] = static_cast<float>(this->Colors[3 * i + 2]);
  }
}

//------------------------------------------------------------------------------
double vtkTiledRayCastTransferFunction::GetNodeScalar(int i) const
{
  return (i >= 0 && i < this->GetNumberOfNodes()) ? this->Scalars[i] : 0.0;
}

//------------------------------------------------------------------------------
double vtkTiledRayCastTransferFunction::GetNodeAttenuation(int i) const
{
  return (i >= 0 && i < this->GetNumberOfNodes()) ? this->Attenuations[i] : 0.0;
}

//------------------------------------------------------------------------------
void vtkTiledRayCastTransferFunction::GetNodeColor(int i, double rgb[3]) const
{
  for (int c = 0; c < 3; ++c)
  {
    rgb[c] = (i >= 0 && i < this->GetNumberOfNodes()) ? this->Colors[3 * i + c] : 0.0;
  }
}

//------------------------------------------------------------------------------
void vtkTiledRayCastTransferFunction::Evaluate(double s, double rgb[3], double& attenuation) const
{
  const int n = this->GetNumberOfNodes();
  if (n == 0)
  {
    rgb[0] = rgb[1] = rgb[2] = attenuation = 0.0;
    return;
  }
  // The last node at or below s.
  const auto it = std::upper_bound(this->Scalars.begin(), this->Scalars.end(), s);
  const int below = static_cast<int>(it - this->Scalars.begin()) - 1;
  if (below < 0 || below >= n - 1)
  {
    const int k = below < 0 ? 0 : n - 1;
    this->GetNodeColor(k, rgb);
    attenuation = this->Attenuations[k];
    return;
  }
  const double s0 = this->Scalars[below];
  const double s1 = this->Scalars[below + 1];
  const double w = s1 > s0 ? std::min(std::max((s - s0) / (s1 - s0), 0.0), 1.0) : 1.0;
  for (int c = 0; c < 3; ++c)
  {
    rgb[c] = (1 - w) * this->Colors[3 * below + c] + w * this->Colors[3 * (below + 1) + c];
  }
  attenuation = (1 - w) * this->Attenuations[below] + w * this->Attenuations[below + 1];
}

//------------------------------------------------------------------------------
void vtkTiledRayCastTransferFunction::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Tolerance: " << this->Tolerance << "\n";
  os << indent << "MaximumNumberOfNodes: " << this->MaximumNumberOfNodes << "\n";
  os << indent << "Exact: " << this->Exact << "\n";
  os << indent << "NumberOfNodes: " << this->GetNumberOfNodes() << "\n";
  os << indent << "MaximumAttenuation: " << this->MaximumAttenuation << "\n";
  os << indent << "UnitDistance: " << this->UnitDistance << "\n";
  os << indent << "NarrowestFeature: " << this->NarrowestFeature << "\n";
}
