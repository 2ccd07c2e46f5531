/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkTetGenMesher.cxx

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "vtkTetGenMesher.h"
#include "vtkTetGenMesherOutput.h"
#include "vtkTetGenMesherSurface.h"

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

  // The surface TetGen is given: the points used by some facet, in input order, and the facets
  // over them. Returns an error message, or nothing.
  std::string Load(vtkPolyData* surface)
  {
    vtkCellArray* facets = surface->GetPolys();
    const vtkIdType numberOfInputPoints = surface->GetNumberOfPoints();
    std::vector<vtkIdType> tetgenId(numberOfInputPoints, -1);
    this->FacetOffsets.assign(1, 0);
    this->FacetOffsets.reserve(facets->GetNumberOfCells() + 1);
    this->FacetPoints.clear();
    this->UsedPointIds.clear();
    auto iter = vtk::TakeSmartPointer(facets->NewIterator());
    vtkIdType npts;
    const vtkIdType* pts;
    for (iter->GoToFirstCell(); !iter->IsDoneWithTraversal(); iter->GoToNextCell())
    {
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
        tetgenId[i] = static_cast<vtkIdType>(this->UsedPointIds.size());
        this->UsedPointIds.push_back(i);
      }
    }
    if (this->UsedPointIds.size() > static_cast<size_t>(std::numeric_limits<int>::max() / 4) ||
      facets->GetNumberOfConnectivityIds() > std::numeric_limits<int>::max())
    {
      return "The surface is too large for TetGen, which counts with 32-bit integers.";
    }
    for (iter->GoToFirstCell(); !iter->IsDoneWithTraversal(); iter->GoToNextCell())
    {
      iter->GetCurrentCell(npts, pts);
      for (vtkIdType i = 0; i < npts; ++i)
      {
        this->FacetPoints.push_back(static_cast<int>(tetgenId[pts[i]]));
      }
      this->FacetOffsets.push_back(static_cast<int>(this->FacetPoints.size()));
    }
    this->Coordinates.resize(3 * this->UsedPointIds.size());
    vtkPoints* points = surface->GetPoints();
    for (size_t i = 0; i < this->UsedPointIds.size(); ++i)
    {
      points->GetPoint(this->UsedPointIds[i], &this->Coordinates[3 * i]);
    }
    return std::string();
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

  // 1. The surface (vtkTetGenMesherSurface).
  std::string error = this->CheckInput(input);
  if (!error.empty())
  {
    return fail(error);
  }
  vtkSmartPointer<vtkPolyData> surface =
    vtkTetGenMesherSurface::MakeFacets(input, this->PolygonsAsFacets);
  this->UpdateProgress(0.05);

  // 2. Checks that TetGen would answer badly or not at all.
  if (surface->GetPolys()->GetNumberOfCells() == 0)
  {
    return fail("Empty input: triangulating the polygons gave no triangles.");
  }
  error = vtkTetGenMesherSurface::FindZeroAreaFacets(surface, this->PolygonsAsFacets);
  if (error.empty())
  {
    error = vtkTetGenMesherSurface::FindOpenEdges(surface);
  }
  // 3. TetGen's input: the points used by some facet, in input order, and the facets.
  if (!error.empty() || !(error = internals.Load(surface)).empty())
  {
    return fail(error);
  }
  this->UpdateProgress(0.1);
  if (this->CheckSelfIntersections && !(error = this->FindSelfIntersections()).empty())
  {
    return fail(error);
  }
  if (this->GetAbortExecute())
  {
    return 1;
  }

  // 4. Meshing.
  const std::string switches = this->MakeSwitches();
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

  // 5. The output grid (vtkTetGenMesherOutput).
  if (!vtkTetGenMesherOutput::Fill(
        this, input, out, internals.UsedPointIds, internals.Coordinates, output, error))
  {
    return fail(error);
  }
  this->UpdateProgress(0.95);
  vtkDebugMacro(<< "TetGen -" << switches << ": " << output->GetNumberOfPoints() << " points ("
                << output->GetNumberOfPoints() - static_cast<vtkIdType>(internals.UsedPointIds.size())
                << " added), " << output->GetNumberOfCells() << " tetrahedra.");
  this->UpdateProgress(1.0);
  return 1;
}

//------------------------------------------------------------------------------
std::string vtkTetGenMesher::CheckInput(vtkPolyData* input)
{
  if (!input || input->GetNumberOfPoints() == 0 || !input->GetPoints())
  {
    return "Empty input: the surface has no points.";
  }
  if (input->GetNumberOfPolys() + input->GetNumberOfStrips() == 0)
  {
    return "Empty input: the surface has no polygons or triangle strips, so it encloses no "
           "volume.";
  }
  if (input->GetNumberOfVerts() + input->GetNumberOfLines() > 0)
  {
    vtkWarningMacro(<< "Ignoring " << input->GetNumberOfVerts() << " vertices and "
                    << input->GetNumberOfLines() << " lines of the input: only polygons and "
                    << "triangle strips bound the volume.");
  }
  // A polygon with fewer than three distinct points would vanish in vtkTriangleFilter and
  // leave a hole: call it degenerate here, where its id is still the user's.
  return vtkTetGenMesherSurface::FindDegeneratePolygons(input);
}

//------------------------------------------------------------------------------
std::string vtkTetGenMesher::FindSelfIntersections()
{
  // TetGen -d meshes nothing: it keeps the facets that intersect another one as its output
  // triangles.
  tetgenio in, out;
  this->Internals->Pack(in);
  const int code = vtkInternals::Run(this->Quiet ? "pdzQ" : "pdz", in, out);
  std::ostringstream message;
  if (code != 0)
  {
    this->LastTetGenError = code;
    message << "Checking the surface for self-intersections: " << TetGenErrorText(code)
            << " (TetGen error " << code << ").";
  }
  else if (out.numberoftrifaces > 0)
  {
    this->NumberOfIntersectingFaces = out.numberoftrifaces;
    message << "The surface intersects itself: " << out.numberoftrifaces
            << " of its triangles cross another one (TetGen -d). A self-intersecting surface "
               "does not bound a volume.";
  }
  return message.str();
}

//------------------------------------------------------------------------------
std::string vtkTetGenMesher::MakeSwitches()
{
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
  const std::vector<std::array<double, 5>>& regions = this->Internals->Regions;
  if (std::any_of(regions.begin(), regions.end(),
        [](const std::array<double, 5>& region) { return region[4] > 0.0; }))
  {
    switches += "a"; // regional volume constraints
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
  return switches;
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
