/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkTiledRayCastVolumeOrder.cxx

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "vtkTiledRayCastVolumeOrder.h"

#include "vtkCamera.h"

#include <cmath>

//------------------------------------------------------------------------------
int vtkTiledRayCastVolumeOrder::Compare(
  const Bounds& a, const Bounds& b, const double eye[3], bool parallel)
{
  int verdict = 0;
  for (int k = 0; k < 3; ++k)
  {
    // +1 when a lies below b along axis k (a plane between them), -1 above, 0 neither.
    const int below = a[2 * k + 1] <= b[2 * k] ? 1 : (b[2 * k + 1] <= a[2 * k] ? -1 : 0);
    if (below == 0)
    {
      continue;
    }
    // Which side of the plane the rays come from: +1 the lower side (a's when below).
    int from = 0;
    if (parallel)
    {
      // Rays travel along the direction of projection: towards +k they come from below.
      from = eye[k] > 0 ? 1 : (eye[k] < 0 ? -1 : 0);
    }
    else
    {
      const double plane =
        below > 0 ? 0.5 * (a[2 * k + 1] + b[2 * k]) : 0.5 * (b[2 * k + 1] + a[2 * k]);
      from = eye[k] < plane ? 1 : (eye[k] > plane ? -1 : 0);
    }
    if (from == 0)
    {
      continue; // the plane holds the rays' origin or their direction: no ray crosses it
    }
    const int front = below * from; // +1: a is on the side the rays come from
    if (verdict != 0 && verdict != front)
    {
      return 0; // planes disagree: no ray meets both boxes
    }
    verdict = front;
  }
  return verdict;
}

//------------------------------------------------------------------------------
std::vector<size_t> vtkTiledRayCastVolumeOrder::BackToFront(
  const std::vector<Bounds>& boxes, vtkCamera* camera)
{
  const size_t n = boxes.size();
  const bool parallel = camera->GetParallelProjection() != 0;
  double eye[3];
  if (parallel)
  {
    camera->GetDirectionOfProjection(eye);
  }
  else
  {
    camera->GetPosition(eye);
  }
  // How far each box is: the distance to its centre, or its centre's depth along the view.
  std::vector<double> distance(n);
  for (size_t i = 0; i < n; ++i)
  {
    double d = 0.0;
    for (int k = 0; k < 3; ++k)
    {
      const double centre = 0.5 * (boxes[i][2 * k] + boxes[i][2 * k + 1]);
      d += parallel ? centre * eye[k] : (centre - eye[k]) * (centre - eye[k]);
    }
    distance[i] = d;
  }
  // behind[i]: how many boxes not drawn yet must be drawn before box i (they are behind it).
  std::vector<std::vector<size_t>> inFrontOf(n); // inFrontOf[j]: the boxes in front of j
  std::vector<size_t> behind(n, 0);
  for (size_t i = 0; i < n; ++i)
  {
    for (size_t j = i + 1; j < n; ++j)
    {
      const int c = Compare(boxes[i], boxes[j], eye, parallel);
      if (c > 0)
      {
        inFrontOf[j].push_back(i);
        ++behind[i];
      }
      else if (c < 0)
      {
        inFrontOf[i].push_back(j);
        ++behind[j];
      }
    }
  }
  std::vector<size_t> order;
  std::vector<bool> drawn(n, false);
  while (order.size() < n)
  {
    // The farthest box free to come next, else (a cycle) the farthest not drawn.
    size_t next = n;
    for (int pass = 0; pass < 2 && next == n; ++pass)
    {
      for (size_t i = 0; i < n; ++i)
      {
        if (!drawn[i] && (pass == 1 || behind[i] == 0) &&
          (next == n || distance[i] > distance[next]))
        {
          next = i;
        }
      }
    }
    drawn[next] = true;
    order.push_back(next);
    for (size_t i : inFrontOf[next])
    {
      if (behind[i] > 0)
      {
        --behind[i];
      }
    }
  }
  return order;
}
