/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkTetReferenceIntermixing.cxx

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "vtkTetReferenceIntermixing.h"

#include "vtkTetRayIntegrator.h"
#include "vtkTetReferenceBVH.h"
#include "vtkTetReferenceMesh.h"
#include "vtkTetReferencePixelRays.h"

#include <algorithm>
#include <cmath>

namespace
{
// A ray stops once its transmittance is below this (as vtkTetReferenceCompositing).
constexpr double TerminationDepth = 36.0;

// The scalar of a segment at ray parameter e within it, exact at its ends.
double ScalarAt(const vtkTetReferenceIntermixing::Segment& s, double e)
{
  if (e == s.T0)
  {
    return s.S0;
  }
  if (e == s.T1)
  {
    return s.S1;
  }
  return s.S0 + (s.S1 - s.S0) * ((e - s.T0) / (s.T1 - s.T0));
}
} // namespace

//------------------------------------------------------------------------------
void vtkTetReferenceIntermixing::SetReference()
{
  double box[6];
  vtkTetReferenceBVH::EmptyBox(box);
  for (const Medium& m : this->Media)
  {
    if (m.Mesh->Nodes.empty())
    {
      continue;
    }
    const vtkTetReferenceBVH::Node& root = m.Mesh->Nodes[0];
    double world[6];
    for (int k = 0; k < 3; ++k)
    {
      world[k] = m.Mesh->Center[k] + root.Min[k];
      world[3 + k] = m.Mesh->Center[k] + root.Max[k];
    }
    vtkTetReferenceBVH::GrowBox(box, world);
  }
  for (int k = 0; k < 3; ++k)
  {
    this->Reference[k] = box[k] <= box[3 + k] ? 0.5 * (box[k] + box[3 + k]) : 0.0;
  }
}

//------------------------------------------------------------------------------
// Every medium places the ray in its own frame (its points are relative to its centre) with the
// same origin, the ray's point nearest Reference, and the same direction: their intervals are
// then in one ray parameter without conversion. The vertex coordinates of each mesh's ray frame
// are as large as its distance to that point (the scene's size at most), which bounds their
// rounding as for one mesh.
void vtkTetReferenceIntermixing::CastRay(const vtkTetReferencePixelRays& rays, int i, int j,
  Scratch& scratch, double rgba[4], int& count) const
{
  rgba[0] = rgba[1] = rgba[2] = rgba[3] = 0.0;
  count = 0;
  scratch.Segments.clear();
  scratch.Fragments.clear();
  double nearP[3], d[3], volumeMin, volumeMax;
  bool volumes = false;
  if (!rays.GetWorld(i, j, nearP, d, volumeMin, volumeMax, volumes))
  {
    return;
  }
  const double dd = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
  double lambdaRef = 0.0;
  for (int k = 0; k < 3; ++k)
  {
    lambdaRef -= (nearP[k] - this->Reference[k]) * d[k];
  }
  lambdaRef = std::min(1.0, std::max(0.0, lambdaRef / dd));
  if (volumes)
  {
    for (size_t m = 0; m < this->Media.size(); ++m)
    {
      const vtkTetReferenceMesh& mesh = *this->Media[m].Mesh;
      double origin[3];
      for (int k = 0; k < 3; ++k)
      {
        origin[k] = (nearP[k] - mesh.Center[k]) + lambdaRef * d[k];
      }
      vtkTetReferenceRayCaster::CastRay(
        mesh, origin, d, volumeMin - lambdaRef, volumeMax - lambdaRef, scratch.Hits);
      count += static_cast<int>(scratch.Hits.size());
      for (const vtkTetReferenceRayCaster::Hit& hit : scratch.Hits)
      {
        if (!mesh.Transparent[hit.Tet] && hit.Z1 > hit.Z0)
        {
          scratch.Segments.push_back({ hit.Z0, hit.Z1, hit.S0, hit.S1, static_cast<int>(m) });
        }
      }
    }
  }
  this->CollectFragments(rays, i, j, nearP, d, lambdaRef, scratch);
  this->Composite(scratch, std::sqrt(dd), rgba);
}

//------------------------------------------------------------------------------
// The fragments of pixel (i, j) in front of the opaque depth (a depth test: window z strictly
// less), in the shared ray parameter. Clipping planes cut volumes only, as a mapper's do.
void vtkTetReferenceIntermixing::CollectFragments(const vtkTetReferencePixelRays& rays, int i,
  int j, const double nearP[3], const double d[3], double lambdaRef, Scratch& scratch) const
{
  const long long pixel = static_cast<long long>(j) * rays.Width + i;
  const float opaque = rays.Depth ? rays.Depth[pixel] : 1.0f;
  for (size_t l = 0; l < this->Layers.size(); ++l)
  {
    const float z = this->Layers[l].Depth[pixel];
    if (!(z < opaque) || !(z < 1.0f))
    {
      continue;
    }
    const double lambda = rays.LambdaAtDepth(i, j, nearP, d, z);
    scratch.Fragments.push_back(
      { lambda - lambdaRef, &this->Layers[l].RGBA[4 * pixel], static_cast<int>(l) });
  }
}

//------------------------------------------------------------------------------
void vtkTetReferenceIntermixing::Composite(
  Scratch& scratch, double unitLength, double rgba[4]) const
{
  std::vector<Segment>& segments = scratch.Segments;
  std::vector<Fragment>& fragments = scratch.Fragments;
  std::sort(segments.begin(), segments.end(),
    [](const Segment& a, const Segment& b)
    { return a.T0 != b.T0 ? a.T0 < b.T0 : (a.T1 != b.T1 ? a.T1 < b.T1 : a.Medium < b.Medium); });
  std::sort(fragments.begin(), fragments.end(),
    [](const Fragment& a, const Fragment& b)
    { return a.T != b.T ? a.T < b.T : a.Layer < b.Layer; });
  // Every place where the set of media changes or a fragment lies.
  std::vector<double>& cuts = scratch.Cuts;
  cuts.clear();
  for (const Segment& s : segments)
  {
    cuts.push_back(s.T0);
    cuts.push_back(s.T1);
  }
  for (const Fragment& f : fragments)
  {
    cuts.push_back(f.T);
  }
  std::sort(cuts.begin(), cuts.end());
  cuts.erase(std::unique(cuts.begin(), cuts.end()), cuts.end());

  double color[3] = { 0.0, 0.0, 0.0 };
  double opticalDepth = 0.0;
  std::vector<int>& active = scratch.Active;
  active.clear();
  size_t nextSegment = 0, nextFragment = 0;
  for (size_t k = 0; k < cuts.size() && opticalDepth <= TerminationDepth; ++k)
  {
    const double e0 = cuts[k];
    for (; nextFragment < fragments.size() && fragments[nextFragment].T <= e0; ++nextFragment)
    {
      const double* f = fragments[nextFragment].RGBA;
      const double transmittance = std::exp(-opticalDepth);
      for (int q = 0; q < 3; ++q)
      {
        color[q] += transmittance * f[q];
      }
      opticalDepth -= std::log1p(-f[3]); // +inf for an opaque fragment
    }
    if (k + 1 == cuts.size() || opticalDepth > TerminationDepth)
    {
      break;
    }
    const double e1 = cuts[k + 1];
    active.erase(
      std::remove_if(active.begin(), active.end(), [&](int s) { return segments[s].T1 <= e0; }),
      active.end());
    for (; nextSegment < segments.size() && segments[nextSegment].T0 <= e0; ++nextSegment)
    {
      if (segments[nextSegment].T1 > e0)
      {
        active.push_back(static_cast<int>(nextSegment));
      }
    }
    if (active.empty())
    {
      continue;
    }
    double segment[4], depth = 0.0;
    this->IntegrateInterval(scratch, e0, e1, unitLength, segment, depth);
    const double transmittance = std::exp(-opticalDepth);
    for (int q = 0; q < 3; ++q)
    {
      color[q] += transmittance * segment[q];
    }
    opticalDepth += depth;
  }
  rgba[0] = color[0];
  rgba[1] = color[1];
  rgba[2] = color[2];
  rgba[3] = -std::expm1(-opticalDepth);
}

//------------------------------------------------------------------------------
// The active segments between cuts e0 and e1: one medium by its integrator, several as a
// mixture.
void vtkTetReferenceIntermixing::IntegrateInterval(
  Scratch& scratch, double e0, double e1, double unitLength, double segment[4], double& depth) const
{
  const double length = (e1 - e0) * unitLength;
  if (scratch.Active.size() == 1)
  {
    const Segment& s = scratch.Segments[scratch.Active[0]];
    this->Media[s.Medium].Integrator->IntegrateWithDepth(
      ScalarAt(s, e0), ScalarAt(s, e1), length, segment, &depth);
    return;
  }
  scratch.Integrators.clear();
  scratch.Front.clear();
  scratch.Back.clear();
  for (int a : scratch.Active)
  {
    const Segment& s = scratch.Segments[a];
    scratch.Integrators.push_back(this->Media[s.Medium].Integrator);
    scratch.Front.push_back(ScalarAt(s, e0));
    scratch.Back.push_back(ScalarAt(s, e1));
  }
  vtkTetRayIntegrator::IntegrateMixture(static_cast<int>(scratch.Active.size()),
    scratch.Integrators.data(), scratch.Front.data(), scratch.Back.data(), length, segment, &depth);
}
