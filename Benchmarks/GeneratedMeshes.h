/*=========================================================================

  Program:   TiledRayCast
  Module:    GeneratedMeshes.h

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// The dataset ladder's largest rungs, 100M tetrahedra to a billion, made in memory where they are
// rendered (no file: a billion tetrahedra written as .vtu would take tens of gigabytes and
// minutes to read back). Both families are n^3 voxels spanning [-10,10]^3, each voxel split into
// the 6 tetrahedra of its Freudenthal (Kuhn) triangulation around the diagonal (0,0,0)-(1,1,1),
// which conforms across voxels with no alternation, every tetrahedron positively oriented:
//   wavelet6  convex: every voxel, the point scalar "RTData" of vtkRTAnalyticSource's defaults
//             evaluated at the points (as the wavelet rungs, which split voxels in 5).
//   gym6      strongly non-convex: a jungle gym of 4 x 4 x 4 cells whose square bars are the
//             voxels within 5 slabs of n/13 voxels per axis (at 0, 3/13, ..., 12/13) in at
//             least two axes; only the points of kept voxels, the same scalar.
// Threads through vtkSMPTools; the cells in vtkCellArray's 32-bit storage where their
// connectivity fits (under 2^31 ids: 536M tetrahedra), 64-bit above.
#ifndef GeneratedMeshes_h
#define GeneratedMeshes_h

#include "vtkSmartPointer.h"
#include "vtkType.h"
#include "vtkUnstructuredGrid.h"

#include <string>

namespace generated
{
// A rung: its name, family, voxels per axis and expected counts.
struct Rung
{
  const char* Name;
  const char* Family;
  int Voxels;
  vtkIdType Points;
  vtkIdType Tetrahedra;
};

// The rung named `name` (wavelet6_100m, gym6_1b, ...), or null.
const Rung* FindRung(const std::string& name);

// Every rung, for listings: `count` gets their number.
const Rung* GetRungs(int& count);

// The mesh of `family` on n^3 voxels; null (with a message on stderr) for an unknown family.
// The points are numbered in lattice order (x fastest), or with `mortonPoints` along a Morton
// curve of their lattice indices (a tetrahedron's four points then lie close in memory).
vtkSmartPointer<vtkUnstructuredGrid> MakeMesh(
  const std::string& family, int n, bool mortonPoints = false);

// The mesh of `rung`, checked against its expected counts (null, with a message, when they
// differ).
vtkSmartPointer<vtkUnstructuredGrid> MakeRung(const Rung& rung, bool mortonPoints = false);

// The boundary triangles the mesh of `family` on n^3 voxels has: two per voxel face between a
// kept voxel and a voxel not kept or outside (counted voxel by voxel, apart from MakeMesh).
vtkIdType CountBoundaryFaces(const std::string& family, int n);
} // namespace generated

#endif
