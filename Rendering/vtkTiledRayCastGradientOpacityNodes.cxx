/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkTiledRayCastGradientOpacityNodes.cxx

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "vtkTiledRayCastGradientOpacityNodes.h"

#include "vtkPiecewiseFunction.h"
#include "vtkVolumeMapper.h"
#include "vtkVolumeProperty.h"

#include <algorithm>
#include <utility>
#include <vector>

//------------------------------------------------------------------------------
void vtkTiledRayCastGradientOpacityNodes::Compute(vtkVolumeProperty* property, int blendMode)
{
  this->Enabled = false;
  this->NumberOfNodes = 0;
  this->Approximated = false;
  vtkPiecewiseFunction* f = property && property->HasGradientOpacity(0) &&
      !property->GetDisableGradientOpacity(0) && blendMode == vtkVolumeMapper::COMPOSITE_BLEND
    ? property->GetStoredGradientOpacity(0)
    : nullptr;
  const int size = f ? f->GetSize() : 0;
  if (size == 0)
  {
    return;
  }
  this->Clamping = f->GetClamping() ? 1 : 0;
  // Linear intervals are kept as they are; curved ones (midpoint, sharpness) are sampled.
  std::vector<std::pair<double, double>> nodes;
  bool changesSomething = !this->Clamping;
  for (int i = 0; i < size; ++i)
  {
    double node[4]; // x, y, midpoint, sharpness
    f->GetNodeValue(i, node);
    changesSomething = changesSomething || node[1] != 1.0;
    nodes.emplace_back(node[0], node[1]);
    if (i + 1 < size && (node[2] != 0.5 || node[3] != 0.0))
    {
      double next[4];
      f->GetNodeValue(i + 1, next);
      for (int k = 1; k < SamplesPerCurvedInterval; ++k)
      {
        const double x = node[0] + (next[0] - node[0]) * k / SamplesPerCurvedInterval;
        nodes.emplace_back(x, f->GetValue(x));
      }
      this->Approximated = true;
    }
  }
  if (!changesSomething)
  {
    return;
  }
  if (nodes.size() > static_cast<size_t>(MaximumNodes))
  {
    const double lo = nodes.front().first, hi = nodes.back().first;
    nodes.clear();
    for (int k = 0; k < MaximumNodes; ++k)
    {
      const double x = lo + (hi - lo) * k / (MaximumNodes - 1);
      nodes.emplace_back(x, f->GetValue(x));
    }
    this->Approximated = true;
  }
  this->Enabled = true;
  this->NumberOfNodes = static_cast<int>(nodes.size());
  for (int i = 0; i < this->NumberOfNodes; ++i)
  {
    this->Nodes[i][0] = static_cast<float>(nodes[i].first);
    this->Nodes[i][1] = static_cast<float>(nodes[i].second);
  }
}
