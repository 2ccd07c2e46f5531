/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkTetReferenceBVH.cxx

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "vtkTetReferenceBVH.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace
{
float RoundDown(double x)
{
  float f = static_cast<float>(x);
  if (static_cast<double>(f) > x)
  {
    f = std::nextafter(f, -std::numeric_limits<float>::infinity());
  }
  return f;
}

float RoundUp(double x)
{
  float f = static_cast<float>(x);
  if (static_cast<double>(f) < x)
  {
    f = std::nextafter(f, std::numeric_limits<float>::infinity());
  }
  return f;
}

double SurfaceArea(const double b[6])
{
  const double dx = b[3] - b[0], dy = b[4] - b[1], dz = b[5] - b[2];
  return dx * dy + dy * dz + dz * dx;
}
}

//------------------------------------------------------------------------------
void vtkTetReferenceBVH::EmptyBox(double b[6])
{
  b[0] = b[1] = b[2] = std::numeric_limits<double>::infinity();
  b[3] = b[4] = b[5] = -std::numeric_limits<double>::infinity();
}

//------------------------------------------------------------------------------
void vtkTetReferenceBVH::GrowBox(double b[6], const double* other)
{
  for (int i = 0; i < 3; ++i)
  {
    b[i] = std::min(b[i], other[i]);
    b[i + 3] = std::max(b[i + 3], other[i + 3]);
  }
}

//------------------------------------------------------------------------------
void vtkTetReferenceBVH::Build(
  const std::vector<double>& boxes, double pad, std::vector<int>& order, std::vector<Node>& nodes)
{
  const int n = static_cast<int>(boxes.size() / 6);
  order.resize(n);
  std::vector<double> centroids(3 * static_cast<size_t>(n));
  for (int i = 0; i < n; ++i)
  {
    order[i] = i;
    for (int k = 0; k < 3; ++k)
    {
      centroids[3 * i + k] = 0.5 * (boxes[6 * i + k] + boxes[6 * i + 3 + k]);
    }
  }
  nodes.clear();
  nodes.reserve(2 * static_cast<size_t>(std::max(n / LeafSize, 1)) + 1);
  nodes.push_back(Node());
  struct Task
  {
    int Node, Begin, End, Depth;
  };
  std::vector<Task> tasks;
  tasks.push_back({ 0, 0, n, 0 });
  while (!tasks.empty())
  {
    const Task t = tasks.back();
    tasks.pop_back();
    double box[6], cbox[6];
    EmptyBox(box);
    EmptyBox(cbox);
    for (int i = t.Begin; i < t.End; ++i)
    {
      GrowBox(box, &boxes[6 * static_cast<size_t>(order[i])]);
      const double* c = &centroids[3 * static_cast<size_t>(order[i])];
      const double cc[6] = { c[0], c[1], c[2], c[0], c[1], c[2] };
      GrowBox(cbox, cc);
    }
    Node& node = nodes[t.Node];
    for (int k = 0; k < 3; ++k)
    {
      node.Min[k] = RoundDown(box[k] - pad);
      node.Max[k] = RoundUp(box[k + 3] + pad);
    }
    const int count = t.End - t.Begin;
    if (count <= LeafSize)
    {
      node.Start = t.Begin;
      node.Count = count;
      continue;
    }
    int axis = 0;
    for (int k = 1; k < 3; ++k)
    {
      if (cbox[k + 3] - cbox[k] > cbox[axis + 3] - cbox[axis])
      {
        axis = k;
      }
    }
    int mid = -1;
    if (cbox[axis + 3] - cbox[axis] > 0.0 && t.Depth < MaxBuildDepth)
    {
      mid = FindSplit(boxes, centroids, order, t.Begin, t.End, axis, cbox);
    }
    if (mid <= t.Begin || mid >= t.End)
    {
      // All centroids in one bin (or too deep): split at the median of the widest axis.
      mid = (t.Begin + t.End) / 2;
      std::nth_element(&order[t.Begin], &order[mid], &order[0] + t.End,
        [&](int a, int b)
        {
          return centroids[3 * static_cast<size_t>(a) + axis] <
            centroids[3 * static_cast<size_t>(b) + axis];
        });
    }
    const int first = static_cast<int>(nodes.size());
    node.Start = first;
    node.Count = 0;
    nodes.push_back(Node());
    nodes.push_back(Node());
    tasks.push_back({ first, t.Begin, mid, t.Depth + 1 });
    tasks.push_back({ first + 1, mid, t.End, t.Depth + 1 });
  }
}

//------------------------------------------------------------------------------
// The binned surface area heuristic along `axis` over order[begin, end), whose centroids span
// cbox: partitions the items at the cheapest bin boundary and returns where; -1 when every
// item falls into one bin.
int vtkTetReferenceBVH::FindSplit(const std::vector<double>& boxes,
  const std::vector<double>& centroids, std::vector<int>& order, int begin, int end, int axis,
  const double cbox[6])
{
  const double cmin = cbox[axis], extent = cbox[axis + 3] - cbox[axis];
  auto binOf = [&](int item)
  {
    const int b = static_cast<int>(
      BinCount * ((centroids[3 * static_cast<size_t>(item) + axis] - cmin) / extent));
    return std::min(BinCount - 1, std::max(0, b));
  };
  int binCount[BinCount] = {};
  double binBox[BinCount][6];
  for (int b = 0; b < BinCount; ++b)
  {
    EmptyBox(binBox[b]);
  }
  for (int i = begin; i < end; ++i)
  {
    const int b = binOf(order[i]);
    ++binCount[b];
    GrowBox(binBox[b], &boxes[6 * static_cast<size_t>(order[i])]);
  }
  double rightArea[BinCount];
  int rightCount[BinCount];
  double acc[6];
  EmptyBox(acc);
  int accCount = 0;
  for (int b = BinCount - 1; b > 0; --b)
  {
    GrowBox(acc, binBox[b]);
    accCount += binCount[b];
    rightArea[b] = accCount ? SurfaceArea(acc) : 0.0;
    rightCount[b] = accCount;
  }
  EmptyBox(acc);
  accCount = 0;
  double bestCost = std::numeric_limits<double>::infinity();
  int bestSplit = -1;
  for (int b = 0; b < BinCount - 1; ++b)
  {
    GrowBox(acc, binBox[b]);
    accCount += binCount[b];
    if (accCount == 0 || rightCount[b + 1] == 0)
    {
      continue;
    }
    const double cost = SurfaceArea(acc) * accCount + rightArea[b + 1] * rightCount[b + 1];
    if (cost < bestCost)
    {
      bestCost = cost;
      bestSplit = b;
    }
  }
  if (bestSplit < 0)
  {
    return -1;
  }
  int* split = std::partition(
    &order[begin], &order[0] + end, [&](int item) { return binOf(item) <= bestSplit; });
  return static_cast<int>(split - &order[0]);
}
