/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkTetGenMesher.cxx

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "vtkTetGenMesher.h"

#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkCellData.h"
#include "vtkCellType.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkErrorCode.h"
#include "vtkFeatureEdges.h"
#include "vtkFloatArray.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolygon.h"
#include "vtkSMPThreadLocal.h"
#include "vtkSMPTools.h"
#include "vtkSmartPointer.h"
#include "vtkTriangleFilter.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <iomanip>
#include <limits>
#include <locale>
#include <new>
#include <sstream>
#include <vector>

// The Debian library is built with TETLIBRARY, which declares tetrahedralize(char*, ...) and
// makes terminatetetgen() throw its error code. terminatetetgen() is an inline function that
// the library calls through the PLT, so a copy compiled here without TETLIBRARY (one that calls
// exit()) could take its place at run time: define it in every case. TetGen's header defines
// REAL and a few other macros, so it comes after every VTK header.
#ifndef TETLIBRARY
#define TETLIBRARY
#endif
#include <tetgen.h>

namespace
{
// A facet whose area is below this fraction of its longest edge squared is degenerate.
constexpr double DegenerateAreaRatio = 1e-12;

// The shortest decimal text, in the C locale, that reads back as exactly `value`. TetGen's
// parser reads the numbers after -q (and after its '/') as digits and dots only, so `fixed`
// must be used there; the number after -a may carry an exponent.
std::string FormatExactly(double value, bool fixed)
{
  std::string text;
  for (int precision = fixed ? 0 : 1; precision <= 40; ++precision)
  {
    std::ostringstream out;
    out.imbue(std::locale::classic());
    if (fixed)
    {
      out << std::fixed;
    }
    out << std::setprecision(precision) << value;
    text = out.str();
    std::istringstream in(text);
    in.imbue(std::locale::classic());
    double back = 0.0;
    in >> back;
    if (back == value)
    {
      break;
    }
  }
  return text;
}

const char* TetGenErrorText(int code)
{
  switch (code)
  {
    case 1:
      return "TetGen ran out of memory";
    case 2:
      return "TetGen hit an internal error";
    case 3:
      return "TetGen found a self-intersection in the surface";
    case 4:
      return "TetGen found an input feature smaller than its tolerance (nearly coincident points "
             "or nearly degenerate facets)";
    case 5:
      return "TetGen found two facets that are too close to each other";
    case 10:
      return "TetGen rejected its input (invalid switches or surface)";
    default:
      return "TetGen failed";
  }
}

// Copies TetGen's double coordinates into a float or double array.
template <typename ValueT>
void CopyCoordinates(const double* source, vtkIdType numberOfPoints, ValueT* target)
{
  vtkSMPTools::For(0, numberOfPoints,
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType i = 3 * begin; i < 3 * end; ++i)
      {
        target[i] = static_cast<ValueT>(source[i]);
      }
    });
}
} // anonymous namespace

//------------------------------------------------------------------------------
class vtkTetGenMesher::vtkInternals
{
public:
  std::vector<std::array<double, 3>> Holes;
  std::vector<std::array<double, 5>> Regions; // x, y, z, attribute, maximum volume

  // The surface handed to TetGen: the points used by some facet (in input order) and the
  // facets as polygons over those points.
  std::vector<vtkIdType> UsedPointIds; // TetGen point -> input point
  std::vector<double> Coordinates;     // 3 per TetGen point
  std::vector<int> FacetOffsets;       // FacetOffsets[f]..FacetOffsets[f+1] in FacetPoints
  std::vector<int> FacetPoints;

  // Fills a tetgenio with the surface, holes and regions. tetgenio frees what it holds with
  // delete[], so everything is allocated with new[].
  void Pack(tetgenio& in) const
  {
    in.firstnumber = 0;
    in.numberofpoints = static_cast<int>(this->UsedPointIds.size());
    in.pointlist = new REAL[this->Coordinates.size()];
    std::copy(this->Coordinates.begin(), this->Coordinates.end(), in.pointlist);

    const int numberOfFacets = static_cast<int>(this->FacetOffsets.size()) - 1;
    in.numberoffacets = numberOfFacets;
    in.facetlist = new tetgenio::facet[numberOfFacets];
    for (int f = 0; f < numberOfFacets; ++f)
    {
      tetgenio::facet& facet = in.facetlist[f];
      tetgenio::init(&facet);
      facet.numberofpolygons = 1;
      facet.polygonlist = new tetgenio::polygon[1];
      tetgenio::polygon& polygon = facet.polygonlist[0];
      tetgenio::init(&polygon);
      const int begin = this->FacetOffsets[f];
      const int size = this->FacetOffsets[f + 1] - begin;
      polygon.numberofvertices = size;
      polygon.vertexlist = new int[size];
      std::copy_n(this->FacetPoints.begin() + begin, size, polygon.vertexlist);
    }

    if (!this->Holes.empty())
    {
      in.numberofholes = static_cast<int>(this->Holes.size());
      in.holelist = new REAL[3 * this->Holes.size()];
      for (size_t i = 0; i < this->Holes.size(); ++i)
      {
        std::copy_n(this->Holes[i].begin(), 3, in.holelist + 3 * i);
      }
    }
    if (!this->Regions.empty())
    {
      in.numberofregions = static_cast<int>(this->Regions.size());
      in.regionlist = new REAL[5 * this->Regions.size()];
      for (size_t i = 0; i < this->Regions.size(); ++i)
      {
        std::copy_n(this->Regions[i].begin(), 5, in.regionlist + 5 * i);
        // TetGen reads a non-positive regional volume as "no constraint".
        if (!(in.regionlist[5 * i + 4] > 0.0))
        {
          in.regionlist[5 * i + 4] = -1.0;
        }
      }
    }
  }

  // Runs TetGen; returns 0 or TetGen's error code (-1 when it threw something else, -2 when
  // memory ran out outside TetGen's own checks).
  static int Run(const std::string& switches, tetgenio& in, tetgenio& out)
  {
    std::vector<char> text(switches.begin(), switches.end());
    text.push_back('\0');
    try
    {
      tetrahedralize(text.data(), &in, &out);
    }
    catch (int code)
    {
      return code == 0 ? -1 : code;
    }
    catch (const std::bad_alloc&)
    {
      return 1;
    }
    catch (...)
    {
      return -1;
    }
    return 0;
  }
};

vtkStandardNewMacro(vtkTetGenMesher);

//------------------------------------------------------------------------------
vtkTetGenMesher::vtkTetGenMesher()
  : Internals(new vtkInternals)
{
}

//------------------------------------------------------------------------------
vtkTetGenMesher::~vtkTetGenMesher()
{
  delete this->Internals;
}

//------------------------------------------------------------------------------
void vtkTetGenMesher::AddHole(double x, double y, double z)
{
  this->Internals->Holes.push_back({ x, y, z });
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkTetGenMesher::RemoveAllHoles()
{
  if (!this->Internals->Holes.empty())
  {
    this->Internals->Holes.clear();
    this->Modified();
  }
}

//------------------------------------------------------------------------------
int vtkTetGenMesher::GetNumberOfHoles() const
{
  return static_cast<int>(this->Internals->Holes.size());
}

//------------------------------------------------------------------------------
void vtkTetGenMesher::AddRegion(
  double x, double y, double z, double attribute, double maximumVolume)
{
  this->Internals->Regions.push_back({ x, y, z, attribute, maximumVolume });
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkTetGenMesher::RemoveAllRegions()
{
  if (!this->Internals->Regions.empty())
  {
    this->Internals->Regions.clear();
    this->Modified();
  }
}

//------------------------------------------------------------------------------
int vtkTetGenMesher::GetNumberOfRegions() const
{
  return static_cast<int>(this->Internals->Regions.size());
}

//------------------------------------------------------------------------------
int vtkTetGenMesher::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  return 1;
}

//------------------------------------------------------------------------------
int vtkTetGenMesher::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0], 0);
  vtkUnstructuredGrid* output = vtkUnstructuredGrid::GetData(outputVector, 0);
  vtkInternals& internals = *this->Internals;

  this->TetGenSwitches.clear();
  this->LastTetGenError = 0;
  this->NumberOfIntersectingFaces = 0;
  this->SetErrorCode(vtkErrorCode::NoError);
  output->Initialize();
  this->UpdateProgress(0.0);

  // Every failure leaves an empty output, says why and returns success to the executive, so
  // that a pipeline downstream sees an empty grid rather than a second, vaguer error.
  auto fail = [&](const std::string& message)
  {
    vtkErrorMacro(<< message);
    output->Initialize();
    this->SetErrorCode(vtkErrorCode::UserError);
    return 1;
  };

  // 1. The surface.
  if (!input || input->GetNumberOfPoints() == 0 || !input->GetPoints())
  {
    return fail("Empty input: the surface has no points.");
  }
  const vtkIdType numberOfPolys = input->GetNumberOfPolys();
  const vtkIdType numberOfStrips = input->GetNumberOfStrips();
  if (numberOfPolys + numberOfStrips == 0)
  {
    return fail("Empty input: the surface has no polygons or triangle strips, so it encloses "
                "no volume.");
  }
  if (input->GetNumberOfVerts() + input->GetNumberOfLines() > 0)
  {
    vtkWarningMacro(<< "Ignoring " << input->GetNumberOfVerts() << " vertices and "
                    << input->GetNumberOfLines() << " lines of the input: only polygons and "
                    << "triangle strips bound the volume.");
  }

  // A polygon with fewer than three distinct points would vanish in vtkTriangleFilter and
  // leave a hole: call it degenerate here, where its id is still the user's.
  {
    vtkIdType degenerate = 0;
    vtkIdType firstDegenerate = -1;
    auto iter = vtk::TakeSmartPointer(input->GetPolys()->NewIterator());
    std::vector<vtkIdType> ids;
    for (iter->GoToFirstCell(); !iter->IsDoneWithTraversal(); iter->GoToNextCell())
    {
      vtkIdType npts;
      const vtkIdType* pts;
      iter->GetCurrentCell(npts, pts);
      ids.assign(pts, pts + npts);
      std::sort(ids.begin(), ids.end());
      if (std::unique(ids.begin(), ids.end()) - ids.begin() < 3)
      {
        if (degenerate++ == 0)
        {
          firstDegenerate =
            input->GetNumberOfVerts() + input->GetNumberOfLines() + iter->GetCurrentCellId();
        }
      }
    }
    if (degenerate > 0)
    {
      std::ostringstream message;
      message << "Degenerate input: " << degenerate
              << " polygons have fewer than three distinct points (the first is cell "
              << firstDegenerate << ").";
      return fail(message.str());
    }
  }

  vtkSmartPointer<vtkPolyData> surface;
  {
    vtkNew<vtkPolyData> faces;
    faces->SetPoints(input->GetPoints());
    faces->SetStrips(input->GetStrips());
    if (!this->PolygonsAsFacets)
    {
      faces->SetPolys(input->GetPolys());
    }
    if (this->PolygonsAsFacets && numberOfStrips == 0)
    {
      surface = vtkSmartPointer<vtkPolyData>::New();
      surface->SetPoints(input->GetPoints());
      surface->SetPolys(input->GetPolys());
    }
    else
    {
      vtkNew<vtkTriangleFilter> triangles;
      triangles->PassVertsOff();
      triangles->PassLinesOff();
      triangles->SetInputData(faces);
      triangles->Update();
      surface = triangles->GetOutput();
      if (this->PolygonsAsFacets)
      {
        // The polygons as they are, then the triangles of the strips.
        vtkNew<vtkCellArray> polys;
        polys->DeepCopy(input->GetPolys());
        polys->Append(surface->GetPolys());
        surface = vtkSmartPointer<vtkPolyData>::New();
        surface->SetPoints(input->GetPoints());
        surface->SetPolys(polys);
      }
    }
  }
  this->UpdateProgress(0.05);

  // 2. Checks that TetGen would answer badly or not at all.
  vtkCellArray* facets = surface->GetPolys();
  const vtkIdType numberOfFacets = facets->GetNumberOfCells();
  if (numberOfFacets == 0)
  {
    return fail("Empty input: triangulating the polygons gave no triangles.");
  }
  {
    // Zero-area facets (collinear points, or polygons folded onto a line).
    vtkPoints* points = surface->GetPoints();
    vtkSMPThreadLocal<std::vector<vtkIdType>> localDegenerate;
    vtkSMPTools::For(0, numberOfFacets,
      [&](vtkIdType begin, vtkIdType end)
      {
        auto iter = vtk::TakeSmartPointer(facets->NewIterator());
        std::vector<vtkIdType>& found = localDegenerate.Local();
        double normal[3];
        for (vtkIdType f = begin; f < end; ++f)
        {
          vtkIdType npts;
          const vtkIdType* pts;
          iter->GetCellAtId(f, npts, pts);
          double longest = 0.0;
          for (vtkIdType i = 0; i < npts; ++i)
          {
            double a[3], b[3];
            points->GetPoint(pts[i], a);
            points->GetPoint(pts[(i + 1) % npts], b);
            longest = std::max(longest, vtkMath::Distance2BetweenPoints(a, b));
          }
          const double area = vtkPolygon::ComputeArea(points, npts, pts, normal);
          if (!(area > DegenerateAreaRatio * longest))
          {
            found.push_back(f);
          }
        }
      });
    std::vector<vtkIdType> degenerate;
    for (const auto& found : localDegenerate)
    {
      degenerate.insert(degenerate.end(), found.begin(), found.end());
    }
    if (!degenerate.empty())
    {
      std::ostringstream message;
      message << "Degenerate input: " << degenerate.size()
              << " facets have no area (collinear points)"
              << (this->PolygonsAsFacets ? "" : " after triangulation") << "; the first is facet "
              << *std::min_element(degenerate.begin(), degenerate.end()) << ".";
      return fail(message.str());
    }
  }
  {
    // Every edge of a closed, manifold surface bounds exactly two facets.
    vtkNew<vtkFeatureEdges> edges;
    edges->SetInputData(surface);
    edges->FeatureEdgesOff();
    edges->ManifoldEdgesOff();
    edges->ColoringOff();
    edges->BoundaryEdgesOn();
    edges->NonManifoldEdgesOff();
    edges->Update();
    const vtkIdType boundaryEdges = edges->GetOutput()->GetNumberOfCells();
    edges->BoundaryEdgesOff();
    edges->NonManifoldEdgesOn();
    edges->Update();
    const vtkIdType nonManifoldEdges = edges->GetOutput()->GetNumberOfCells();
    if (boundaryEdges > 0 || nonManifoldEdges > 0)
    {
      std::ostringstream message;
      message << "The surface is not closed: " << boundaryEdges
              << " boundary edges (edges of a single facet) and " << nonManifoldEdges
              << " non-manifold edges (edges of three or more facets). Only a closed, manifold "
                 "surface encloses a volume (coincident but distinct points also leave edges "
                 "open: vtkCleanPolyData merges them).";
      return fail(message.str());
    }
  }

  // 3. TetGen's input: the points used by some facet, in input order, and the facets.
  {
    const vtkIdType numberOfInputPoints = surface->GetNumberOfPoints();
    std::vector<vtkIdType> tetgenId(numberOfInputPoints, -1);
    internals.FacetOffsets.assign(1, 0);
    internals.FacetOffsets.reserve(numberOfFacets + 1);
    internals.FacetPoints.clear();
    internals.UsedPointIds.clear();
    auto iter = vtk::TakeSmartPointer(facets->NewIterator());
    for (iter->GoToFirstCell(); !iter->IsDoneWithTraversal(); iter->GoToNextCell())
    {
      vtkIdType npts;
      const vtkIdType* pts;
      iter->GetCurrentCell(npts, pts);
      for (vtkIdType i = 0; i < npts; ++i)
      {
        tetgenId[pts[i]] = 0;
      }
    }
    for (vtkIdType i = 0; i < numberOfInputPoints; ++i)
    {
      if (tetgenId[i] == 0)
      {
        tetgenId[i] = static_cast<vtkIdType>(internals.UsedPointIds.size());
        internals.UsedPointIds.push_back(i);
      }
    }
    if (internals.UsedPointIds.size() > static_cast<size_t>(std::numeric_limits<int>::max() / 4) ||
      facets->GetNumberOfConnectivityIds() > std::numeric_limits<int>::max())
    {
      return fail("The surface is too large for TetGen, which counts with 32-bit integers.");
    }
    for (iter->GoToFirstCell(); !iter->IsDoneWithTraversal(); iter->GoToNextCell())
    {
      vtkIdType npts;
      const vtkIdType* pts;
      iter->GetCurrentCell(npts, pts);
      for (vtkIdType i = 0; i < npts; ++i)
      {
        internals.FacetPoints.push_back(static_cast<int>(tetgenId[pts[i]]));
      }
      internals.FacetOffsets.push_back(static_cast<int>(internals.FacetPoints.size()));
    }
    internals.Coordinates.resize(3 * internals.UsedPointIds.size());
    vtkPoints* points = surface->GetPoints();
    for (size_t i = 0; i < internals.UsedPointIds.size(); ++i)
    {
      points->GetPoint(internals.UsedPointIds[i], &internals.Coordinates[3 * i]);
    }
  }
  this->UpdateProgress(0.1);

  if (this->CheckSelfIntersections)
  {
    // TetGen -d meshes nothing: it keeps the facets that intersect another one as its output
    // triangles.
    tetgenio in, out;
    internals.Pack(in);
    const int code = vtkInternals::Run(this->Quiet ? "pdzQ" : "pdz", in, out);
    if (code != 0)
    {
      this->LastTetGenError = code;
      std::ostringstream message;
      message << "Checking the surface for self-intersections: " << TetGenErrorText(code)
              << " (TetGen error " << code << ").";
      return fail(message.str());
    }
    if (out.numberoftrifaces > 0)
    {
      this->NumberOfIntersectingFaces = out.numberoftrifaces;
      std::ostringstream message;
      message << "The surface intersects itself: " << out.numberoftrifaces
              << " of its triangles cross another one (TetGen -d). A self-intersecting surface "
                 "does not bound a volume.";
      return fail(message.str());
    }
  }
  if (this->GetAbortExecute())
  {
    return 1;
  }

  // 4. Meshing.
  std::string switches = "p";
  if (this->Quality)
  {
    switches += "q" + FormatExactly(this->RadiusEdgeRatio, true);
    if (this->MinDihedralAngle > 0.0)
    {
      switches += "/" + FormatExactly(this->MinDihedralAngle, true);
    }
  }
  if (this->MaximumVolume > 0.0)
  {
    switches += "a" + FormatExactly(this->MaximumVolume, false);
  }
  const bool regionalVolumes = std::any_of(internals.Regions.begin(), internals.Regions.end(),
    [](const std::array<double, 5>& region) { return region[4] > 0.0; });
  if (regionalVolumes)
  {
    switches += "a";
  }
  if (this->RegionAttributes)
  {
    switches += "A";
  }
  if (this->PreserveSurface)
  {
    switches += "Y";
  }
  if (!this->MergeCoplanarFacets)
  {
    switches += "M";
  }
  // z: number from zero; J: keep every input point, so that they stay first and in order.
  switches += "zJ";
  if (this->Quiet)
  {
    switches += "Q";
  }
  this->TetGenSwitches = switches;

  tetgenio in, out;
  internals.Pack(in);
  this->UpdateProgress(0.15);
  const int code = vtkInternals::Run(switches, in, out);
  if (code != 0)
  {
    this->LastTetGenError = code;
    std::ostringstream message;
    message << TetGenErrorText(code) << " (TetGen error " << code << ", switches -" << switches
            << ").";
    return fail(message.str());
  }
  this->UpdateProgress(0.85);

  // 5. The output grid.
  const vtkIdType numberOfSurfacePoints = static_cast<vtkIdType>(internals.UsedPointIds.size());
  const vtkIdType numberOfPoints = out.numberofpoints;
  const vtkIdType numberOfTets = out.numberoftetrahedra;
  if (numberOfTets <= 0 || out.numberofcorners != 4 || !out.tetrahedronlist)
  {
    return fail("TetGen produced no tetrahedra: the holes remove every region, or the surface "
                "encloses no volume.");
  }
  if (numberOfPoints < numberOfSurfacePoints ||
    !std::equal(internals.Coordinates.begin(), internals.Coordinates.end(), out.pointlist))
  {
    return fail("TetGen renumbered the surface points; the output cannot be matched to the "
                "input.");
  }
  const int firstNumber = out.firstnumber;

  vtkNew<vtkPoints> points;
  int pointType = input->GetPoints()->GetDataType();
  if (this->OutputPointsPrecision == vtkAlgorithm::SINGLE_PRECISION)
  {
    pointType = VTK_FLOAT;
  }
  else if (this->OutputPointsPrecision == vtkAlgorithm::DOUBLE_PRECISION ||
    (pointType != VTK_FLOAT && pointType != VTK_DOUBLE))
  {
    pointType = VTK_DOUBLE;
  }
  points->SetDataType(pointType);
  points->SetNumberOfPoints(numberOfPoints);
  if (pointType == VTK_FLOAT)
  {
    CopyCoordinates(
      out.pointlist, numberOfPoints, vtkFloatArray::SafeDownCast(points->GetData())->GetPointer(0));
  }
  else
  {
    CopyCoordinates(out.pointlist, numberOfPoints,
      vtkDoubleArray::SafeDownCast(points->GetData())->GetPointer(0));
  }

  // Connectivity. TetGen 1.5 already lists its tetrahedra with det[p1-p0, p2-p0, p3-p0] > 0 (the
  // torus of the tests has no exception), but docs/design.md makes positive orientation a
  // promise of every mesh, so it is checked per tetrahedron rather than assumed of TetGen.
  vtkNew<vtkIdTypeArray> offsets;
  offsets->SetNumberOfValues(numberOfTets + 1);
  vtkNew<vtkIdTypeArray> connectivity;
  connectivity->SetNumberOfValues(4 * numberOfTets);
  {
    const int* tets = out.tetrahedronlist;
    const double* xyz = out.pointlist;
    vtkIdType* conn = connectivity->GetPointer(0);
    vtkIdType* offs = offsets->GetPointer(0);
    vtkSMPTools::For(0, numberOfTets,
      [&](vtkIdType begin, vtkIdType end)
      {
        for (vtkIdType t = begin; t < end; ++t)
        {
          vtkIdType ids[4];
          for (int k = 0; k < 4; ++k)
          {
            ids[k] = tets[4 * t + k] - firstNumber;
          }
          const double* p0 = xyz + 3 * ids[0];
          double e[3][3];
          for (int k = 0; k < 3; ++k)
          {
            const double* p = xyz + 3 * ids[k + 1];
            e[k][0] = p[0] - p0[0];
            e[k][1] = p[1] - p0[1];
            e[k][2] = p[2] - p0[2];
          }
          if (vtkMath::Determinant3x3(e[0], e[1], e[2]) < 0.0)
          {
            std::swap(ids[2], ids[3]);
          }
          std::copy_n(ids, 4, conn + 4 * t);
          offs[t] = 4 * t;
        }
      });
    offs[numberOfTets] = 4 * numberOfTets;
  }
  vtkNew<vtkCellArray> cells;
  cells->SetData(offsets, connectivity);
  output->SetPoints(points);
  output->SetCells(VTK_TETRA, cells);

  if (this->RegionAttributes && out.numberoftetrahedronattributes > 0 &&
    out.tetrahedronattributelist)
  {
    vtkNew<vtkDoubleArray> attribute;
    attribute->SetName("RegionAttribute");
    attribute->SetNumberOfValues(numberOfTets);
    const int stride = out.numberoftetrahedronattributes;
    for (vtkIdType t = 0; t < numberOfTets; ++t)
    {
      attribute->SetValue(t, out.tetrahedronattributelist[stride * t]);
    }
    output->GetCellData()->AddArray(attribute);
  }

  if (this->PassPointData)
  {
    vtkPointData* inPD = input->GetPointData();
    vtkPointData* outPD = output->GetPointData();
    for (int a = 0; a < inPD->GetNumberOfArrays(); ++a)
    {
      vtkDataArray* source = inPD->GetArray(a);
      if (!source)
      {
        continue; // only numeric arrays can say "no value" (NaN or 0)
      }
      auto target = vtk::TakeSmartPointer(source->NewInstance());
      target->SetName(source->GetName());
      target->SetNumberOfComponents(source->GetNumberOfComponents());
      target->SetNumberOfTuples(numberOfPoints);
      const bool real = target->GetDataType() == VTK_FLOAT || target->GetDataType() == VTK_DOUBLE;
      for (int c = 0; c < target->GetNumberOfComponents(); ++c)
      {
        target->FillComponent(c, real ? std::numeric_limits<double>::quiet_NaN() : 0.0);
      }
      for (vtkIdType i = 0; i < numberOfSurfacePoints; ++i)
      {
        target->SetTuple(i, internals.UsedPointIds[i], source);
      }
      const int index = outPD->AddArray(target);
      for (int attributeType = 0; attributeType < vtkDataSetAttributes::NUM_ATTRIBUTES;
           ++attributeType)
      {
        if (inPD->GetAttribute(attributeType) == source)
        {
          outPD->SetActiveAttribute(index, attributeType);
        }
      }
    }
  }
  if (this->GenerateOriginalPointIds)
  {
    vtkNew<vtkIdTypeArray> originalIds;
    originalIds->SetName("vtkOriginalPointIds");
    originalIds->SetNumberOfValues(numberOfPoints);
    originalIds->Fill(-1);
    for (vtkIdType i = 0; i < numberOfSurfacePoints; ++i)
    {
      originalIds->SetValue(i, internals.UsedPointIds[i]);
    }
    output->GetPointData()->AddArray(originalIds);
  }
  this->UpdateProgress(0.95);

  vtkDebugMacro(<< "TetGen -" << switches << ": " << numberOfPoints << " points ("
                << numberOfPoints - numberOfSurfacePoints << " added), " << numberOfTets
                << " tetrahedra.");
  this->UpdateProgress(1.0);
  return 1;
}

//------------------------------------------------------------------------------
void vtkTetGenMesher::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Quality: " << (this->Quality ? "On" : "Off") << "\n";
  os << indent << "RadiusEdgeRatio: " << this->RadiusEdgeRatio << "\n";
  os << indent << "MinDihedralAngle: " << this->MinDihedralAngle << "\n";
  os << indent << "MaximumVolume: " << this->MaximumVolume << "\n";
  os << indent << "PreserveSurface: " << (this->PreserveSurface ? "On" : "Off") << "\n";
  os << indent << "MergeCoplanarFacets: " << (this->MergeCoplanarFacets ? "On" : "Off") << "\n";
  os << indent << "PolygonsAsFacets: " << (this->PolygonsAsFacets ? "On" : "Off") << "\n";
  os << indent << "CheckSelfIntersections: " << (this->CheckSelfIntersections ? "On" : "Off")
     << "\n";
  os << indent << "NumberOfHoles: " << this->GetNumberOfHoles() << "\n";
  os << indent << "NumberOfRegions: " << this->GetNumberOfRegions() << "\n";
  os << indent << "RegionAttributes: " << (this->RegionAttributes ? "On" : "Off") << "\n";
  os << indent << "PassPointData: " << (this->PassPointData ? "On" : "Off") << "\n";
  os << indent << "GenerateOriginalPointIds: " << (this->GenerateOriginalPointIds ? "On" : "Off")
     << "\n";
  os << indent << "Quiet: " << (this->Quiet ? "On" : "Off") << "\n";
  os << indent << "OutputPointsPrecision: " << this->OutputPointsPrecision << "\n";
  os << indent << "TetGenSwitches: " << this->TetGenSwitches << "\n";
  os << indent << "LastTetGenError: " << this->LastTetGenError << "\n";
  os << indent << "NumberOfIntersectingFaces: " << this->NumberOfIntersectingFaces << "\n";
}
