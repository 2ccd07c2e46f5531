/*=========================================================================

  Program:   TiledRayCast
  Module:    TestTetMeshRebuild.cxx

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// vtkTetMeshBuilder and the layouts rebuild only what changed: nothing twice, points only for a
// deforming mesh (and then exactly what a full build of the moved mesh gives), scalars only
// when only the scalars change, everything when the cells or a topology setting change, and
// everything again when a deformation turns a tetrahedron inside out. The layouts follow with
// the matching partial updates, and their arrays then equal a fresh build's.
#include "TetMeshTestUtilities.h"

#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkIdList.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkTestUtilities.h"
#include "vtkTetMesh.h"
#include "vtkTetMeshBuilder.h"
#include "vtkTetMeshCompactLayout.h"
#include "vtkTetMeshPaperLayout.h"
#include "vtkTetMeshValidationReport.h"
#include "vtkUnstructuredGrid.h"
#include "vtkXMLUnstructuredGridReader.h"

#include <cstring>

namespace
{
template <typename T>
bool SameArray(const T* a, const T* b, size_t n)
{
  return (n == 0) || (a && b && std::memcmp(a, b, n * sizeof(T)) == 0);
}

// Two meshes are the same, value for value (report included).
std::string CompareMeshes(vtkTetMesh* a, vtkTetMesh* b)
{
  const size_t numTets = static_cast<size_t>(a->GetNumberOfTetrahedra());
  const size_t numPoints = static_cast<size_t>(a->GetNumberOfPoints());
  if (a->GetNumberOfTetrahedra() != b->GetNumberOfTetrahedra() ||
    a->GetNumberOfPoints() != b->GetNumberOfPoints() ||
    a->GetNumberOfBoundaryFaces() != b->GetNumberOfBoundaryFaces())
  {
    return "sizes differ";
  }
  if (!SameArray(a->GetPoints(), b->GetPoints(), 3 * numPoints))
  {
    return "points differ";
  }
  if (!SameArray(a->GetTetPoints(), b->GetTetPoints(), 4 * numTets))
  {
    return "tetrahedra differ";
  }
  if (!SameArray(a->GetTetNeighbors(), b->GetTetNeighbors(), 4 * numTets))
  {
    return "neighbours differ";
  }
  if (!SameArray(a->GetBoundaryFaces(), b->GetBoundaryFaces(),
        static_cast<size_t>(a->GetNumberOfBoundaryFaces())))
  {
    return "boundary faces differ";
  }
  if (!SameArray(a->GetTetFlags(), b->GetTetFlags(), numTets))
  {
    return "flags differ";
  }
  if (a->GetHasCellScalars() != b->GetHasCellScalars() ||
    !SameArray(a->GetPointScalars(), b->GetPointScalars(), a->GetPointScalars() ? numPoints : 0) ||
    !SameArray(a->GetCellScalars(), b->GetCellScalars(), a->GetCellScalars() ? numTets : 0))
  {
    return "scalars differ";
  }
  double ba[6], bb[6], sa[3], sb[3], ra[2], rb[2];
  a->GetBounds(ba);
  b->GetBounds(bb);
  a->GetShift(sa);
  b->GetShift(sb);
  a->GetScalarRange(ra);
  b->GetScalarRange(rb);
  if (std::memcmp(ba, bb, sizeof(ba)) || std::memcmp(sa, sb, sizeof(sa)) ||
    std::memcmp(ra, rb, sizeof(ra)))
  {
    return "bounds, shift or scalar range differ";
  }
  vtkTetMeshValidationReport* x = a->GetReport();
  vtkTetMeshValidationReport* y = b->GetReport();
  if (x->GetSummary() != y->GetSummary() || x->GetUsable() != y->GetUsable())
  {
    return "reports differ: " + x->GetSummary() + " / " + y->GetSummary();
  }
  return std::string();
}

// Two layouts hold the same arrays.
std::string CompareLayouts(vtkTetMeshLayout* a, vtkTetMeshLayout* b)
{
  if (a->GetNumberOfArrays() != b->GetNumberOfArrays())
  {
    return "array counts differ";
  }
  for (int i = 0; i <= a->GetNumberOfArrays(); ++i)
  {
    vtkDataArray* x = i < a->GetNumberOfArrays() ? a->GetArray(i) : a->GetBoundaryArray();
    vtkDataArray* y = i < a->GetNumberOfArrays() ? b->GetArray(i) : b->GetBoundaryArray();
    if (x->GetNumberOfValues() != y->GetNumberOfValues() ||
      std::memcmp(x->GetVoidPointer(0), y->GetVoidPointer(0),
        static_cast<size_t>(x->GetNumberOfValues() * x->GetDataTypeSize())) != 0)
    {
      return std::string("array ") + x->GetName() + " differs";
    }
  }
  return std::string();
}

struct Pipeline
{
  vtkNew<vtkTetMeshBuilder> Builder;
  vtkNew<vtkTetMeshCompactLayout> Compact;
  vtkNew<vtkTetMeshPaperLayout> Paper;
  vtkTetMesh* Build(vtkDataSet* input)
  {
    vtkTetMesh* mesh = this->Builder->Build(input);
    this->Compact->Update(mesh);
    this->Paper->Update(mesh);
    return mesh;
  }
};

// What a fresh builder and fresh layouts make of a copy of the grid must equal what the
// incremental pipeline holds.
std::string CompareWithFullBuild(vtkUnstructuredGrid* grid, Pipeline& incremental)
{
  vtkNew<vtkUnstructuredGrid> copy;
  copy->DeepCopy(grid);
  Pipeline fresh;
  fresh.Builder->SetSpatialOrdering(incremental.Builder->GetSpatialOrdering());
  fresh.Builder->SetPointOrdering(incremental.Builder->GetPointOrdering());
  fresh.Build(copy);
  std::string error = CompareMeshes(incremental.Builder->GetMesh(), fresh.Builder->GetMesh());
  if (error.empty())
  {
    error = CompareLayouts(incremental.Compact, fresh.Compact);
  }
  if (error.empty())
  {
    error = CompareLayouts(incremental.Paper, fresh.Paper);
  }
  return error;
}

// A smooth deformation that keeps every tetrahedron's orientation (small against the cells).
void Deform(vtkUnstructuredGrid* grid, double amount)
{
  vtkPoints* points = grid->GetPoints();
  for (vtkIdType i = 0; i < points->GetNumberOfPoints(); ++i)
  {
    double x[3];
    points->GetPoint(i, x);
    x[0] += amount * std::sin(x[1]);
    x[2] += amount * std::cos(x[0]);
    points->SetPoint(i, x);
  }
  points->Modified();
}

vtkSmartPointer<vtkUnstructuredGrid> ReadGrid(int argc, char* argv[], const char* name)
{
  char* fileName = vtkTestUtilities::ExpandDataFileName(argc, argv, name);
  vtkNew<vtkXMLUnstructuredGridReader> reader;
  reader->SetFileName(fileName);
  delete[] fileName;
  reader->Update();
  auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
  grid->DeepCopy(reader->GetOutput());
  return grid;
}

// Nothing changed, or nothing that matters: nothing rebuilt, no time stamp moves.
int NothingChanged(Pipeline& p, vtkUnstructuredGrid* grid)
{
  vtkTetMesh* mesh = p.Builder->GetMesh();
  // Nothing changed: nothing rebuilt, no time stamp moves.
  const vtkMTimeType meshTime = mesh->GetMTime();
  p.Build(grid);
  TRC_CHECK(p.Builder->GetLastRebuild() == vtkTetMeshBuilder::RebuildNothing);
  TRC_CHECK(p.Compact->GetLastUpdate() == vtkTetMeshLayout::UpdatedNothing);
  TRC_CHECK(p.Paper->GetLastUpdate() == vtkTetMeshLayout::UpdatedNothing);
  TRC_CHECK(mesh->GetMTime() == meshTime);
  // Nor does touching the builder without changing a setting, or another array of the grid.
  p.Builder->Modified();
  vtkNew<vtkDoubleArray> unrelated;
  unrelated->SetName("unrelated");
  unrelated->SetNumberOfTuples(grid->GetNumberOfPoints());
  unrelated->FillValue(1.0);
  grid->GetPointData()->AddArray(unrelated);
  p.Builder->SetSpatialOrdering(false);
  p.Build(grid);
  TRC_CHECK(p.Builder->GetLastRebuild() == vtkTetMeshBuilder::RebuildNothing);
  TRC_CHECK(mesh->GetMTime() == meshTime);
  return EXIT_SUCCESS;
}

// Points, scalars or both change: only they are rebuilt, and the result equals a full build.
int PointsAndScalars(Pipeline& p, vtkUnstructuredGrid* grid)
{
  vtkTetMesh* mesh = p.Builder->GetMesh();
  const vtkMTimeType topologyTime = mesh->GetTopologyTime();
  // Points only (a deforming mesh): the points path, and the same result as a full build.
  // The compact layout rewrites (marks modified) its points only: no re-upload of the rest.
  const vtkMTimeType tetPointsTime = p.Compact->GetArray(0)->GetMTime();
  const vtkMTimeType boundaryTime = p.Compact->GetBoundaryArray()->GetMTime();
  const vtkMTimeType pointsArrayTime = p.Compact->GetArray(2)->GetMTime();
  Deform(grid, 0.02);
  p.Build(grid);
  TRC_CHECK(p.Compact->GetArray(0)->GetMTime() == tetPointsTime);
  TRC_CHECK(p.Compact->GetArray(1)->GetMTime() < pointsArrayTime);
  TRC_CHECK(p.Compact->GetBoundaryArray()->GetMTime() == boundaryTime);
  TRC_CHECK(p.Compact->GetArray(2)->GetMTime() > pointsArrayTime);
  TRC_CHECK(p.Builder->GetLastRebuild() == vtkTetMeshBuilder::RebuildPoints);
  TRC_CHECK(mesh->GetTopologyTime() == topologyTime);
  TRC_CHECK(mesh->GetPointsTime() > topologyTime);
  TRC_CHECK(p.Compact->GetLastUpdate() ==
    (vtkTetMeshLayout::UpdatedPoints | vtkTetMeshLayout::UpdatedScalars));
  TRC_CHECK(p.Paper->GetLastUpdate() ==
    (vtkTetMeshLayout::UpdatedPoints | vtkTetMeshLayout::UpdatedScalars));
  TRC_CHECK_EMPTY(CompareWithFullBuild(grid, p));

  // New points object with the same number of points: still the points path.
  vtkNew<vtkPoints> moved;
  moved->DeepCopy(grid->GetPoints());
  grid->SetPoints(moved);
  Deform(grid, -0.01);
  p.Build(grid);
  TRC_CHECK(p.Builder->GetLastRebuild() == vtkTetMeshBuilder::RebuildPoints);
  TRC_CHECK_EMPTY(CompareWithFullBuild(grid, p));

  // Scalars only, modified in place.
  vtkDataArray* scalars = grid->GetPointData()->GetScalars();
  for (vtkIdType i = 0; i < scalars->GetNumberOfTuples(); ++i)
  {
    scalars->SetComponent(i, 0, 2.0 * scalars->GetComponent(i, 0) + 1.0);
  }
  scalars->Modified();
  p.Build(grid);
  TRC_CHECK(p.Builder->GetLastRebuild() == vtkTetMeshBuilder::RebuildScalars);
  TRC_CHECK(mesh->GetTopologyTime() == topologyTime);
  TRC_CHECK(p.Compact->GetLastUpdate() == vtkTetMeshLayout::UpdatedScalars);
  TRC_CHECK(p.Paper->GetLastUpdate() == vtkTetMeshLayout::UpdatedScalars);
  TRC_CHECK_EMPTY(CompareWithFullBuild(grid, p));

  // Another active array: scalars only.
  vtkNew<vtkFloatArray> other;
  other->SetName("other");
  other->SetNumberOfTuples(grid->GetNumberOfPoints());
  for (vtkIdType i = 0; i < grid->GetNumberOfPoints(); ++i)
  {
    other->SetValue(i, static_cast<float>(i % 17));
  }
  grid->GetPointData()->SetScalars(other);
  p.Build(grid);
  TRC_CHECK(p.Builder->GetLastRebuild() == vtkTetMeshBuilder::RebuildScalars);
  TRC_CHECK(mesh->GetPointScalars()[20] == 3.0);
  TRC_CHECK_EMPTY(CompareWithFullBuild(grid, p));

  // A scalar setting: scalars only.
  p.Builder->GetScalarSelection()->SetScalarMode(VTK_SCALAR_MODE_USE_POINT_FIELD_DATA);
  p.Builder->GetScalarSelection()->SelectScalarArray("unrelated");
  p.Build(grid);
  TRC_CHECK(p.Builder->GetLastRebuild() == vtkTetMeshBuilder::RebuildScalars);
  TRC_CHECK(mesh->GetPointScalars()[20] == 1.0);
  p.Builder->GetScalarSelection()->SetScalarMode(VTK_SCALAR_MODE_DEFAULT);
  p.Build(grid);
  TRC_CHECK(p.Builder->GetLastRebuild() == vtkTetMeshBuilder::RebuildScalars);

  // Points and scalars together.
  Deform(grid, 0.01);
  other->SetValue(20, 5.0f);
  other->Modified();
  p.Build(grid);
  TRC_CHECK(p.Builder->GetLastRebuild() ==
    (vtkTetMeshBuilder::RebuildPoints | vtkTetMeshBuilder::RebuildScalars));
  TRC_CHECK(mesh->GetTopologyTime() == topologyTime);
  TRC_CHECK_EMPTY(CompareWithFullBuild(grid, p));
  return EXIT_SUCCESS;
}

// What changes the topology (or may): everything is rebuilt.
int Everything(Pipeline& p, vtkUnstructuredGrid* grid)
{
  vtkTetMesh* mesh = p.Builder->GetMesh();
  const vtkMTimeType topologyTime = mesh->GetTopologyTime();
  // A deformation that turns tetrahedra inside out (a mirror): everything is rebuilt, and the
  // result still equals a full build (now with every tetrahedron inverted in the input).
  vtkPoints* points = grid->GetPoints();
  for (vtkIdType i = 0; i < points->GetNumberOfPoints(); ++i)
  {
    double x[3];
    points->GetPoint(i, x);
    x[0] = -x[0];
    points->SetPoint(i, x);
  }
  points->Modified();
  const vtkIdType invertedBefore = mesh->GetReport()->GetNumberOfInvertedTetrahedra();
  p.Build(grid);
  TRC_CHECK(p.Builder->GetLastRebuild() == vtkTetMeshBuilder::RebuildAll);
  TRC_CHECK(mesh->GetTopologyTime() > topologyTime);
  TRC_CHECK(p.Compact->GetLastUpdate() == vtkTetMeshLayout::UpdatedAll);
  TRC_CHECK(mesh->GetReport()->GetNumberOfInvertedTetrahedra() ==
    mesh->GetNumberOfTetrahedra() - invertedBefore);
  TRC_CHECK_EMPTY(trc::CheckOrientation(mesh));
  TRC_CHECK_EMPTY(CompareWithFullBuild(grid, p));

  // The cells change: everything.
  vtkNew<vtkCellArray> fewer;
  vtkIdType npts;
  const vtkIdType* pts;
  for (vtkIdType c = 0; c + 1 < grid->GetNumberOfCells(); ++c)
  {
    grid->GetCellPoints(c, npts, pts);
    fewer->InsertNextCell(npts, pts);
  }
  grid->SetCells(VTK_TETRA, fewer);
  p.Build(grid);
  TRC_CHECK(p.Builder->GetLastRebuild() == vtkTetMeshBuilder::RebuildAll);
  TRC_CHECK(mesh->GetNumberOfTetrahedra() == 12935);
  TRC_CHECK_EMPTY(trc::CheckNeighbors(mesh));
  TRC_CHECK_EMPTY(CompareWithFullBuild(grid, p));

  // Topology settings: everything.
  p.Builder->SpatialOrderingOn();
  p.Build(grid);
  TRC_CHECK(p.Builder->GetLastRebuild() == vtkTetMeshBuilder::RebuildAll);
  TRC_CHECK_EMPTY(CompareWithFullBuild(grid, p));
  // With spatial ordering, a points-only update keeps the order of the last full build.
  Deform(grid, 0.01);
  p.Build(grid);
  TRC_CHECK(p.Builder->GetLastRebuild() == vtkTetMeshBuilder::RebuildPoints);
  TRC_CHECK_EMPTY(trc::CheckNeighbors(mesh));
  p.Builder->SetDegeneracyTolerance(1e-2); // spx has tetrahedra down to 1.3e-3
  p.Build(grid);
  TRC_CHECK(p.Builder->GetLastRebuild() == vtkTetMeshBuilder::RebuildAll);
  TRC_CHECK(mesh->GetReport()->GetNumberOfDegenerateTetrahedra() > 0);

  // Scratch memory: held between builds, released on request, without changing the mesh.
  TRC_CHECK(p.Builder->GetScratchMemorySize() > 12 * 4 * mesh->GetNumberOfTetrahedra());
  p.Builder->ReleaseScratchMemory();
  TRC_CHECK(p.Builder->GetScratchMemorySize() == 0);
  TRC_CHECK_EMPTY(trc::CheckNeighbors(mesh));
  // Beyond MaximumKeptScratchMemory each stage frees its scratch: none is left, and the mesh
  // and its layouts are those of a build that keeps it.
  p.Builder->SetDegeneracyTolerance(1e-12); // as the fresh builder's
  p.Builder->SetMaximumKeptScratchMemory(0);
  p.Builder->Invalidate();
  p.Build(grid);
  TRC_CHECK(p.Builder->GetScratchMemorySize() == 0);
  TRC_CHECK_EMPTY(CompareWithFullBuild(grid, p));
  p.Builder->SetMaximumKeptScratchMemory(vtkIdType(1) << 31);

  // Another input object with the same content: everything; Invalidate(): everything.
  vtkNew<vtkUnstructuredGrid> twin;
  twin->DeepCopy(grid);
  p.Build(twin);
  TRC_CHECK(p.Builder->GetLastRebuild() == vtkTetMeshBuilder::RebuildAll);
  p.Builder->Invalidate();
  p.Build(twin);
  TRC_CHECK(p.Builder->GetLastRebuild() == vtkTetMeshBuilder::RebuildAll);
  p.Build(twin);
  TRC_CHECK(p.Builder->GetLastRebuild() == vtkTetMeshBuilder::RebuildNothing);
  return EXIT_SUCCESS;
}

// torus_vistrails: half its tetrahedra inverted and 30 exactly flat. An exact translation
// (power-of-two step on double coordinates holding float values) keeps every orientation and
// every flat tetrahedron flat: points only, and still equal to a full build.
int TorusTranslation(int argc, char* argv[])
{
  vtkSmartPointer<vtkUnstructuredGrid> torus = ReadGrid(argc, argv, "Meshes/torus_vistrails.vtu");
  vtkNew<vtkPoints> doublePoints;
  doublePoints->SetDataTypeToDouble();
  doublePoints->DeepCopy(torus->GetPoints());
  torus->SetPoints(doublePoints);
  Pipeline q;
  vtkTetMesh* mesh = q.Build(torus);
  TRC_CHECK(mesh->GetReport()->GetNumberOfInvertedTetrahedra() == 4626);
  TRC_CHECK(mesh->GetReport()->GetNumberOfDegenerateTetrahedra() == 30);
  for (vtkIdType i = 0; i < doublePoints->GetNumberOfPoints(); ++i)
  {
    double x[3];
    doublePoints->GetPoint(i, x);
    doublePoints->SetPoint(i, x[0] + 0.125, x[1] - 0.25, x[2] + 0.5);
  }
  doublePoints->Modified();
  q.Build(torus);
  TRC_CHECK(q.Builder->GetLastRebuild() == vtkTetMeshBuilder::RebuildPoints);
  TRC_CHECK(mesh->GetReport()->GetNumberOfDegenerateTetrahedra() == 30);
  TRC_CHECK_EMPTY(CompareWithFullBuild(torus, q));
  // Lifting one point of a flat tetrahedron makes it a real one; whichever way it now faces,
  // the result equals a full build.
  vtkIdType flat[4];
  vtkIdType flatTet = -1;
  for (vtkIdType t = 0; t < mesh->GetNumberOfTetrahedra() && flatTet < 0; ++t)
  {
    flatTet = (mesh->GetTetFlags(t) & vtkTetMesh::Degenerate) ? t : -1;
  }
  mesh->GetTetPointIds(flatTet, flat);
  double x[3];
  doublePoints->GetPoint(flat[0], x);
  doublePoints->SetPoint(flat[0], x[0], x[1], x[2] + 1e-3);
  doublePoints->Modified();
  q.Build(torus);
  TRC_CHECK(q.Builder->GetLastRebuild() != vtkTetMeshBuilder::RebuildNothing);
  TRC_CHECK_EMPTY(CompareWithFullBuild(torus, q));
  return EXIT_SUCCESS;
}

// PointOrdering: the points renumbered along a Morton curve. The mesh's points and point scalars
// are the input's through GetPointInputIds() (a permutation) and every tetrahedron keeps its
// input cell's points, after a full build and after points-only and scalars-only rebuilds
// (which keep the last full build's order, as for the tetrahedra).
std::string CheckPointOrder(vtkTetMesh* mesh, vtkUnstructuredGrid* grid)
{
  const vtkIdType numPoints = mesh->GetNumberOfPoints();
  const uint32_t* inputIds = mesh->GetPointInputIds();
  if (!inputIds)
  {
    return "no point order";
  }
  std::vector<char> seen(static_cast<size_t>(numPoints), 0);
  vtkIdType moved = 0;
  vtkDataArray* scalars = grid->GetPointData()->GetScalars();
  for (vtkIdType i = 0; i < numPoints; ++i)
  {
    if (inputIds[i] >= numPoints || seen[inputIds[i]])
    {
      return "not a permutation";
    }
    seen[inputIds[i]] = 1;
    moved += inputIds[i] != i ? 1 : 0;
    double x[3];
    grid->GetPoint(inputIds[i], x);
    const double* p = mesh->GetPoints() + 3 * i;
    if (p[0] != x[0] || p[1] != x[1] || p[2] != x[2] ||
      mesh->GetPointScalars()[i] != scalars->GetTuple1(inputIds[i]))
    {
      return "point " + std::to_string(i) + " is not its input point";
    }
  }
  if (moved < numPoints / 2)
  {
    return "the points kept their order";
  }
  vtkNew<vtkIdList> cellIds;
  for (vtkIdType t = 0; t < mesh->GetNumberOfTetrahedra(); ++t)
  {
    grid->GetCellPoints(mesh->GetTetInputCellIds()[t], cellIds);
    for (int k = 0; k < 4; ++k)
    {
      if (cellIds->IsId(inputIds[mesh->GetTetPoints()[4 * t + k]]) < 0)
      {
        return "tetrahedron " + std::to_string(t) + " has a point not of its input cell";
      }
    }
  }
  return trc::CheckNeighbors(mesh);
}

int PointOrder(vtkUnstructuredGrid* input)
{
  vtkNew<vtkUnstructuredGrid> grid;
  grid->DeepCopy(input);
  Pipeline p;
  p.Builder->SpatialOrderingOn();
  p.Builder->PointOrderingOn();
  vtkTetMesh* mesh = p.Build(grid);
  TRC_CHECK_EMPTY(CheckPointOrder(mesh, grid));
  TRC_CHECK_EMPTY(CompareWithFullBuild(grid, p));
  Deform(grid, 0.01);
  p.Build(grid);
  TRC_CHECK(p.Builder->GetLastRebuild() == vtkTetMeshBuilder::RebuildPoints);
  TRC_CHECK_EMPTY(CheckPointOrder(mesh, grid));
  vtkDataArray* scalars = grid->GetPointData()->GetScalars();
  for (vtkIdType i = 0; i < scalars->GetNumberOfTuples(); ++i)
  {
    scalars->SetTuple1(i, scalars->GetTuple1(i) + 0.5 * i);
  }
  scalars->Modified();
  p.Build(grid);
  TRC_CHECK(p.Builder->GetLastRebuild() == vtkTetMeshBuilder::RebuildScalars);
  TRC_CHECK_EMPTY(CheckPointOrder(mesh, grid));
  // Off again: a full build, in the input's numbering.
  p.Builder->PointOrderingOff();
  mesh = p.Build(grid);
  TRC_CHECK(p.Builder->GetLastRebuild() == vtkTetMeshBuilder::RebuildAll);
  TRC_CHECK(mesh->GetPointInputIds() == nullptr);
  return EXIT_SUCCESS;
}

} // namespace

// Face matching in four passes over ranges of point ids (as above MaximumKeptScratchMemory),
// each reading only the chunks of 65,536 tetrahedra with faces in its range: on a mesh of ten
// chunks in spatial order, the mesh and layouts of one pass.
int FourPasses(int argc, char* argv[])
{
  vtkSmartPointer<vtkUnstructuredGrid> grid =
    ReadGrid(argc, argv, "Meshes/post_tets6_conforming.vtu");
  TRC_CHECK(grid->GetNumberOfCells() > 9 * 65536);
  Pipeline passes;
  passes.Builder->SetMaximumKeptScratchMemory(0);
  vtkTetMesh* mesh = passes.Build(grid);
  TRC_CHECK(mesh->GetReport()->GetUsable());
  TRC_CHECK_EMPTY(trc::CheckNeighbors(mesh));
  TRC_CHECK_EMPTY(CompareWithFullBuild(grid, passes));
  return EXIT_SUCCESS;
}

int TestTetMeshRebuild(int argc, char* argv[])
{
  vtkSmartPointer<vtkUnstructuredGrid> grid = ReadGrid(argc, argv, "Meshes/spx_vistrails.vtu");
  TRC_CHECK(grid->GetNumberOfCells() == 12936);

  Pipeline p;
  vtkTetMesh* mesh = p.Build(grid);
  TRC_CHECK(p.Builder->GetLastRebuild() == vtkTetMeshBuilder::RebuildAll);
  TRC_CHECK(p.Compact->GetLastUpdate() == vtkTetMeshLayout::UpdatedAll);
  TRC_CHECK(p.Paper->GetLastUpdate() == vtkTetMeshLayout::UpdatedAll);
  TRC_CHECK(mesh->GetReport()->GetUsable());
  TRC_CHECK(NothingChanged(p, grid) == EXIT_SUCCESS);
  TRC_CHECK(PointsAndScalars(p, grid) == EXIT_SUCCESS);
  TRC_CHECK(Everything(p, grid) == EXIT_SUCCESS);
  TRC_CHECK(TorusTranslation(argc, argv) == EXIT_SUCCESS);
  TRC_CHECK(PointOrder(grid) == EXIT_SUCCESS);
  TRC_CHECK(FourPasses(argc, argv) == EXIT_SUCCESS);

  TRC_CHECK(std::string(vtkTetMeshBuilder::GetRebuildAsString(vtkTetMeshBuilder::RebuildPoints |
              vtkTetMeshBuilder::RebuildScalars)) == "points and scalars");
  return EXIT_SUCCESS;
}
