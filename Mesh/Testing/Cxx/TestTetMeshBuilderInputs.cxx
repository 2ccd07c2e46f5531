/*=========================================================================

  Program:   TiledRayCast
  Module:    TestTetMeshBuilderInputs.cxx

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// vtkTetMeshBuilder on small synthetic inputs, good and bad: no input, an empty grid, a 2D-only
// grid, a mixed hexahedron/wedge/pyramid/voxel/tetrahedron grid (split conformingly), quadratic
// tetrahedra, image data, a flat tetrahedron inside a mesh, a face shared by three
// tetrahedra, an unwelded seam (crack), duplicate points, bad point ids, NaN coordinates, NaN and
// infinite scalars, missing scalar arrays, cell scalars, 3-component arrays by component and
// by magnitude, and integer scalar types. Errors and warnings are caught by an observer (the
// test driver fails on printed errors) and checked.
#include "TetMeshTestUtilities.h"
#include "TiledRayCastMessageCounter.h"
#include "TiledRayCastTestGrids.h"

#include "vtkCellData.h"
#include "vtkCommand.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkIntArray.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkShortArray.h"
#include "vtkTetMesh.h"
#include "vtkTetMeshBuilder.h"
#include "vtkTetMeshCompactLayout.h"
#include "vtkTetMeshValidationReport.h"
#include "vtkTypeInt64Array.h"
#include "vtkUnsignedCharArray.h"
#include "vtkUnstructuredGrid.h"

#include <array>
#include <limits>
#include <map>

namespace
{
using trctest::AddCell;
using trctest::AddLinearScalars;
using trctest::MakeArray;
using trctest::MakeTetGrid;
using trctest::MessageCounter;

struct Builder
{
  vtkNew<vtkTetMeshBuilder> B;
  vtkNew<MessageCounter> Messages;
  Builder()
  {
    this->B->AddObserver(vtkCommand::ErrorEvent, this->Messages);
    this->B->AddObserver(vtkCommand::WarningEvent, this->Messages);
  }
  vtkTetMesh* Build(vtkDataSet* input)
  {
    this->Messages->Clear();
    return this->B->Build(input);
  }
};

bool Contains(const std::string& text, const char* what)
{
  return text.find(what) != std::string::npos;
}

// The mesh is refused, with an error that says `what`.
bool Refused(vtkTetMesh* mesh, const char* what)
{
  return !mesh->GetReport()->GetUsable() && Contains(mesh->GetReport()->GetErrorMessage(), what);
}

vtkIdType AddPoint(vtkPoints* points, double x, double y, double z)
{
  return points->InsertNextPoint(x, y, z);
}

// A 4 x 3 x 2 lattice of unit cubes' corners (id = i + 4 j + 12 k) plus the centre of cube
// (2, 0), filled with six cells of different kinds, one per unit cube.
vtkSmartPointer<vtkUnstructuredGrid> MakeMixedGrid()
{
  auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
  vtkNew<vtkPoints> points;
  for (int k = 0; k < 2; ++k)
  {
    for (int j = 0; j < 3; ++j)
    {
      for (int i = 0; i < 4; ++i)
      {
        AddPoint(points, i, j, k);
      }
    }
  }
  const vtkIdType centre = AddPoint(points, 2.5, 0.5, 0.5);
  grid->SetPoints(points);
  grid->Allocate(32);
  auto v = [](int i, int j, int c) -> vtkIdType
  {
    // Corner c of cube (i, j) in VTK hexahedron order.
    const int di[8] = { 0, 1, 1, 0, 0, 1, 1, 0 };
    const int dj[8] = { 0, 0, 1, 1, 0, 0, 1, 1 };
    const int dk[8] = { 0, 0, 0, 0, 1, 1, 1, 1 };
    return (i + di[c]) + 4 * (j + dj[c]) + 12 * dk[c];
  };
  // These corners of cube (i, j).
  auto corners = [&v](int i, int j, std::initializer_list<int> cs)
  {
    std::vector<vtkIdType> ids;
    for (int c : cs)
    {
      ids.push_back(v(i, j, c));
    }
    return ids;
  };
  // Cube (0, 0): a hexahedron.
  AddCell(grid, VTK_HEXAHEDRON, corners(0, 0, { 0, 1, 2, 3, 4, 5, 6, 7 }));
  // Cube (1, 0): two wedges (base normal pointing away from the top, VTK's convention).
  AddCell(grid, VTK_WEDGE, corners(1, 0, { 0, 2, 1, 4, 6, 5 }));
  AddCell(grid, VTK_WEDGE, corners(1, 0, { 0, 3, 2, 4, 7, 6 }));
  // Cube (2, 0): six pyramids around its centre (base normals towards the apex).
  const int pyramids[6][4] = { { 0, 1, 2, 3 }, { 4, 7, 6, 5 }, { 0, 4, 5, 1 }, { 3, 2, 6, 7 },
    { 0, 3, 7, 4 }, { 1, 5, 6, 2 } };
  for (const auto& base : pyramids)
  {
    AddCell(grid, VTK_PYRAMID,
      { v(2, 0, base[0]), v(2, 0, base[1]), v(2, 0, base[2]), v(2, 0, base[3]), centre });
  }
  // Cube (0, 1): six tetrahedra around the diagonal 0-6 (some of them inverted on purpose).
  const int kuhn[6][2] = { { 1, 2 }, { 2, 3 }, { 3, 7 }, { 7, 4 }, { 4, 5 }, { 5, 1 } };
  for (const auto& edge : kuhn)
  {
    AddCell(grid, VTK_TETRA, { v(0, 1, 0), v(0, 1, edge[0]), v(0, 1, edge[1]), v(0, 1, 6) });
  }
  // Cube (1, 1): a voxel (x fastest).
  AddCell(grid, VTK_VOXEL, corners(1, 1, { 0, 1, 3, 2, 4, 5, 7, 6 }));
  // Cube (2, 1): a hexahedron.
  AddCell(grid, VTK_HEXAHEDRON, corners(2, 1, { 0, 1, 2, 3, 4, 5, 6, 7 }));
  return grid;
}

// Volume of the tetrahedra of each input cell.
std::map<vtkIdType, double> VolumePerCell(vtkTetMesh* mesh)
{
  std::map<vtkIdType, double> volumes;
  for (vtkIdType t = 0; t < mesh->GetNumberOfTetrahedra(); ++t)
  {
    volumes[mesh->GetTetInputCellId(t)] += mesh->ComputeSignedVolume(t);
  }
  return volumes;
}

// Two tetrahedra above and below the square ABCD, two more, and the flat tetrahedron ABCD
// between them: the upper pair covers the square with diagonal AC, the lower pair with BD, and
// the flat tetrahedron's four faces are exactly those four triangles (it is the last cell).
vtkSmartPointer<vtkUnstructuredGrid> MakeSliverGrid()
{
  const vtkIdType a = 0, b = 1, c = 2, d = 3, e = 4, f = 5; // the points below, in order
  return MakeTetGrid(
    { { 0, 0, 0 }, { 1, 0, 0 }, { 1, 1, 0 }, { 0, 1, 0 }, { 0.5, 0.5, 1 }, { 0.5, 0.5, -1 } },
    { { e, a, b, c }, { e, a, c, d }, { f, a, b, d }, { f, b, c, d }, { a, b, c, d } });
}

int TestNoInput()
{
  Builder builder;
  vtkTetMesh* mesh = builder.Build(nullptr);
  TRC_CHECK(mesh != nullptr);
  TRC_CHECK(Refused(mesh, "no input"));
  TRC_CHECK(builder.Messages->Errors == 1);

  vtkNew<vtkUnstructuredGrid> empty;
  mesh = builder.Build(empty);
  TRC_CHECK(Refused(mesh, "empty"));
  TRC_CHECK(builder.Messages->Errors == 1);
  TRC_CHECK(mesh->GetNumberOfTetrahedra() == 0);
  TRC_CHECK(mesh->GetNumberOfBoundaryFaces() == 0);
  // Nothing changed: no new error, nothing rebuilt.
  builder.Build(empty);
  TRC_CHECK(builder.Messages->Errors == 0);
  TRC_CHECK(builder.B->GetLastRebuild() == vtkTetMeshBuilder::RebuildNothing);

  // Points but no cells.
  vtkNew<vtkPoints> points;
  AddPoint(points, 0, 0, 0);
  empty->SetPoints(points);
  mesh = builder.Build(empty);
  TRC_CHECK(Refused(mesh, "empty"));

  // A data set of another kind with no 3D cells.
  vtkNew<vtkPolyData> poly;
  vtkNew<vtkPoints> triangle;
  AddPoint(triangle, 0, 0, 0);
  AddPoint(triangle, 1, 0, 0);
  AddPoint(triangle, 0, 1, 0);
  poly->SetPoints(triangle);
  vtkNew<vtkCellArray> polys;
  const vtkIdType tri[3] = { 0, 1, 2 };
  polys->InsertNextCell(3, tri);
  poly->SetPolys(polys);
  mesh = builder.Build(poly);
  TRC_CHECK(Refused(mesh, "no 3D cells"));
  TRC_CHECK(mesh->GetReport()->GetNumberOfIgnoredCells() == 1);
  return EXIT_SUCCESS;
}

int Test2DOnly()
{
  vtkNew<vtkUnstructuredGrid> grid;
  vtkNew<vtkPoints> points;
  for (int k = 0; k < 4; ++k)
  {
    AddPoint(points, k % 2, k / 2, 0);
  }
  grid->SetPoints(points);
  grid->Allocate(4);
  AddCell(grid, VTK_TRIANGLE, { 0, 1, 2 });
  AddCell(grid, VTK_QUAD, { 0, 1, 3, 2 });
  AddCell(grid, VTK_LINE, { 0, 3 });
  AddCell(grid, VTK_VERTEX, { 1 });
  AddLinearScalars(grid);
  Builder builder;
  vtkTetMesh* mesh = builder.Build(grid);
  vtkTetMeshValidationReport* report = mesh->GetReport();
  TRC_CHECK(Refused(mesh, "no 3D cells"));
  TRC_CHECK(report->GetNumberOfIgnoredCells() == 4);
  TRC_CHECK(report->GetNumberOfInputCells() == 4);
  TRC_CHECK(mesh->GetNumberOfTetrahedra() == 0);
  TRC_CHECK(builder.Messages->Errors == 1);
  // A layout refuses the unusable mesh, with an error, without crashing.
  vtkNew<vtkTetMeshCompactLayout> layout;
  vtkNew<MessageCounter> layoutMessages;
  layout->AddObserver(vtkCommand::ErrorEvent, layoutMessages);
  TRC_CHECK(!layout->Build(mesh));
  TRC_CHECK(!layout->GetValid());
  TRC_CHECK(layoutMessages->Errors == 1);
  return EXIT_SUCCESS;
}

int TestMixed()
{
  vtkSmartPointer<vtkUnstructuredGrid> grid3D = MakeMixedGrid();
  const vtkIdType cells3D = grid3D->GetNumberOfCells();
  // VTK's surface of the 3D cells: every quad becomes two of our triangles.
  vtkIdType quads = 0;
  const std::vector<trc::Triangle> surfaceTriangles = trc::SurfaceFilterBoundary(grid3D, &quads);
  const vtkIdType expectedBoundary = static_cast<vtkIdType>(surfaceTriangles.size()) + 2 * quads;

  // The same grid with cells of lower dimension, which are ignored.
  vtkNew<vtkUnstructuredGrid> grid;
  grid->DeepCopy(grid3D);
  AddCell(grid, VTK_TRIANGLE, { 0, 1, 4 });
  AddCell(grid, VTK_VERTEX, { 5 });
  AddLinearScalars(grid);

  Builder builder;
  vtkTetMesh* mesh = builder.Build(grid);
  vtkTetMeshValidationReport* report = mesh->GetReport();
  std::cout << "mixed: " << report->GetSummary() << "\n";
  TRC_CHECK(report->GetUsable());
  // Everything but the six Kuhn tetrahedra is split (counted, normal service: no warning); one
  // warning for the ignored cells.
  TRC_CHECK(report->GetNumberOfSplitCells() == cells3D - 6);
  TRC_CHECK(report->GetNumberOfIgnoredCells() == 2);
  TRC_CHECK(builder.Messages->Warnings == 1);
  TRC_CHECK(report->HasDefects() && report->HasProblems());
  TRC_CHECK(builder.Messages->Errors == 0);
  TRC_CHECK(Contains(builder.Messages->LastWarning, "Ignored 2 cells"));
  TRC_CHECK(report->GetNumberOfNonManifoldFaces() == 0);
  TRC_CHECK(report->GetNumberOfDegenerateTetrahedra() == 0);
  TRC_CHECK(report->GetNumberOfCrackFaces() == 0);
  TRC_CHECK_EMPTY(trc::CheckNeighbors(mesh));
  TRC_CHECK_EMPTY(trc::CheckOrientation(mesh));
  // Conforming split: no internal face left unmatched.
  TRC_CHECK(mesh->GetNumberOfBoundaryFaces() == expectedBoundary);
  TRC_CHECK(trc::ScalarReproductionError(mesh) < 1e-12);

  // Each cell's tetrahedra fill exactly its volume.
  std::map<vtkIdType, double> volumes = VolumePerCell(mesh);
  TRC_CHECK(static_cast<vtkIdType>(volumes.size()) == cells3D);
  double total = 0.0;
  for (const auto& cell : volumes)
  {
    const int type = grid->GetCellType(cell.first);
    const double expected = type == VTK_WEDGE      ? 0.5
      : (type == VTK_PYRAMID || type == VTK_TETRA) ? 1.0 / 6.0
                                                   : 1.0;
    TRC_CHECK(std::abs(cell.second - expected) < 1e-12);
    total += cell.second;
  }
  TRC_CHECK(std::abs(total - 6.0) < 1e-12);

  // Cell scalars of split cells: each tetrahedron carries its input cell's value.
  vtkNew<vtkIntArray> cellValues;
  cellValues->SetName("cellid");
  cellValues->SetNumberOfTuples(grid->GetNumberOfCells());
  for (vtkIdType c = 0; c < grid->GetNumberOfCells(); ++c)
  {
    cellValues->SetValue(c, static_cast<int>(10 * c));
  }
  grid->GetCellData()->SetScalars(cellValues);
  builder.B->GetScalarSelection()->SetScalarMode(VTK_SCALAR_MODE_USE_CELL_DATA);
  mesh = builder.Build(grid);
  TRC_CHECK(builder.B->GetLastRebuild() == vtkTetMeshBuilder::RebuildScalars);
  TRC_CHECK(mesh->GetHasCellScalars());
  TRC_CHECK(mesh->GetCellScalars() != nullptr && mesh->GetPointScalars() == nullptr);
  for (vtkIdType t = 0; t < mesh->GetNumberOfTetrahedra(); ++t)
  {
    TRC_CHECK(mesh->GetCellScalars()[t] == 10.0 * mesh->GetTetInputCellId(t));
    double gc[4];
    TRC_CHECK(mesh->ComputeScalarGradient(t, gc));
    TRC_CHECK(
      gc[0] == 0.0 && gc[1] == 0.0 && gc[2] == 0.0 && gc[3] == 10.0 * mesh->GetTetInputCellId(t));
  }
  double range[2];
  mesh->GetScalarRange(range);
  // The range covers the whole array (the ignored cells' values too), as VTK's own.
  TRC_CHECK(range[0] == 0.0 && range[1] == 10.0 * (grid->GetNumberOfCells() - 1));
  // A scalars-only rebuild warns of nothing (the ignored cells were told of once).
  TRC_CHECK(builder.Messages->Warnings == 0);
  return EXIT_SUCCESS;
}

int TestQuadratic()
{
  // Two quadratic tetrahedra sharing the face (0, 1, 2) and its mid-edge nodes.
  vtkNew<vtkUnstructuredGrid> grid;
  vtkNew<vtkPoints> points;
  const double corners[5][3] = { { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 },
    { 0.25, 0.25, -1 } };
  for (const auto& c : corners)
  {
    points->InsertNextPoint(c);
  }
  std::map<std::pair<vtkIdType, vtkIdType>, vtkIdType> mids;
  auto mid = [&](vtkIdType a, vtkIdType b)
  {
    const auto key = std::make_pair(std::min(a, b), std::max(a, b));
    auto it = mids.find(key);
    if (it != mids.end())
    {
      return it->second;
    }
    double x[3];
    for (int k = 0; k < 3; ++k)
    {
      x[k] = 0.5 * (corners[a][k] + corners[b][k]);
    }
    return mids[key] = points->InsertNextPoint(x);
  };
  grid->SetPoints(points);
  grid->Allocate(2);
  // VTK order: corners 0..3, then mid-edges (0,1) (1,2) (2,0) (0,3) (1,3) (2,3).
  auto quadraticTet = [&](vtkIdType p0, vtkIdType p1, vtkIdType p2, vtkIdType p3)
  {
    AddCell(grid, VTK_QUADRATIC_TETRA,
      { p0, p1, p2, p3, mid(p0, p1), mid(p1, p2), mid(p2, p0), mid(p0, p3), mid(p1, p3),
        mid(p2, p3) });
  };
  quadraticTet(0, 1, 2, 3);
  quadraticTet(0, 2, 1, 4);
  AddLinearScalars(grid);
  Builder builder;
  vtkTetMesh* mesh = builder.Build(grid);
  std::cout << "quadratic: " << mesh->GetReport()->GetSummary() << "\n";
  TRC_CHECK(mesh->GetReport()->GetUsable());
  TRC_CHECK(mesh->GetReport()->GetNumberOfSplitCells() == 2);
  // Splitting is normal service: counted in the report, no warning.
  TRC_CHECK(builder.Messages->Warnings == 0);
  TRC_CHECK(mesh->GetReport()->HasDefects() && !mesh->GetReport()->HasProblems());
  TRC_CHECK_EMPTY(trc::CheckNeighbors(mesh));
  TRC_CHECK_EMPTY(trc::CheckOrientation(mesh));
  // Each of the 6 outer faces is split into 4 triangles; the shared face is matched.
  TRC_CHECK(mesh->GetNumberOfBoundaryFaces() == 24);
  std::map<vtkIdType, double> volumes = VolumePerCell(mesh);
  TRC_CHECK(std::abs(volumes[0] - 1.0 / 6.0) < 1e-12);
  TRC_CHECK(std::abs(volumes[1] - 1.0 / 6.0) < 1e-12); // base 1/2, height 1 (exact coordinates)
  return EXIT_SUCCESS;
}

int TestImageData()
{
  vtkNew<vtkImageData> image;
  image->SetDimensions(3, 3, 2);
  image->SetSpacing(0.5, 1.0, 2.0);
  image->SetOrigin(100.0, 0.0, 0.0);
  AddLinearScalars(image);
  Builder builder;
  vtkTetMesh* mesh = builder.Build(image);
  TRC_CHECK(mesh->GetReport()->GetUsable());
  TRC_CHECK(mesh->GetReport()->GetNumberOfSplitCells() == 4);
  TRC_CHECK_EMPTY(trc::CheckNeighbors(mesh));
  TRC_CHECK_EMPTY(trc::CheckOrientation(mesh));
  double total = 0.0;
  for (vtkIdType t = 0; t < mesh->GetNumberOfTetrahedra(); ++t)
  {
    total += mesh->ComputeSignedVolume(t);
  }
  TRC_CHECK(std::abs(total - 1.0 * 2.0 * 2.0) < 1e-12);
  // A box of 2 x 2 x 1 cells: 2 * (4 + 2 + 2) quads on its surface, 2 triangles each.
  TRC_CHECK(mesh->GetNumberOfBoundaryFaces() == 32);
  double shift[3];
  mesh->GetShift(shift);
  TRC_CHECK(shift[0] == 100.5 && shift[1] == 1.0 && shift[2] == 1.0);
  TRC_CHECK(trc::ScalarReproductionError(mesh) < 1e-12);
  return EXIT_SUCCESS;
}

int TestSliver()
{
  vtkSmartPointer<vtkUnstructuredGrid> grid = MakeSliverGrid();
  Builder builder;
  vtkTetMesh* mesh = builder.Build(grid);
  vtkTetMeshValidationReport* report = mesh->GetReport();
  TRC_CHECK(report->GetUsable());
  TRC_CHECK(report->GetNumberOfDegenerateTetrahedra() == 1);
  TRC_CHECK(report->GetDegenerateCellIds()->GetNumberOfValues() == 1);
  TRC_CHECK(report->GetDegenerateCellIds()->GetValue(0) == 4);
  TRC_CHECK(mesh->GetTetFlags(4) & vtkTetMesh::Degenerate);
  TRC_CHECK_EMPTY(trc::CheckNeighbors(mesh));
  TRC_CHECK_EMPTY(trc::CheckOrientation(mesh));
  // The flat tetrahedron keeps both sides connected: all four of its faces have neighbours,
  // two above and two below.
  std::vector<vtkIdType> around;
  for (int face = 0; face < 4; ++face)
  {
    around.push_back(mesh->GetNeighborTet(4, face));
  }
  std::sort(around.begin(), around.end());
  TRC_CHECK((around == std::vector<vtkIdType>{ 0, 1, 2, 3 }));
  // Only the eight slanted faces are boundary, as VTK's surface filter says.
  TRC_CHECK(mesh->GetNumberOfBoundaryFaces() == 8);
  TRC_CHECK(trc::MeshBoundary(mesh) == trc::SurfaceFilterBoundary(grid));
  // Its scalar field is constant (the mean), the others are exact.
  double gc[4];
  TRC_CHECK(mesh->ComputeScalarGradient(4, gc));
  TRC_CHECK(gc[0] == 0.0 && gc[1] == 0.0 && gc[2] == 0.0);
  TRC_CHECK(trc::ScalarReproductionError(mesh) < 1e-12);

  // A tetrahedron with a repeated point id is degenerate too, and its collapsed faces are left
  // unmatched: no crash, symmetric neighbours.
  AddCell(grid, VTK_TETRA, { 0, 0, 1, 5 });
  mesh = builder.Build(grid);
  std::cout << "sliver: " << mesh->GetReport()->GetSummary() << "\n";
  TRC_CHECK(mesh->GetReport()->GetNumberOfDegenerateTetrahedra() == 2);
  TRC_CHECK_EMPTY(trc::CheckNeighbors(mesh));
  return EXIT_SUCCESS;
}

// With `scratchLimit` 0 the faces are matched in four passes over ranges of point ids, as a
// huge mesh's are (vtkTetMeshFaceMatching): the same result.
int TestNonManifoldWith(vtkIdType scratchLimit)
{
  // Three tetrahedra on the face ABC: two above (apexes E and G), one below (F).
  vtkSmartPointer<vtkUnstructuredGrid> grid = MakeTetGrid(
    { { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { 0.2, 0.2, 1 }, { 0.2, 0.2, -1 }, { 0.3, 0.3, 2 } },
    { { 0, 1, 2, 3 }, { 0, 1, 2, 4 }, { 0, 1, 2, 5 } });
  Builder builder;
  builder.B->SetMaximumKeptScratchMemory(scratchLimit);
  vtkTetMesh* mesh = builder.Build(grid);
  TRC_CHECK(mesh->GetReport()->GetUsable());
  TRC_CHECK(mesh->GetReport()->GetNumberOfNonManifoldFaces() == 1);
  TRC_CHECK_EMPTY(trc::CheckNeighbors(mesh));
  // The two above overlap: the later one in input order (2, apex G) is left out
  // (vtkTetMeshOverlapRule): no neighbours, no boundary faces. Tetrahedra 0 and 1 are
  // neighbours across ABC, and their 3 + 3 other faces are the boundary.
  TRC_CHECK(mesh->GetReport()->GetNumberOfOverlappingTetrahedra() == 1);
  TRC_CHECK(mesh->GetNumberOfBoundaryFaces() == 6);
  TRC_CHECK(mesh->GetTetFlags(2) & vtkTetMesh::Overlapping);
  TRC_CHECK(!(mesh->GetTetFlags(0) & vtkTetMesh::Overlapping));
  vtkIdType below = -1;
  for (int face = 0; face < 4; ++face)
  {
    below = std::max(below, mesh->GetNeighborTet(1, face));
    TRC_CHECK(mesh->GetNeighborTet(2, face) < 0);
  }
  TRC_CHECK(below == 0);

  // A cell listed twice: every face of the copy lies on the same side as the original's, so
  // the copy is left out and the original keeps its neighbour.
  AddCell(grid, VTK_TETRA, { 0, 1, 2, 4 });
  grid->Modified();
  mesh = builder.Build(grid);
  TRC_CHECK(mesh->GetReport()->GetNumberOfOverlappingTetrahedra() == 2);
  TRC_CHECK(mesh->GetTetFlags(3) & vtkTetMesh::Overlapping);
  TRC_CHECK(mesh->GetNumberOfBoundaryFaces() == 6);
  TRC_CHECK_EMPTY(trc::CheckNeighbors(mesh));
  return EXIT_SUCCESS;
}

int TestNonManifold()
{
  TRC_CHECK(TestNonManifoldWith(vtkIdType(1) << 31) == EXIT_SUCCESS);
  TRC_CHECK(TestNonManifoldWith(0) == EXIT_SUCCESS);
  return EXIT_SUCCESS;
}

int TestCrackAndDuplicates()
{
  // Two tetrahedra on either side of the triangle ABC, the upper one using copies of A, B, C:
  // the mesh is cut along ABC (two coincident boundary faces, a crack).
  // The last point is an unused duplicate.
  vtkSmartPointer<vtkUnstructuredGrid> grid =
    MakeTetGrid({ { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { 0.2, 0.2, -1 }, { 0, 0, 0 }, { 1, 0, 0 },
                  { 0, 1, 0 }, { 0.2, 0.2, 1 }, { 0.2, 0.2, 1 } },
      { { 0, 1, 2, 3 }, { 4, 5, 6, 7 } });
  Builder builder;
  vtkTetMesh* mesh = builder.Build(grid);
  vtkTetMeshValidationReport* report = mesh->GetReport();
  TRC_CHECK(report->GetUsable());
  TRC_CHECK(report->GetNumberOfDuplicatePoints() == 4);
  TRC_CHECK(report->GetNumberOfCrackFaces() == 2);
  TRC_CHECK(mesh->GetNumberOfBoundaryFaces() == 8);
  TRC_CHECK(report->HasDefects());
  TRC_CHECK(Contains(report->GetSummary(), "2 crack faces"));

  // The same cut with the upper triangle split differently (as along post_tets5_classic's
  // seam): a square ABCD below with diagonal AC, its copy above with diagonal BD.
  // Points 0-3 and 4-7 are the square twice, 8 and 9 the apexes below and above.
  vtkSmartPointer<vtkUnstructuredGrid> seam =
    MakeTetGrid({ { 0, 0, 0 }, { 1, 0, 0 }, { 1, 1, 0 }, { 0, 1, 0 }, { 0, 0, 0 }, { 1, 0, 0 },
                  { 1, 1, 0 }, { 0, 1, 0 }, { 0.5, 0.5, -1 }, { 0.5, 0.5, 1 } },
      { { 0, 1, 2, 8 }, { 0, 2, 3, 8 }, { 4, 5, 7, 9 }, { 5, 6, 7, 9 } });
  mesh = builder.Build(seam);
  TRC_CHECK(mesh->GetReport()->GetNumberOfDuplicatePoints() == 4);
  TRC_CHECK(mesh->GetReport()->GetNumberOfCrackFaces() == 4);
  TRC_CHECK(mesh->GetNumberOfBoundaryFaces() == 12);
  return EXIT_SUCCESS;
}

int TestBadIdsAndCoordinates()
{
  vtkSmartPointer<vtkUnstructuredGrid> grid = MakeSliverGrid();
  AddCell(grid, VTK_TETRA, { 0, 1, 2, 99 });
  AddCell(grid, VTK_HEXAHEDRON, { 0, 1, 2, 3, 4, 5, -1, 7 });
  Builder builder;
  vtkTetMesh* mesh = builder.Build(grid);
  TRC_CHECK(mesh->GetReport()->GetUsable());
  TRC_CHECK(mesh->GetReport()->GetNumberOfInvalidCells() == 2);
  TRC_CHECK(mesh->GetNumberOfTetrahedra() == 5);
  TRC_CHECK(Contains(builder.Messages->LastWarning, "2 invalid cells"));
  TRC_CHECK_EMPTY(trc::CheckNeighbors(mesh));

  // A NaN coordinate: unusable, not a crash.
  vtkSmartPointer<vtkUnstructuredGrid> nan = MakeSliverGrid();
  nan->GetPoints()->SetPoint(5, 0.5, std::numeric_limits<double>::quiet_NaN(), -1);
  mesh = builder.Build(nan);
  TRC_CHECK(Refused(mesh, "NaN or infinite"));
  TRC_CHECK(builder.Messages->Errors == 1);
  // Fixing the point makes it usable again (a points change after a failed build: full).
  nan->GetPoints()->SetPoint(5, 0.5, 0.5, -1);
  nan->GetPoints()->Modified();
  mesh = builder.Build(nan);
  TRC_CHECK(mesh->GetReport()->GetUsable());
  TRC_CHECK(builder.B->GetLastRebuild() == vtkTetMeshBuilder::RebuildAll);
  TRC_CHECK(mesh->GetNumberOfTetrahedra() == 5);
  return EXIT_SUCCESS;
}

int TestNonFiniteScalars()
{
  vtkSmartPointer<vtkUnstructuredGrid> grid = MakeSliverGrid();
  vtkDoubleArray* s = vtkDoubleArray::SafeDownCast(grid->GetPointData()->GetScalars());
  s->SetValue(4, std::numeric_limits<double>::quiet_NaN()); // E: the two upper tets
  s->SetValue(5, -std::numeric_limits<double>::infinity()); // F: the two lower tets
  Builder builder;
  vtkTetMesh* mesh = builder.Build(grid);
  vtkTetMeshValidationReport* report = mesh->GetReport();
  TRC_CHECK(report->GetUsable());
  TRC_CHECK(report->GetNumberOfNonFiniteScalars() == 2);
  for (vtkIdType t = 0; t < 4; ++t)
  {
    TRC_CHECK(mesh->GetTetFlags(t) & vtkTetMesh::NonFiniteScalars);
    double gc[4];
    TRC_CHECK(!mesh->ComputeScalarGradient(t, gc));
  }
  TRC_CHECK(!(mesh->GetTetFlags(4) & vtkTetMesh::NonFiniteScalars));
  double range[2];
  mesh->GetScalarRange(range);
  TRC_CHECK(range[0] == 0.0 && range[1] == 3.0); // s over A, B, C, D only
  // The compact layout stores them as +infinity.
  vtkNew<vtkTetMeshCompactLayout> layout;
  TRC_CHECK(layout->Build(mesh));
  vtkDataArray* points = layout->GetArray(vtkTetMeshCompactLayout::PointsArray);
  TRC_CHECK(points->GetComponent(4, 3) == std::numeric_limits<double>::infinity());
  TRC_CHECK(points->GetComponent(5, 3) == std::numeric_limits<double>::infinity());
  // Stored minus the scalar shift, the middle of the range (vtkTetMesh::GetScalarShift).
  TRC_CHECK(mesh->GetScalarShift() == 1.5);
  TRC_CHECK(points->GetComponent(2, 3) == 3.0 - 1.5);

  // Cell scalars with a NaN: only that tetrahedron is transparent.
  auto c = MakeArray<vtkFloatArray>("c", grid->GetNumberOfCells(), [](vtkIdType k) { return k; });
  c->SetValue(2, std::numeric_limits<float>::quiet_NaN());
  grid->GetCellData()->SetScalars(c);
  builder.B->GetScalarSelection()->SetScalarMode(VTK_SCALAR_MODE_USE_CELL_DATA);
  mesh = builder.Build(grid);
  TRC_CHECK(builder.B->GetLastRebuild() == vtkTetMeshBuilder::RebuildScalars);
  TRC_CHECK(mesh->GetReport()->GetNumberOfNonFiniteScalars() == 1);
  for (vtkIdType t = 0; t < 5; ++t)
  {
    TRC_CHECK(((mesh->GetTetFlags(t) & vtkTetMesh::NonFiniteScalars) != 0) == (t == 2));
  }
  TRC_CHECK(layout->Update(mesh));
  TRC_CHECK(layout->GetNumberOfArrays() == 4);
  vtkDataArray* cells = layout->GetArray(vtkTetMeshCompactLayout::TetScalarsArray);
  TRC_CHECK(cells->GetNumberOfComponents() == 1 && cells->GetNumberOfTuples() == 5);
  TRC_CHECK(cells->GetComponent(2, 0) == std::numeric_limits<double>::infinity());
  TRC_CHECK(cells->GetComponent(3, 0) == 3.0 - mesh->GetScalarShift()); // stored shifted
  return EXIT_SUCCESS;
}

int TestScalarSelection()
{
  vtkSmartPointer<vtkUnstructuredGrid> grid = MakeSliverGrid();
  // The array "s" stays, but no array is the active scalars.
  grid->GetPointData()->SetActiveAttribute(-1, vtkDataSetAttributes::SCALARS);
  TRC_CHECK(grid->GetPointData()->GetScalars() == nullptr);
  Builder builder;
  vtkTetMesh* mesh = builder.Build(grid);
  TRC_CHECK(Refused(mesh, "no active point or cell scalars"));
  TRC_CHECK(builder.Messages->Errors == 1);
  // The topology is built all the same.
  TRC_CHECK(mesh->GetNumberOfTetrahedra() == 5);

  // An unknown array name.
  builder.B->GetScalarSelection()->SetScalarMode(VTK_SCALAR_MODE_USE_POINT_FIELD_DATA);
  builder.B->GetScalarSelection()->SelectScalarArray("nonexistent");
  mesh = builder.Build(grid);
  TRC_CHECK(Refused(mesh, "\"nonexistent\""));
  TRC_CHECK(builder.B->GetLastRebuild() == vtkTetMeshBuilder::RebuildScalars);

  // The right name: usable, and only the scalars were rebuilt.
  builder.B->GetScalarSelection()->SelectScalarArray("s");
  mesh = builder.Build(grid);
  TRC_CHECK(mesh->GetReport()->GetUsable());
  TRC_CHECK(builder.B->GetLastRebuild() == vtkTetMeshBuilder::RebuildScalars);
  TRC_CHECK(mesh->GetPointScalars()[2] == 1.0 + 2.0);
  // By index.
  builder.B->GetScalarSelection()->SelectScalarArray(0);
  mesh = builder.Build(grid);
  TRC_CHECK(mesh->GetReport()->GetUsable());
  builder.B->GetScalarSelection()->SelectScalarArray(7);
  mesh = builder.Build(grid);
  TRC_CHECK(Refused(mesh, "index 7"));

  // A 3-component array: each component, and the magnitude.
  vtkNew<vtkFloatArray> vectors;
  vectors->SetName("v");
  vectors->SetNumberOfComponents(3);
  vectors->SetNumberOfTuples(grid->GetNumberOfPoints());
  for (vtkIdType i = 0; i < grid->GetNumberOfPoints(); ++i)
  {
    vectors->SetTuple3(i, 3.0 * i, 4.0 * i, -1.0 * i);
  }
  grid->GetPointData()->AddArray(vectors);
  builder.B->GetScalarSelection()->SelectScalarArray("v");
  for (int component = 0; component < 3; ++component)
  {
    builder.B->GetScalarSelection()->SetVectorComponent(component);
    mesh = builder.Build(grid);
    TRC_CHECK(mesh->GetReport()->GetUsable());
    TRC_CHECK(builder.B->GetLastRebuild() == vtkTetMeshBuilder::RebuildScalars);
    const double factor[3] = { 3.0, 4.0, -1.0 };
    for (vtkIdType i = 0; i < grid->GetNumberOfPoints(); ++i)
    {
      TRC_CHECK(mesh->GetPointScalars()[i] == factor[component] * i);
    }
  }
  builder.B->GetScalarSelection()->SetVectorModeToMagnitude();
  mesh = builder.Build(grid);
  for (vtkIdType i = 0; i < grid->GetNumberOfPoints(); ++i)
  {
    TRC_CHECK(std::abs(mesh->GetPointScalars()[i] - std::sqrt(26.0) * i) < 1e-12);
  }
  builder.B->GetScalarSelection()->SetVectorModeToComponent();
  builder.B->GetScalarSelection()->SetVectorComponent(5);
  mesh = builder.Build(grid);
  TRC_CHECK(Refused(mesh, "component 5"));

  // Integer types, converted exactly.
  builder.B->GetScalarSelection()->SetVectorComponent(0);
  vtkNew<vtkUnsignedCharArray> uchar;
  vtkNew<vtkShortArray> shorts;
  vtkNew<vtkIntArray> ints;
  vtkNew<vtkTypeInt64Array> longs;
  vtkDataArray* arrays[4] = { uchar, shorts, ints, longs };
  const char* names[4] = { "uchar", "short", "int", "int64" };
  for (int a = 0; a < 4; ++a)
  {
    arrays[a]->SetName(names[a]);
    arrays[a]->SetNumberOfTuples(grid->GetNumberOfPoints());
    for (vtkIdType i = 0; i < grid->GetNumberOfPoints(); ++i)
    {
      arrays[a]->SetComponent(i, 0, a == 1 ? -7.0 * i : 40.0 * i);
    }
    grid->GetPointData()->AddArray(arrays[a]);
    builder.B->GetScalarSelection()->SelectScalarArray(names[a]);
    mesh = builder.Build(grid);
    TRC_CHECK(mesh->GetReport()->GetUsable());
    for (vtkIdType i = 0; i < grid->GetNumberOfPoints(); ++i)
    {
      TRC_CHECK(mesh->GetPointScalars()[i] == (a == 1 ? -7.0 * i : 40.0 * i));
    }
    double range[2];
    mesh->GetScalarRange(range);
    TRC_CHECK(range[0] == (a == 1 ? -35.0 : 0.0) && range[1] == (a == 1 ? 0.0 : 200.0));
  }
  // Cell data selected by name.
  grid->GetCellData()->AddArray(
    MakeArray<vtkShortArray>("cells", grid->GetNumberOfCells(), [](vtkIdType c) { return -c; }));
  builder.B->GetScalarSelection()->SetScalarMode(VTK_SCALAR_MODE_USE_CELL_FIELD_DATA);
  builder.B->GetScalarSelection()->SelectScalarArray("cells");
  mesh = builder.Build(grid);
  TRC_CHECK(mesh->GetReport()->GetUsable());
  TRC_CHECK(mesh->GetHasCellScalars());
  TRC_CHECK(mesh->GetCellScalars()[4] == -4.0);
  return EXIT_SUCCESS;
}
}

int TestTetMeshBuilderInputs(int, char*[])
{
  int (*tests[])() = { TestNoInput, Test2DOnly, TestMixed, TestQuadratic, TestImageData, TestSliver,
    TestNonManifold, TestCrackAndDuplicates, TestBadIdsAndCoordinates, TestNonFiniteScalars,
    TestScalarSelection };
  for (auto test : tests)
  {
    if (test() != EXIT_SUCCESS)
    {
      return EXIT_FAILURE;
    }
  }
  return EXIT_SUCCESS;
}
