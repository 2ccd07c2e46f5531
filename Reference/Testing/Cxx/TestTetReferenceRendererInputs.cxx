/*=========================================================================

  Program:   TiledRayCast
  Module:    TestTetReferenceRendererInputs.cxx

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// What the reference renderer accepts and refuses:
//  - bad input (no input, empty grid, no scalars, an unknown array, no camera, no property, a
//    bad image size, a depth buffer of the wrong size, only 2D cells, only degenerate cells, an
//    unsupported colour space): Render() returns 0 with an error and no crash;
//  - NaN scalars make their tetrahedra transparent (still counted as crossed);
//  - degenerate (zero-volume) tetrahedra change nothing;
//  - hexahedra and voxels (image data) are split; triangles and lines are ignored;
//  - cell scalars, scalar arrays chosen by name, the magnitude or a component of vectors;
//  - the output helpers (compositing over a background, 8-bit conversion, image comparison);
//  - repeated renders are identical (threads do not change results).
#include "TetReferenceTestUtilities.h"

#include "vtkCellType.h"
#include "vtkDoubleArray.h"
#include "vtkImageData.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkTestErrorObserver.h"
#include "vtkTetRayIntegrator.h"
#include "vtkTetReferenceRenderer.h"
#include "vtkTetScalarSelection.h"
#include "vtkUnsignedCharArray.h"
#include "vtkUnstructuredGrid.h"

#include <limits>
#include <sstream>

namespace
{
double Difference(vtkImageData* a, vtkImageData* b)
{
  double stats[3];
  if (!vtkTetReferenceRenderer::CompareImages(a, b, stats))
  {
    return std::numeric_limits<double>::infinity();
  }
  return stats[2] / 255.0;
}
// What every check below starts from: a cube of constant medium, a camera, and the reference
// image of the cube rendered by `Good` (a renderer the last check uses again).
struct Fixture
{
  double Color[3] = { 0.9, 0.4, 0.1 };
  double Tau = 0.6;
  vtkSmartPointer<vtkVolumeProperty> Constant = trc::ConstantProperty(this->Tau, this->Color);
  double (*Flat)(double, double, double) = [](double, double, double) { return 0.5; };
  double Origin[3] = { 0, 0, 0 };
  vtkSmartPointer<vtkCamera> Camera;
  trc::Box CubeBox = { { 0, 0, 0 }, { 2, 2, 2 }, 1.0 };
  vtkSmartPointer<vtkUnstructuredGrid> Cube;
  vtkNew<vtkTetReferenceRenderer> Good;
  vtkNew<vtkImageData> Reference;
};

// Bad input: refused with an error, never a crash.
int BadInput(Fixture& f)
{
  vtkNew<vtkTest::ErrorObserver> errors;
  auto expectFailure = [&errors](vtkTetReferenceRenderer* r, const char* what)
  {
    errors->Clear();
    const int ok = r->Render();
    if (ok || !errors->GetError())
    {
      std::cerr << what << ": not refused" << std::endl;
      return false;
    }
    // VTK's messages read "ERROR: In <file>, line <n>\n<class> (<address>): <text>\n";
    // print the first text only (ctest fails a test whose output has "ERROR: " lines).
    const std::string message = errors->GetErrorMessage();
    const size_t begin = message.find("): ");
    const size_t end = message.find('\n', begin == std::string::npos ? 0 : begin);
    std::cout << what << ": refused ("
              << (begin == std::string::npos ? std::string("?")
                                             : message.substr(begin + 3, end - begin - 3))
              << ")" << std::endl;
    return r->GetOutput()->GetNumberOfPoints() == 0;
  };
  vtkNew<vtkTetReferenceRenderer> r;
  r->AddObserver(vtkCommand::ErrorEvent, errors);
  r->GetIntegrator()->AddObserver(vtkCommand::ErrorEvent, errors);
  r->SetVolumeProperty(f.Constant);
  r->SetCamera(f.Camera);
  r->SetImageSize(8, 8);
  TRC_CHECK(expectFailure(r, "no input"));

  vtkNew<vtkUnstructuredGrid> empty;
  r->SetInputData(empty);
  TRC_CHECK(expectFailure(r, "empty grid"));

  vtkNew<vtkUnstructuredGrid> noScalars;
  noScalars->DeepCopy(f.Cube);
  noScalars->GetPointData()->SetScalars(nullptr);
  noScalars->GetCellData()->RemoveArray("CellField");
  r->SetInputData(noScalars);
  TRC_CHECK(expectFailure(r, "no scalars"));

  r->SetInputData(f.Cube);
  r->GetScalarSelection()->SetScalarModeToUsePointFieldData();
  r->GetScalarSelection()->SelectScalarArray("NoSuchArray");
  TRC_CHECK(expectFailure(r, "unknown array"));
  r->GetScalarSelection()->SetScalarModeToDefault();

  r->SetCamera(nullptr);
  TRC_CHECK(expectFailure(r, "no camera"));
  r->SetCamera(f.Camera);

  r->SetVolumeProperty(nullptr);
  TRC_CHECK(expectFailure(r, "no property"));
  r->SetVolumeProperty(f.Constant);

  r->SetImageSize(0, 8);
  TRC_CHECK(expectFailure(r, "image size 0"));
  r->SetImageSize(8, 8);

  vtkNew<vtkFloatArray> depth;
  depth->SetNumberOfTuples(10);
  depth->FillValue(0.5f);
  r->SetOpaqueDepth(depth);
  TRC_CHECK(expectFailure(r, "depth buffer of the wrong size"));
  r->SetOpaqueDepth(nullptr);

  vtkNew<vtkUnstructuredGrid> triangles;
  vtkNew<vtkPoints> points;
  points->InsertNextPoint(0, 0, 0);
  points->InsertNextPoint(1, 0, 0);
  points->InsertNextPoint(0, 1, 0);
  points->InsertNextPoint(0, 0, 1);
  triangles->SetPoints(points);
  const vtkIdType tri[3] = { 0, 1, 2 };
  triangles->InsertNextCell(VTK_TRIANGLE, 3, tri);
  vtkNew<vtkDoubleArray> s4;
  s4->SetNumberOfTuples(4);
  s4->FillValue(0.5);
  triangles->GetPointData()->SetScalars(s4);
  r->SetInputData(triangles);
  TRC_CHECK(expectFailure(r, "only 2D cells"));

  vtkNew<vtkUnstructuredGrid> flatTets;
  vtkNew<vtkPoints> coplanar;
  coplanar->InsertNextPoint(0, 0, 0);
  coplanar->InsertNextPoint(1, 0, 0);
  coplanar->InsertNextPoint(0, 1, 0);
  coplanar->InsertNextPoint(1, 1, 0);
  flatTets->SetPoints(coplanar);
  const vtkIdType tet[4] = { 0, 1, 2, 3 };
  flatTets->InsertNextCell(VTK_TETRA, 4, tet);
  flatTets->GetPointData()->SetScalars(s4);
  r->SetInputData(flatTets);
  TRC_CHECK(expectFailure(r, "only zero-volume tetrahedra"));

  auto ciede = vtkSmartPointer<vtkVolumeProperty>::New();
  vtkNew<vtkColorTransferFunction> ciedeColor;
  ciedeColor->AddRGBPoint(0.0, 1, 0, 0);
  ciedeColor->AddRGBPoint(1.0, 0, 0, 1);
  ciedeColor->SetColorSpaceToLabCIEDE2000();
  ciede->SetColor(ciedeColor);
  r->SetInputData(f.Cube);
  r->SetVolumeProperty(ciede);
  TRC_CHECK(expectFailure(r, "CIEDE2000 colour space"));
  r->SetVolumeProperty(f.Constant);

  // And it still works afterwards.
  errors->Clear();
  TRC_CHECK(r->Render() == 1 && !errors->GetError());
  return EXIT_SUCCESS;
}

// NaN scalars: the tetrahedra touching the NaN point are transparent, still crossed.
int NaNScalars(Fixture& f)
{
  vtkNew<vtkUnstructuredGrid> holed;
  holed->DeepCopy(f.Cube);
  vtkDataArray* s = holed->GetPointData()->GetScalars();
  // The point (1, 1, 2) (id 1 + 3 (1 + 3 * 2) = 22) on the top face.
  s->SetComponent(22, 0, std::numeric_limits<double>::quiet_NaN());
  vtkNew<vtkTetReferenceRenderer> r;
  r->SetInputData(holed);
  r->SetVolumeProperty(f.Constant);
  r->SetCamera(f.Camera);
  r->SetImageSize(24, 20);
  r->DoublePrecisionOutputOn();
  TRC_CHECK(r->Render());
  vtkImageData* image = r->GetOutput();
  double lessOpaque = 0.0;
  for (int j = 0; j < 20; ++j)
  {
    for (int i = 0; i < 24; ++i)
    {
      double a[4], b[4];
      trc::Pixel(image, i, j, a);
      trc::Pixel(f.Reference, i, j, b);
      TRC_CHECK(a[3] <= b[3] + 1e-15); // never more opaque
      TRC_CHECK(trc::TetCount(image, i, j) == trc::TetCount(f.Reference, i, j));
      lessOpaque += b[3] - a[3];
      TRC_CHECK(std::isfinite(a[0]) && std::isfinite(a[3]));
    }
  }
  TRC_CHECK(lessOpaque > 1.0);
  return EXIT_SUCCESS;
}

// Degenerate tetrahedra (zero volume) are skipped and change nothing.
int DegenerateTetrahedra(Fixture& f)
{
  vtkNew<vtkUnstructuredGrid> withFlat;
  withFlat->DeepCopy(f.Cube);
  // Four coplanar points of the grid (the plane z = 1) and a repeated point.
  const vtkIdType flatIds[4] = { 9, 10, 12, 13 };
  const vtkIdType repeated[4] = { 0, 1, 1, 4 };
  withFlat->InsertNextCell(VTK_TETRA, 4, flatIds);
  withFlat->InsertNextCell(VTK_TETRA, 4, repeated);
  vtkDataArray* cs = withFlat->GetCellData()->GetArray("CellField");
  cs->InsertNextTuple1(0.5);
  cs->InsertNextTuple1(0.5);
  vtkNew<vtkTetReferenceRenderer> r;
  r->SetInputData(withFlat);
  r->SetVolumeProperty(f.Constant);
  r->SetCamera(f.Camera);
  r->SetImageSize(24, 20);
  r->DoublePrecisionOutputOn();
  TRC_CHECK(r->Render());
  TRC_CHECK(r->GetNumberOfDegenerateTetrahedra() == 2);
  TRC_CHECK(r->GetNumberOfTetrahedra() == 40);
  TRC_CHECK(Difference(r->GetOutput(), f.Reference) <= 1e-15);
  return EXIT_SUCCESS;
}

// A flat tetrahedron (6|V| = 1e-15 L^3, the sign of rounding noise) listed before a real one
// that shares its face, on the same side of it: dropped as degenerate, not kept as the first of
// an overlapping pair, which would leave the real one out (torus_vistrails' flat boundary
// tetrahedra did so: up to 111/255 off). The real one renders as alone.
int FlatBeforeReal(Fixture& f)
{
  vtkNew<vtkPoints> points;
  points->InsertNextPoint(0, 0, 0);
  points->InsertNextPoint(1, 0, 0);
  points->InsertNextPoint(0, 1, 0);
  points->InsertNextPoint(0.3, 0.3, 1e-15); // nearly in the plane of the first three
  points->InsertNextPoint(0.3, 0.3, 1.0);   // the real tetrahedron's apex, on the same side
  vtkNew<vtkDoubleArray> scalars;
  scalars->SetName("s");
  for (int i = 0; i < 5; ++i)
  {
    scalars->InsertNextValue(0.5);
  }
  const double focal[3] = { 0.3, 0.3, 0.3 }, dir[3] = { 0.3, -0.4, 0.85 }, up[3] = { 0, 1, 0 };
  auto camera = trc::MakeCamera(focal, dir, up, 4.0, false, 30.0, 0.5, 10.0);
  vtkSmartPointer<vtkImageData> images[2];
  for (int withFlat = 0; withFlat < 2; ++withFlat)
  {
    vtkNew<vtkUnstructuredGrid> grid;
    grid->SetPoints(points);
    grid->GetPointData()->SetScalars(scalars);
    const vtkIdType flatIds[4] = { 0, 1, 2, 3 }, realIds[4] = { 0, 1, 2, 4 };
    if (withFlat)
    {
      grid->InsertNextCell(VTK_TETRA, 4, flatIds);
    }
    grid->InsertNextCell(VTK_TETRA, 4, realIds);
    vtkNew<vtkTetReferenceRenderer> r;
    r->SetInputData(grid);
    r->SetVolumeProperty(f.Constant);
    r->SetCamera(camera);
    r->SetImageSize(16, 16);
    r->DoublePrecisionOutputOn();
    TRC_CHECK(r->Render());
    TRC_CHECK(r->GetNumberOfTetrahedra() == 1);
    TRC_CHECK(r->GetNumberOfDegenerateTetrahedra() == withFlat);
    images[withFlat] = vtkSmartPointer<vtkImageData>::New();
    images[withFlat]->DeepCopy(r->GetOutput());
  }
  TRC_CHECK(Difference(images[0], images[1]) == 0.0);
  return EXIT_SUCCESS;
}

// Other cells: hexahedra and image data voxels are split; triangles and lines ignored.
int OtherCells(Fixture& f)
{
  vtkNew<vtkUnstructuredGrid> hexes;
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  for (int k = 0; k <= 2; ++k)
  {
    for (int j = 0; j <= 2; ++j)
    {
      for (int i = 0; i <= 2; ++i)
      {
        points->InsertNextPoint(i, j, k);
      }
    }
  }
  hexes->SetPoints(points);
  auto id = [](int i, int j, int k) { return static_cast<vtkIdType>(i + 3 * (j + 3 * k)); };
  for (int k = 0; k < 2; ++k)
  {
    for (int j = 0; j < 2; ++j)
    {
      for (int i = 0; i < 2; ++i)
      {
        const vtkIdType h[8] = { id(i, j, k), id(i + 1, j, k), id(i + 1, j + 1, k), id(i, j + 1, k),
          id(i, j, k + 1), id(i + 1, j, k + 1), id(i + 1, j + 1, k + 1), id(i, j + 1, k + 1) };
        hexes->InsertNextCell(VTK_HEXAHEDRON, 8, h);
      }
    }
  }
  // Lower-dimensional cells mixed in are ignored.
  const vtkIdType line[2] = { 0, 26 };
  const vtkIdType tri[3] = { 0, 8, 26 };
  hexes->InsertNextCell(VTK_LINE, 2, line);
  hexes->InsertNextCell(VTK_TRIANGLE, 3, tri);
  vtkNew<vtkDoubleArray> s;
  s->SetNumberOfTuples(27);
  s->FillValue(0.5);
  hexes->GetPointData()->SetScalars(s);
  vtkNew<vtkTetReferenceRenderer> r;
  r->SetInputData(hexes);
  r->SetVolumeProperty(f.Constant);
  r->SetCamera(f.Camera);
  r->SetImageSize(24, 20);
  r->DoublePrecisionOutputOn();
  TRC_CHECK(r->Render());
  TRC_CHECK(r->GetNumberOfTetrahedra() >= 40);
  TRC_CHECK(trc::CheckBoxes(
              r->GetOutput(), f.Camera, 24, 20, { f.CubeBox }, f.Tau, f.Color, "hexahedra") > 0);

  vtkNew<vtkImageData> voxels;
  voxels->SetDimensions(3, 3, 3);
  voxels->SetSpacing(1, 1, 1);
  voxels->GetPointData()->SetScalars(s);
  r->SetInputData(voxels);
  TRC_CHECK(r->Render());
  TRC_CHECK(trc::CheckBoxes(r->GetOutput(), f.Camera, 24, 20, { f.CubeBox }, f.Tau, f.Color,
              "image data (voxels)") > 0);

  // Tetrahedra with a triangle and a line: the same image as the tetrahedra alone.
  vtkNew<vtkUnstructuredGrid> mixed;
  mixed->DeepCopy(f.Cube);
  mixed->InsertNextCell(VTK_LINE, 2, line);
  mixed->InsertNextCell(VTK_TRIANGLE, 3, tri);
  mixed->GetCellData()->GetArray("CellField")->InsertNextTuple1(0.5);
  mixed->GetCellData()->GetArray("CellField")->InsertNextTuple1(0.5);
  r->SetInputData(mixed);
  TRC_CHECK(r->Render());
  TRC_CHECK(r->GetNumberOfTetrahedra() == 40);
  TRC_CHECK(Difference(r->GetOutput(), f.Reference) <= 1e-15);
  return EXIT_SUCCESS;
}

// Scalar selection: cell scalars by name, vector components and magnitude.
int ScalarSelection(Fixture& f)
{
  auto ramp = vtkSmartPointer<vtkVolumeProperty>::New();
  vtkNew<vtkColorTransferFunction> c;
  c->AddRGBPoint(0.0, 0.0, 0.0, 1.0);
  c->AddRGBPoint(2.0, 1.0, 0.0, 0.0);
  vtkNew<vtkPiecewiseFunction> o;
  o->AddPoint(0.0, 0.1);
  o->AddPoint(2.0, 1.0);
  ramp->SetColor(c);
  ramp->SetScalarOpacity(o);

  // Piecewise-constant cell scalars = a point field that is constant per cell cannot be
  // written with point scalars; compare instead with a mesh whose points carry the same
  // constant everywhere: a constant cell field 1.25 equals a constant point field 1.25.
  auto constantField = [](double, double, double) { return 1.25; };
  auto mesh = trc::MakeGrid(2, 2, 2, f.Origin, 1.0, trc::Split::Six, constantField);
  vtkNew<vtkTetReferenceRenderer> byPoints, byCells;
  for (vtkTetReferenceRenderer* r : { byPoints.Get(), byCells.Get() })
  {
    r->SetInputData(mesh);
    r->SetVolumeProperty(ramp);
    r->SetCamera(f.Camera);
    r->SetImageSize(24, 20);
    r->DoublePrecisionOutputOn();
  }
  byCells->GetScalarSelection()->SetScalarModeToUseCellFieldData();
  byCells->GetScalarSelection()->SelectScalarArray("CellField");
  TRC_CHECK(byPoints->Render() && byCells->Render());
  TRC_CHECK(Difference(byPoints->GetOutput(), byCells->GetOutput()) <= 1e-14);

  // A varying cell field renders differently from its point counterpart but finitely.
  auto varying = [](double x, double y, double z) { return 0.2 + 0.5 * x + 0.2 * y + 0.1 * z; };
  auto mesh2 = trc::MakeGrid(2, 2, 2, f.Origin, 1.0, trc::Split::Six, varying);
  byCells->SetInputData(mesh2);
  byPoints->SetInputData(mesh2);
  TRC_CHECK(byPoints->Render() && byCells->Render());
  const double d = Difference(byPoints->GetOutput(), byCells->GetOutput());
  TRC_CHECK(d > 1e-4 && d < 0.5);

  // Vectors: component 1 of (0, s, 0) and the magnitude of (0.6 s, 0.8 s, 0) equal s.
  vtkNew<vtkDoubleArray> vectors, rotated;
  vectors->SetName("V");
  rotated->SetName("W");
  vectors->SetNumberOfComponents(3);
  rotated->SetNumberOfComponents(3);
  vtkDataArray* s = mesh2->GetPointData()->GetScalars();
  for (vtkIdType i = 0; i < s->GetNumberOfTuples(); ++i)
  {
    const double v = s->GetComponent(i, 0);
    vectors->InsertNextTuple3(0.0, v, 0.0);
    rotated->InsertNextTuple3(0.6 * v, 0.8 * v, 0.0);
  }
  mesh2->GetPointData()->AddArray(vectors);
  mesh2->GetPointData()->AddArray(rotated);
  vtkNew<vtkTetReferenceRenderer> byVector;
  byVector->SetInputData(mesh2);
  byVector->SetVolumeProperty(ramp);
  byVector->SetCamera(f.Camera);
  byVector->SetImageSize(24, 20);
  byVector->DoublePrecisionOutputOn();
  vtkTetScalarSelection* selection = byVector->GetScalarSelection();
  selection->SetScalarModeToUsePointFieldData();
  selection->SelectScalarArray("V");
  selection->SetVectorModeToComponent(); // the default follows the colour function (component 0)
  selection->SetVectorComponent(1);
  TRC_CHECK(byVector->Render());
  TRC_CHECK(Difference(byVector->GetOutput(), byPoints->GetOutput()) <= 1e-14);
  selection->SelectScalarArray("W");
  selection->SetVectorModeToMagnitude();
  TRC_CHECK(byVector->Render());
  TRC_CHECK(Difference(byVector->GetOutput(), byPoints->GetOutput()) <= 1e-12);
  selection->SetVectorModeToComponent();
  selection->SetVectorComponent(0); // 0.6 s: a different image
  TRC_CHECK(byVector->Render());
  TRC_CHECK(Difference(byVector->GetOutput(), byPoints->GetOutput()) > 1e-4);
  return EXIT_SUCCESS;
}

// Output helpers.
int OutputHelpers(Fixture& f)
{
  const double background[3] = { 0.2, 0.4, 0.6 };
  vtkNew<vtkImageData> rgb, rgb8;
  vtkTetReferenceRenderer::CompositeOverBackground(f.Reference, background, rgb);
  vtkTetReferenceRenderer::ConvertToUnsignedChar(f.Reference, background, rgb8);
  TRC_CHECK(rgb->GetNumberOfPoints() == 24 * 20 && rgb8->GetNumberOfPoints() == 24 * 20);
  TRC_CHECK(vtkUnsignedCharArray::SafeDownCast(rgb8->GetPointData()->GetScalars()));
  for (vtkIdType p = 0; p < 24 * 20; ++p)
  {
    double rgba[4], c[3], c8[3];
    f.Reference->GetPointData()->GetArray("RGBA")->GetTuple(p, rgba);
    rgb->GetPointData()->GetScalars()->GetTuple(p, c);
    rgb8->GetPointData()->GetScalars()->GetTuple(p, c8);
    for (int k = 0; k < 3; ++k)
    {
      const double expected = rgba[k] + (1.0 - rgba[3]) * background[k];
      TRC_CHECK_NEAR(c[k], expected, 1e-7);
      TRC_CHECK(std::fabs(c8[k] - 255.0 * expected) <= 0.5 + 1e-9);
    }
  }
  double stats[3];
  TRC_CHECK(vtkTetReferenceRenderer::CompareImages(rgb, rgb8, stats));
  TRC_CHECK(stats[0] <= 0.5 && stats[1] <= 0.5 && stats[2] <= 0.5 + 1e-4);
  TRC_CHECK(vtkTetReferenceRenderer::CompareImages(rgb8, rgb8, stats) && stats[2] == 0.0);

  // The ray-cast display emulation: a uniform image stays uniform, truncated to 8 bits
  // (colour and alpha) and blended over the background.
  vtkNew<vtkImageData> uniform;
  uniform->SetDimensions(7, 5, 1);
  vtkNew<vtkDoubleArray> values;
  values->SetNumberOfComponents(4);
  values->SetNumberOfTuples(35);
  for (vtkIdType p = 0; p < 35; ++p)
  {
    values->SetTuple4(p, 0.5, 0.25, 0.1, 0.6);
  }
  uniform->GetPointData()->SetScalars(values);
  vtkNew<vtkImageData> shown;
  vtkTetReferenceRenderer::EmulateRayCastImageDisplay(uniform, background, shown);
  const double texel[4] = { 127, 63, 25, 153 }; // floor(255 v)
  for (vtkIdType p = 0; p < 35; ++p)
  {
    for (int k = 0; k < 3; ++k)
    {
      const double expected =
        std::round(255.0 * (texel[k] / 255.0 + (1.0 - texel[3] / 255.0) * background[k]));
      TRC_CHECK(shown->GetPointData()->GetScalars()->GetComponent(p, k) == expected);
    }
  }
  return EXIT_SUCCESS;
}

// Repeated renders (threads, cached mesh) are bitwise identical; the state prints.
int RepeatedRenders(Fixture& f)
{
  TRC_CHECK(f.Good->Render());
  TRC_CHECK(f.Good->GetLastPreparationTime() == 0.0); // cached
  TRC_CHECK(Difference(f.Good->GetOutput(), f.Reference) == 0.0);
  std::ostringstream printed;
  f.Good->Print(printed);
  TRC_CHECK(printed.str().find("NumberOfTetrahedra: 40") != std::string::npos);
  TRC_CHECK(printed.str().find("NumberOfNodes: 2") != std::string::npos); // the integrator
  return EXIT_SUCCESS;
}
} // namespace

int TestTetReferenceRendererInputs(int, char*[])
{
  Fixture f;
  const double focal[3] = { 1, 1, 1 }, dir[3] = { 0.3, -0.4, 0.85 }, up[3] = { 0, 1, 0 };
  f.Camera = trc::MakeCamera(focal, dir, up, 8.0, false, 30.0, 1.0, 20.0);
  f.Cube = trc::MakeGrid(2, 2, 2, f.Origin, 1.0, trc::Split::Five, f.Flat);

  // A reference image of the cube.
  vtkTetReferenceRenderer* good = f.Good;
  good->SetInputData(f.Cube);
  good->SetVolumeProperty(f.Constant);
  good->SetCamera(f.Camera);
  good->SetImageSize(24, 20);
  good->DoublePrecisionOutputOn();
  TRC_CHECK(good->Render());
  TRC_CHECK(good->GetNumberOfTetrahedra() == 40);
  TRC_CHECK(good->GetNumberOfDegenerateTetrahedra() == 0);
  TRC_CHECK(trc::CheckBoxes(
              good->GetOutput(), f.Camera, 24, 20, { f.CubeBox }, f.Tau, f.Color, "cube") > 0);
  f.Reference->DeepCopy(good->GetOutput());

  for (auto check : { BadInput, NaNScalars, DegenerateTetrahedra, FlatBeforeReal, OtherCells,
         ScalarSelection, OutputHelpers, RepeatedRenders })
  {
    TRC_CHECK(check(f) == EXIT_SUCCESS);
  }
  std::cout << "TestTetReferenceRendererInputs passed" << std::endl;
  return EXIT_SUCCESS;
}
