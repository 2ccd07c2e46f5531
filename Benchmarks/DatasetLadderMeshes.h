/*=========================================================================

  Program:   TiledRayCast
  Module:    DatasetLadderMeshes.h

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// The mesh generators of MakeDatasetLadder (docs/datasets.md): the wavelet family in VTK, the
// TetGen families' input surfaces (.off and .poly files, the lattice) and their meshing, and the
// orientation every rung gets before it is written.
#ifndef DatasetLadderMeshes_h
#define DatasetLadderMeshes_h

#include "vtkSmartPointer.h"
#include "vtkType.h"
#include "vtkUnstructuredGrid.h"

#include <array>
#include <string>
#include <vector>

#ifdef TRC_HAVE_TETGEN
#include "vtkPolyData.h"
#endif

namespace ladder
{
// Checks that every cell is a tetrahedron stored as 4 consecutive ids, then swaps p2 and p3 of
// every tetrahedron of negative volume (docs/design.md asks for positive tetrahedra); says how
// many were swapped and how many have zero volume.
bool OrientMesh(vtkUnstructuredGrid* mesh, vtkIdType& swapped, vtkIdType& degenerate);

// `text` as the mesh's field array "Provenance".
void AddProvenance(vtkUnstructuredGrid* mesh, const std::string& text);

// The wavelet rung of n^3 voxels spanning [-10,10]^3, 5 tetrahedra per voxel; `provenance` says
// how it was made.
vtkSmartPointer<vtkUnstructuredGrid> MakeWavelet(int n, std::string& provenance);

#ifdef TRC_HAVE_TETGEN
// A closed surface for TetGen, with its holes and regions.
struct Surface
{
  vtkSmartPointer<vtkPolyData> PolyData;
  std::vector<std::array<double, 3>> Holes;
  std::vector<std::array<double, 5>> Regions;
  bool PolygonsAsFacets = false;
  std::string Description;
};

// A Geomview .off polyhedron, read as TetGen reads it (double precision, one facet per face).
bool ReadOFF(const std::string& fileName, Surface& surface);

// A TetGen .poly file whose facets are single polygons without facet holes (comb.poly and
// hollowcube.poly are): its points, facets, hole list and region list.
bool ReadPoly(const std::string& fileName, Surface& surface);

// The lattice of n x n x n cells (a jungle gym of square bars).
Surface MakeLattice(int n);

// TetGen's mesh of `surface` with -q1.414 and maximum volume `maxVolume` (`switches` gets the
// switches TetGen ran with), with the point scalar "Synthetic" and float points; null on failure.
vtkSmartPointer<vtkUnstructuredGrid> MakeTetGen(
  const Surface& surface, double maxVolume, std::string& switches);
#endif
} // namespace ladder

#endif
