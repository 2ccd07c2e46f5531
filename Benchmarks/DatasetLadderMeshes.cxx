/*=========================================================================

  Program:   TiledRayCast
  Module:    DatasetLadderMeshes.cxx

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "DatasetLadderMeshes.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDataSetTriangleFilter.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkImageChangeInformation.h"
#include "vtkImageData.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkRTAnalyticSource.h"
#include "vtkSMPThreadLocal.h"
#include "vtkSMPTools.h"
#include "vtkStringArray.h"
#include "vtkUnsignedCharArray.h"

#ifdef TRC_HAVE_TETGEN
#include "vtkDataSetSurfaceFilter.h"
#include "vtkTetGenMesher.h"
#include "vtkThreshold.h"
#endif

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>
#include <utility>

namespace
{
// Swaps p2 and p3 of every tetrahedron with det[p1-p0, p2-p0, p3-p0] < 0 (docs/design.md asks
// for positive tetrahedra); returns how many were swapped and how many have zero volume.
template <typename ConnT>
void OrientPositively(
  vtkPoints* points, vtkCellArray* cells, ConnT* conn, vtkIdType& swapped, vtkIdType& degenerate)
{
  vtkSMPThreadLocal<vtkIdType> localSwapped, localDegenerate;
  const vtkIdType numberOfCells = cells->GetNumberOfCells();
  vtkSMPTools::For(0, numberOfCells,
    [&](vtkIdType begin, vtkIdType end)
    {
      vtkIdType& s = localSwapped.Local();
      vtkIdType& d = localDegenerate.Local();
      for (vtkIdType t = begin; t < end; ++t)
      {
        auto* ids = conn + 4 * t;
        double p[4][3];
        for (int k = 0; k < 4; ++k)
        {
          points->GetPoint(static_cast<vtkIdType>(ids[k]), p[k]);
        }
        double e[3][3];
        for (int k = 0; k < 3; ++k)
        {
          vtkMath::Subtract(p[k + 1], p[0], e[k]);
        }
        const double det = vtkMath::Determinant3x3(e[0], e[1], e[2]);
        if (det < 0.0)
        {
          std::swap(ids[2], ids[3]);
          ++s;
        }
        else if (det == 0.0)
        {
          ++d;
        }
      }
    });
  swapped = degenerate = 0;
  for (vtkIdType s : localSwapped)
  {
    swapped += s;
  }
  for (vtkIdType d : localDegenerate)
  {
    degenerate += d;
  }
}

#ifdef TRC_HAVE_TETGEN
// Reads the next line that is not empty or a comment, split into words.
bool NextRecord(std::istream& in, std::istringstream& record)
{
  std::string line;
  while (std::getline(in, line))
  {
    const auto hash = line.find('#');
    if (hash != std::string::npos)
    {
      line.erase(hash);
    }
    if (line.find_first_not_of(" \t\r") != std::string::npos)
    {
      record.clear();
      record.str(line);
      return true;
    }
  }
  return false;
}
#endif
} // anonymous namespace

namespace ladder
{
//------------------------------------------------------------------------------
bool OrientMesh(vtkUnstructuredGrid* mesh, vtkIdType& swapped, vtkIdType& degenerate)
{
  vtkCellArray* cells = mesh->GetCells();
  const vtkIdType n = cells->GetNumberOfCells();
  if (cells->GetNumberOfConnectivityIds() != 4 * n)
  {
    return false;
  }
  vtkUnsignedCharArray* types = mesh->GetCellTypesArray();
  for (vtkIdType c = 0; c < n; ++c)
  {
    if (types->GetValue(c) != VTK_TETRA)
    {
      return false;
    }
  }
  if (cells->IsStorage64Bit())
  {
    OrientPositively(mesh->GetPoints(), cells, cells->GetConnectivityArray64()->GetPointer(0),
      swapped, degenerate);
  }
  else
  {
    OrientPositively(mesh->GetPoints(), cells, cells->GetConnectivityArray32()->GetPointer(0),
      swapped, degenerate);
  }
  cells->Modified();
  return true;
}

void AddProvenance(vtkUnstructuredGrid* mesh, const std::string& text)
{
  vtkNew<vtkStringArray> provenance;
  provenance->SetName("Provenance");
  provenance->InsertNextValue(text);
  mesh->GetFieldData()->AddArray(provenance);
}

//------------------------------------------------------------------------------
vtkSmartPointer<vtkUnstructuredGrid> MakeWavelet(int n, std::string& provenance)
{
  // Extent lo..hi (n voxels) around the source's centre 0, then scaled to [-10,10]^3 so that
  // every rung fits the same camera. vtkRTAnalyticSource normalises its field by the whole
  // extent, so the field has the same shape at every size.
  const int lo = -(n / 2);
  const int hi = lo + n;
  vtkNew<vtkRTAnalyticSource> source;
  source->SetWholeExtent(lo, hi, lo, hi, lo, hi);
  vtkNew<vtkImageChangeInformation> scale;
  scale->SetInputConnection(source->GetOutputPort());
  const double spacing = 20.0 / n;
  scale->SetOutputSpacing(spacing, spacing, spacing);
  const double origin = -10.0 - lo * spacing;
  scale->SetOutputOrigin(origin, origin, origin);
  vtkNew<vtkDataSetTriangleFilter> tetrahedra;
  tetrahedra->SetInputConnection(scale->GetOutputPort());
  tetrahedra->TetrahedraOnlyOn();
  tetrahedra->Update();
  auto mesh = vtkSmartPointer<vtkUnstructuredGrid>::New();
  mesh->ShallowCopy(tetrahedra->GetOutput());
  std::ostringstream text;
  text << "vtkRTAnalyticSource extent [" << lo << "," << hi << "]^3 scaled to [-10,10]^3, "
       << "vtkDataSetTriangleFilter (5 tetrahedra per voxel); scalar RTData";
  provenance = text.str();
  return mesh;
}

#ifdef TRC_HAVE_TETGEN
//------------------------------------------------------------------------------
// A Geomview .off polyhedron, read as TetGen reads it (double precision, one facet per face).
bool ReadOFF(const std::string& fileName, Surface& surface)
{
  std::ifstream in(fileName);
  std::string header;
  vtkIdType numberOfPoints = 0, numberOfFaces = 0, numberOfEdges = 0;
  if (!(in >> header >> numberOfPoints >> numberOfFaces >> numberOfEdges) || header != "OFF")
  {
    return false;
  }
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(numberOfPoints);
  for (vtkIdType i = 0; i < numberOfPoints; ++i)
  {
    double x[3];
    in >> x[0] >> x[1] >> x[2];
    points->SetPoint(i, x);
  }
  vtkNew<vtkCellArray> polys;
  std::vector<vtkIdType> ids;
  for (vtkIdType f = 0; f < numberOfFaces && in; ++f)
  {
    vtkIdType n = 0;
    in >> n;
    ids.resize(n);
    for (auto& id : ids)
    {
      in >> id;
    }
    polys->InsertNextCell(n, ids.data());
  }
  if (!in)
  {
    return false;
  }
  surface.PolyData = vtkSmartPointer<vtkPolyData>::New();
  surface.PolyData->SetPoints(points);
  surface.PolyData->SetPolys(polys);
  return true;
}

// A TetGen .poly file whose facets are single polygons without facet holes (comb.poly and
// hollowcube.poly are): its points, facets, hole list and region list.
bool ReadPoly(const std::string& fileName, Surface& surface)
{
  std::ifstream in(fileName);
  std::istringstream record;
  vtkIdType numberOfPoints = 0;
  int dimension = 0, attributes = 0, markers = 0;
  if (!NextRecord(in, record) ||
    !(record >> numberOfPoints >> dimension >> attributes >> markers) || dimension != 3 ||
    numberOfPoints <= 0)
  {
    return false;
  }
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(numberOfPoints);
  vtkIdType firstNumber = 0;
  for (vtkIdType i = 0; i < numberOfPoints; ++i)
  {
    vtkIdType index;
    double x[3];
    if (!NextRecord(in, record) || !(record >> index >> x[0] >> x[1] >> x[2]))
    {
      return false;
    }
    if (i == 0)
    {
      firstNumber = index;
    }
    points->SetPoint(i, x);
  }
  vtkIdType numberOfFacets = 0;
  if (!NextRecord(in, record) || !(record >> numberOfFacets >> markers))
  {
    return false;
  }
  vtkNew<vtkCellArray> polys;
  std::vector<vtkIdType> ids;
  for (vtkIdType f = 0; f < numberOfFacets; ++f)
  {
    int polygons = 0, facetHoles = 0;
    if (!NextRecord(in, record) || !(record >> polygons))
    {
      return false;
    }
    record >> facetHoles;
    if (polygons != 1 || facetHoles != 0)
    {
      std::cerr << "error: " << fileName << ": facet " << f
                << " has several polygons or holes, which this reader does not support\n";
      return false;
    }
    vtkIdType n = 0;
    if (!NextRecord(in, record) || !(record >> n) || n < 3)
    {
      return false;
    }
    ids.resize(n);
    for (auto& id : ids)
    {
      record >> id;
      id -= firstNumber;
    }
    if (!record)
    {
      return false;
    }
    polys->InsertNextCell(n, ids.data());
  }
  vtkIdType holes = 0;
  if (NextRecord(in, record) && (record >> holes))
  {
    for (vtkIdType h = 0; h < holes; ++h)
    {
      vtkIdType index;
      std::array<double, 3> x;
      if (!NextRecord(in, record) || !(record >> index >> x[0] >> x[1] >> x[2]))
      {
        return false;
      }
      surface.Holes.push_back(x);
    }
    vtkIdType regions = 0;
    if (NextRecord(in, record) && (record >> regions))
    {
      for (vtkIdType r = 0; r < regions; ++r)
      {
        vtkIdType index;
        std::array<double, 5> region = { 0, 0, 0, 0, -1 };
        if (!NextRecord(in, record) || !(record >> index >> region[0] >> region[1] >> region[2]))
        {
          return false;
        }
        record >> region[3] >> region[4];
        surface.Regions.push_back(region);
      }
    }
  }
  surface.PolyData = vtkSmartPointer<vtkPolyData>::New();
  surface.PolyData->SetPoints(points);
  surface.PolyData->SetPolys(polys);
  // As `tetgen file.poly` does: every polygon is one facet, triangulated by TetGen.
  surface.PolygonsAsFacets = true;
  return true;
}

// The lattice: voxels of a (3n+1)^3 grid with unit spacing, a voxel being solid when at least
// two of its indices are multiples of 3 (bars of 1x1 section along the three axes, meeting at
// nodes every 3 units). Its boundary quads come from vtkThreshold + vtkDataSetSurfaceFilter.
Surface MakeLattice(int n)
{
  const int m = 3 * n + 1;
  vtkNew<vtkImageData> grid;
  grid->SetDimensions(m + 1, m + 1, m + 1);
  vtkNew<vtkUnsignedCharArray> solid;
  solid->SetName("Solid");
  solid->SetNumberOfValues(static_cast<vtkIdType>(m) * m * m);
  for (int k = 0; k < m; ++k)
  {
    for (int j = 0; j < m; ++j)
    {
      for (int i = 0; i < m; ++i)
      {
        const int onAxes = (i % 3 == 0) + (j % 3 == 0) + (k % 3 == 0);
        solid->SetValue(i + m * (j + m * static_cast<vtkIdType>(k)), onAxes >= 2 ? 1 : 0);
      }
    }
  }
  grid->GetCellData()->SetScalars(solid);
  vtkNew<vtkThreshold> threshold;
  threshold->SetInputData(grid);
  threshold->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_CELLS, "Solid");
  threshold->SetLowerThreshold(0.5);
  threshold->SetUpperThreshold(1.5);
  threshold->SetThresholdFunction(vtkThreshold::THRESHOLD_BETWEEN);
  vtkNew<vtkDataSetSurfaceFilter> boundary;
  boundary->SetInputConnection(threshold->GetOutputPort());
  boundary->Update();
  Surface surface;
  surface.PolyData = vtkSmartPointer<vtkPolyData>::New();
  surface.PolyData->SetPoints(boundary->GetOutput()->GetPoints());
  surface.PolyData->SetPolys(boundary->GetOutput()->GetPolys());
  surface.PolygonsAsFacets = true; // planar quads
  return surface;
}

vtkSmartPointer<vtkUnstructuredGrid> MakeTetGen(
  const Surface& surface, double maxVolume, std::string& switches)
{
  vtkNew<vtkTetGenMesher> mesher;
  mesher->SetInputData(surface.PolyData);
  mesher->QualityOn();
  mesher->SetRadiusEdgeRatio(1.414);
  mesher->SetMaximumVolume(maxVolume);
  mesher->SetPolygonsAsFacets(surface.PolygonsAsFacets);
  for (const auto& hole : surface.Holes)
  {
    mesher->AddHole(hole[0], hole[1], hole[2]);
  }
  for (const auto& region : surface.Regions)
  {
    mesher->AddRegion(region[0], region[1], region[2], region[3], region[4]);
  }
  mesher->SetOutputPointsPrecision(vtkAlgorithm::DOUBLE_PRECISION);
  mesher->Update();
  switches = mesher->GetTetGenSwitches();
  if (mesher->GetErrorCode() != 0 || mesher->GetOutput()->GetNumberOfCells() == 0)
  {
    return nullptr;
  }
  auto mesh = vtkSmartPointer<vtkUnstructuredGrid>::New();
  mesh->ShallowCopy(mesher->GetOutput());

  // "Synthetic" from the double coordinates, then the points stored as float (as the shipped
  // TetGen meshes are; TiledRayCast keeps float coordinates on the GPU anyway).
  vtkDataArray* xyz = mesh->GetPoints()->GetData();
  const vtkIdType n = mesh->GetNumberOfPoints();
  vtkNew<vtkFloatArray> synthetic;
  synthetic->SetName("Synthetic");
  synthetic->SetNumberOfValues(n);
  vtkNew<vtkFloatArray> single;
  single->SetNumberOfComponents(3);
  single->SetNumberOfTuples(n);
  vtkSMPTools::For(0, n,
    [&](vtkIdType begin, vtkIdType end)
    {
      double p[3];
      for (vtkIdType i = begin; i < end; ++i)
      {
        xyz->GetTuple(i, p);
        synthetic->SetValue(i,
          static_cast<float>(
            0.5 + 0.5 * std::sin(1.5 * p[0]) * std::cos(1.5 * p[1]) * std::cos(2.0 * p[2])));
        single->SetTypedTuple(i,
          std::array<float, 3>{
            static_cast<float>(p[0]), static_cast<float>(p[1]), static_cast<float>(p[2]) }
            .data());
      }
    });
  vtkNew<vtkPoints> points;
  points->SetData(single);
  mesh->SetPoints(points);
  mesh->GetPointData()->SetScalars(synthetic);
  return mesh;
}
#endif
} // namespace ladder
