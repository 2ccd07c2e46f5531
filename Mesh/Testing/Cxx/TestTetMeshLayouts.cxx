/*=========================================================================

  Program:   TiledRayCast
  Module:    TestTetMeshLayouts.cxx

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// The two GPU layouts. On two tetrahedra whose every texel is computed by hand below: the
// paper layout (Figure 8 of Bernardon et al. 2004) is exactly 144 bytes per tetrahedron and
// holds the expected vertices, outward normals, neighbour texel coordinates and (g, c); the
// compact layout holds the expected ids, neighbour words, points and boundary faces. On a real
// mesh: exactly 144 B/tet when the width divides the number of tetrahedra, padding otherwise,
// errors (not garbage) beyond the texture limits, and the partial updates.
#include "TetMeshTestUtilities.h"
#include "TiledRayCastMessageCounter.h"

#include "vtkCommand.h"
#include "vtkDoubleArray.h"
#include "vtkPoints.h"
#include "vtkTestUtilities.h"
#include "vtkTetMeshBuilder.h"
#include "vtkUnstructuredGrid.h"
#include "vtkXMLUnstructuredGridReader.h"

namespace
{
bool Near(const float* texel, std::initializer_list<double> expected, double tol = 1e-7)
{
  int k = 0;
  for (double e : expected)
  {
    if (!(std::abs(texel[k] - e) <= tol))
    {
      std::cerr << "texel component " << k << " is " << texel[k] << ", expected " << e << "\n";
      return false;
    }
    ++k;
  }
  return true;
}

bool Equal(const uint32_t* texel, std::initializer_list<uint32_t> expected)
{
  int k = 0;
  for (uint32_t e : expected)
  {
    if (texel[k] != e)
    {
      std::cerr << "texel component " << k << " is " << texel[k] << ", expected " << e << "\n";
      return false;
    }
    ++k;
  }
  return true;
}

// Tetrahedron A = (P0, P1, P2, P3), the corner of the cube [0,2]^3 at the origin, and
// tetrahedron B = (P4, P1, P2, P3) on the other side of the face P1 P2 P3, given inverted
// (the builder stores it as (P4, P1, P3, P2)). Scalars s = 1 + x + 2y + 3z.
vtkSmartPointer<vtkUnstructuredGrid> MakeTwoTets()
{
  auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  const double p[5][3] = { { 0, 0, 0 }, { 2, 0, 0 }, { 0, 2, 0 }, { 0, 0, 2 }, { 2, 2, 2 } };
  vtkNew<vtkDoubleArray> s;
  s->SetName("s");
  for (const auto& x : p)
  {
    points->InsertNextPoint(x);
    s->InsertNextValue(1 + x[0] + 2 * x[1] + 3 * x[2]);
  }
  grid->SetPoints(points);
  grid->GetPointData()->SetScalars(s);
  grid->Allocate(2);
  const vtkIdType a[4] = { 0, 1, 2, 3 }, b[4] = { 4, 1, 2, 3 };
  grid->InsertNextCell(VTK_TETRA, 4, a);
  grid->InsertNextCell(VTK_TETRA, 4, b);
  return grid;
}

int TestHandComputed()
{
  vtkSmartPointer<vtkUnstructuredGrid> grid = MakeTwoTets();
  vtkNew<vtkTetMeshBuilder> builder;
  vtkTetMesh* mesh = builder->Build(grid);
  TRC_CHECK(mesh->GetReport()->GetUsable());
  TRC_CHECK(mesh->GetReport()->GetNumberOfInvertedTetrahedra() == 1);
  vtkIdType ids[4];
  mesh->GetTetPointIds(1, ids);
  TRC_CHECK(ids[0] == 4 && ids[1] == 1 && ids[2] == 3 && ids[3] == 2);
  double shift[3];
  mesh->GetShift(shift);
  TRC_CHECK(shift[0] == 1 && shift[1] == 1 && shift[2] == 1);

  // Paper layout, width 2: one row group, tetrahedron 0 in column 0, tetrahedron 1 in column 1.
  vtkNew<vtkTetMeshPaperLayout> paper;
  paper->SetTextureWidth(2);
  TRC_CHECK(paper->Build(mesh));
  TRC_CHECK(paper->GetNumberOfArrays() == 3);
  TRC_CHECK(std::string(paper->GetArrayName(0)) == "Vertices");
  TRC_CHECK(std::string(paper->GetArrayName(1)) == "FaceNormals");
  TRC_CHECK(std::string(paper->GetArrayName(2)) == "NeighborsAndScalars");
  for (int a = 0; a < 3; ++a)
  {
    int size[2];
    paper->GetArrayTextureSize(a, size);
    TRC_CHECK(size[0] == 2 && size[1] == 3);
    TRC_CHECK(paper->GetArrayKind(a) == vtkTetMeshLayout::Texture2D);
    TRC_CHECK(paper->GetArray(a)->GetNumberOfComponents() == 4);
    TRC_CHECK(paper->GetArray(a)->GetDataType() == VTK_FLOAT);
  }
  // 3 textures x 6 texels x 16 bytes for 2 tetrahedra: 144 bytes each, as in the paper.
  TRC_CHECK(paper->GetNumberOfBytes() == 288);
  TRC_CHECK(paper->GetBytesPerTet() == 144.0);
  auto texel = [&](int array, int column, int row) {
    return vtkFloatArray::SafeDownCast(paper->GetArray(array))->GetPointer(4 * (row * 2 + column));
  };
  // Vertices minus the shift (1, 1, 1): A = (-1,-1,-1) (1,-1,-1) (-1,1,-1) (-1,-1,1);
  // B = (1,1,1) (1,-1,-1) (-1,-1,1) (-1,1,-1). Row k: (vk.xyz, v3[k]).
  TRC_CHECK(Near(texel(0, 0, 0), { -1, -1, -1, -1 }));
  TRC_CHECK(Near(texel(0, 0, 1), { 1, -1, -1, -1 }));
  TRC_CHECK(Near(texel(0, 0, 2), { -1, 1, -1, 1 }));
  TRC_CHECK(Near(texel(0, 1, 0), { 1, 1, 1, -1 }));
  TRC_CHECK(Near(texel(0, 1, 1), { 1, -1, -1, 1 }));
  TRC_CHECK(Near(texel(0, 1, 2), { -1, -1, 1, -1 }));
  // Unit outward normals. A: n0 = (1,1,1)/sqrt3 (the slanted face), n1 = -x, n2 = -y, n3 = -z.
  // B: n0 = -(1,1,1)/sqrt3, n1 = (-1,1,1)/sqrt3, n2 = (1,1,-1)/sqrt3, n3 = (1,-1,1)/sqrt3.
  const double k = 1.0 / std::sqrt(3.0);
  TRC_CHECK(Near(texel(1, 0, 0), { k, k, k, 0 }));
  TRC_CHECK(Near(texel(1, 0, 1), { -1, 0, 0, 0 }));
  TRC_CHECK(Near(texel(1, 0, 2), { 0, -1, 0, -1 }));
  TRC_CHECK(Near(texel(1, 1, 0), { -k, -k, -k, k }));
  TRC_CHECK(Near(texel(1, 1, 1), { -k, k, k, -k }));
  TRC_CHECK(Near(texel(1, 1, 2), { k, k, -k, k }));
  // Neighbours as texel coordinates: A's face 0 leads to B at (1, 0), B's face 0 to A at (0, 0);
  // every other face is boundary (-1, -1). Row 2: (g, c) = (1, 2, 3, s(shift) = 7), c minus
  // the scalar shift (the middle of the scalar range, vtkTetMesh::GetScalarShift).
  const float c = static_cast<float>(7.0 - mesh->GetScalarShift());
  TRC_CHECK(Near(texel(2, 0, 0), { 1, 0, -1, -1 }));
  TRC_CHECK(Near(texel(2, 0, 1), { -1, -1, -1, -1 }));
  TRC_CHECK(Near(texel(2, 0, 2), { 1, 2, 3, c }, 1e-6));
  TRC_CHECK(Near(texel(2, 1, 0), { 0, 0, -1, -1 }));
  TRC_CHECK(Near(texel(2, 1, 1), { -1, -1, -1, -1 }));
  TRC_CHECK(Near(texel(2, 1, 2), { 1, 2, 3, c }, 1e-6));
  int tetTexel[2];
  paper->GetTetTexel(1, tetTexel);
  TRC_CHECK(tetTexel[0] == 1 && tetTexel[1] == 0);
  // Boundary faces, in order (0,1) (0,2) (0,3) (1,1) (1,2) (1,3); three texels each:
  // (a.xyz, u) (b.xyz, v) (c.xyz, face). A's face 1 is (p0, p3, p2).
  vtkDataArray* boundary = paper->GetBoundaryArray();
  TRC_CHECK(boundary->GetNumberOfTuples() == 18);
  TRC_CHECK(paper->GetNumberOfBoundaryBytes() == 6 * 48);
  const float* bf = vtkFloatArray::SafeDownCast(boundary)->GetPointer(0);
  TRC_CHECK(Near(bf, { -1, -1, -1, 0 }));
  TRC_CHECK(Near(bf + 4, { -1, -1, 1, 0 }));
  TRC_CHECK(Near(bf + 8, { -1, 1, -1, 1 }));
  // B's face 3 (the last) is (p0, p2, p1) = (P4, P3, P1), in column 1.
  TRC_CHECK(Near(bf + 60, { 1, 1, 1, 1 }));
  TRC_CHECK(Near(bf + 64, { -1, -1, 1, 0 }));
  TRC_CHECK(Near(bf + 68, { 1, -1, -1, 3 }));

  // Compact layout.
  vtkNew<vtkTetMeshCompactLayout> compact;
  TRC_CHECK(compact->Build(mesh));
  TRC_CHECK(compact->GetNumberOfArrays() == 3);
  TRC_CHECK(std::string(compact->GetArrayName(0)) == "TetPoints");
  TRC_CHECK(std::string(compact->GetArrayName(1)) == "TetNeighbors");
  TRC_CHECK(std::string(compact->GetArrayName(2)) == "Points");
  TRC_CHECK(compact->GetArrayKind(0) == vtkTetMeshLayout::TextureBuffer);
  TRC_CHECK(compact->GetArray(0)->GetDataType() == VTK_UNSIGNED_INT);
  int size[2];
  compact->GetArrayTextureSize(2, size);
  TRC_CHECK(size[0] == 5 && size[1] == 1);
  const uint32_t* tp = vtkTypeUInt32Array::SafeDownCast(compact->GetArray(0))->GetPointer(0);
  TRC_CHECK(Equal(tp, { 0, 1, 2, 3 }));
  TRC_CHECK(Equal(tp + 4, { 4, 1, 3, 2 }));
  const uint32_t* nb = vtkTypeUInt32Array::SafeDownCast(compact->GetArray(1))->GetPointer(0);
  const uint32_t none = 0xFFFFFFFFu;
  TRC_CHECK(Equal(nb, { (1u << 2) | 0u, none, none, none }));
  TRC_CHECK(Equal(nb + 4, { (0u << 2) | 0u, none, none, none }));
  // Scalars 1, 3, 5, 7, 13, stored minus the scalar shift, the middle of their range: 7.
  const float* pts = vtkFloatArray::SafeDownCast(compact->GetArray(2))->GetPointer(0);
  TRC_CHECK(mesh->GetScalarShift() == 7.0);
  TRC_CHECK(Near(pts, { -1, -1, -1, -6 }));
  TRC_CHECK(Near(pts + 4, { 1, -1, -1, -4 }));
  TRC_CHECK(Near(pts + 8, { -1, 1, -1, -2 }));
  TRC_CHECK(Near(pts + 12, { -1, -1, 1, 0 }));
  TRC_CHECK(Near(pts + 16, { 1, 1, 1, 6 }));
  const uint32_t* cb = vtkTypeUInt32Array::SafeDownCast(compact->GetBoundaryArray())->GetPointer(0);
  TRC_CHECK(Equal(cb, { 0, 3, 2, 1 }));
  TRC_CHECK(Equal(cb + 4, { 0, 1, 3, 2 }));
  TRC_CHECK(Equal(cb + 8, { 0, 2, 1, 3 }));
  TRC_CHECK(Equal(cb + 12, { 4, 2, 3, 5 }));
  TRC_CHECK(Equal(cb + 16, { 4, 1, 2, 6 }));
  TRC_CHECK(Equal(cb + 20, { 4, 3, 1, 7 }));
  // 2 x 16 + 2 x 16 + 5 x 16 bytes for the mesh; 6 x 16 for the boundary.
  TRC_CHECK(compact->GetNumberOfBytes() == 144);
  TRC_CHECK(compact->GetBytesPerTet() == 72.0);
  TRC_CHECK(compact->GetNumberOfBytesWithBoundary() == 240);
  TRC_CHECK_EMPTY(trc::CheckCompactLayout(mesh, compact));
  TRC_CHECK_EMPTY(trc::CheckPaperLayout(mesh, paper));
  return EXIT_SUCCESS;
}

int TestRealMesh(int argc, char* argv[])
{
  char* fileName = vtkTestUtilities::ExpandDataFileName(argc, argv, "Meshes/spx_vistrails.vtu");
  vtkNew<vtkXMLUnstructuredGridReader> reader;
  reader->SetFileName(fileName);
  delete[] fileName;
  reader->Update();
  vtkNew<vtkTetMeshBuilder> builder;
  vtkTetMesh* mesh = builder->Build(reader->GetOutput());
  const vtkIdType numTets = mesh->GetNumberOfTetrahedra();
  TRC_CHECK(numTets == 12936);

  // A width that divides the count: exactly 144 bytes per tetrahedron, texel count x 16 / tets.
  vtkNew<vtkTetMeshPaperLayout> paper;
  paper->SetTextureWidth(1078); // 12936 = 12 x 1078
  TRC_CHECK(paper->Build(mesh));
  vtkIdType texels = 0;
  for (int a = 0; a < paper->GetNumberOfArrays(); ++a)
  {
    texels += paper->GetArray(a)->GetNumberOfTuples();
  }
  TRC_CHECK(texels * 16 == 144 * numTets);
  TRC_CHECK(paper->GetBytesPerTet() == 144.0);
  TRC_CHECK_EMPTY(trc::CheckPaperLayout(mesh, paper));
  // Another width pads the last row group: fewer than W tetrahedra of padding.
  paper->SetTextureWidth(1000);
  TRC_CHECK(paper->Update(mesh));
  TRC_CHECK(paper->GetLastUpdate() == vtkTetMeshLayout::UpdatedAll);
  TRC_CHECK(paper->GetNumberOfBytes() == 144 * 13000);
  TRC_CHECK_EMPTY(trc::CheckPaperLayout(mesh, paper));

  // Texture limits: a clear error and an invalid layout, never garbage.
  vtkNew<trctest::MessageCounter> errors;
  paper->AddObserver(vtkCommand::ErrorEvent, errors);
  paper->SetTextureWidth(4096);
  paper->SetMaximumTextureSize(8); // 12 rows are needed
  TRC_CHECK(!paper->Build(mesh));
  TRC_CHECK(!paper->GetValid());
  TRC_CHECK(errors->Count == 1);
  TRC_CHECK(
    std::string(paper->GetErrorMessage()).find("maximum texture size 8") != std::string::npos);
  // Update() does not repeat the same failure (nor its error) while nothing changed.
  TRC_CHECK(!paper->Update(mesh));
  TRC_CHECK(errors->Count == 1);
  paper->SetMaximumTextureSize(16384);
  TRC_CHECK(paper->Update(mesh));
  TRC_CHECK(paper->GetValid());

  vtkNew<vtkTetMeshCompactLayout> compact;
  compact->AddObserver(vtkCommand::ErrorEvent, errors);
  // Larger than one texture buffer: split over buffers of a power of two texels (8192 of the
  // 10000 allowed), two per tetrahedron array here (12936 tetrahedra, 2896 points), up to
  // MaximumTextureBuffersPerArray.
  compact->SetMaximumTextureBufferSize(10000);
  TRC_CHECK(compact->Build(mesh));
  TRC_CHECK(compact->GetTextureBufferShift() == 13 && compact->GetTextureBufferSize() == 8192);
  TRC_CHECK(compact->GetNumberOfTextureBuffers(vtkTetMeshCompactLayout::TetPointsArray) == 2);
  TRC_CHECK(compact->GetNumberOfTextureBuffers(vtkTetMeshCompactLayout::TetNeighborsArray) == 2);
  TRC_CHECK(compact->GetNumberOfTextureBuffers(vtkTetMeshCompactLayout::PointsArray) == 1);
  TRC_CHECK(compact->GetNumberOfTextureBuffers(99) == 0);
  TRC_CHECK_EMPTY(trc::CheckCompactLayout(mesh, compact));
  compact->SetMaximumTextureBuffersPerArray(1);
  TRC_CHECK(!compact->Update(mesh));
  TRC_CHECK(errors->Count == 2);
  TRC_CHECK(std::string(compact->GetErrorMessage())
              .find("needs 2 texture buffers of 8192 texels for an array of 12936 texels, more "
                    "than the 1 allowed per array (maximum texture buffer size 10000 texels)") !=
    std::string::npos);
  compact->SetMaximumTextureBuffersPerArray(8);
  compact->SetMaximumTextureBufferSize(1 << 27);
  TRC_CHECK(compact->Build(mesh));
  TRC_CHECK_EMPTY(trc::CheckCompactLayout(mesh, compact));
  // Bytes per tetrahedron: 32 + 16 points / tets.
  const double expected = 32.0 + 16.0 * mesh->GetNumberOfPoints() / numTets;
  TRC_CHECK(std::abs(compact->GetBytesPerTet() - expected) < 1e-12);
  return EXIT_SUCCESS;
}
}

int TestTetMeshLayouts(int argc, char* argv[])
{
  if (TestHandComputed() != EXIT_SUCCESS)
  {
    return EXIT_FAILURE;
  }
  return TestRealMesh(argc, argv);
}
