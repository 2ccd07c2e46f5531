/*=========================================================================

  Program:   TiledRayCast
  Module:    MakeDatasetLadder.cxx

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// Writes the dataset ladder: tetrahedral meshes from about 100K to 30M tetrahedra, convex and
// strongly non-convex, as .vtu files, for benchmarks. See docs/datasets.md.
//
//   MakeDatasetLadder [options] <output directory>
//
// Families (every mesh holds only positively oriented linear tetrahedra and one point scalar):
//   wavelet  convex: vtkRTAnalyticSource on n^3 voxels spanning [-10,10]^3, split by
//            vtkDataSetTriangleFilter into 5 tetrahedra per voxel; scalar "RTData".
//   torus    non-convex (a solid torus): TetGen -pq1.414a<volume> on TetGenInputs/torus.off.
//   comb     non-convex (a comb with 6 teeth, a ray crosses its boundary up to 12 times):
//            TetGen -pq1.414a<volume> on TetGenInputs/comb.poly.
//   lattice  strongly non-convex (a 4x4x4-cell jungle gym of square bars, genus 176, a ray along
//            an axis crosses up to 10 walls): built in VTK from voxels, meshed with TetGen.
// TetGen meshes carry "Synthetic" = 0.5+0.5*sin(1.5x)*cos(1.5y)*cos(2z) (SOURCES.md). The
// TetGen families need the optional module TiledRayCast::FiltersTetGen (AGPL-3+ TetGen).
//
// The output is deterministic: the same build writes the same bytes. Counts are checked against
// the table below with --verify (after reading the files back).
#include "DatasetLadderMeshes.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkSmartPointer.h"
#include "vtkTimerLog.h"
#include "vtkUnsignedCharArray.h"
#include "vtkUnstructuredGrid.h"
#include "vtkVersionMacros.h"
#include "vtkXMLUnstructuredGridReader.h"
#include "vtkXMLUnstructuredGridWriter.h"

#include <vtksys/SystemTools.hxx>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include <sys/resource.h>
#ifdef __GLIBC__
#include <malloc.h>
#endif

namespace
{
using ladder::AddProvenance;
using ladder::MakeWavelet;
using ladder::OrientMesh;
#ifdef TRC_HAVE_TETGEN
using ladder::MakeLattice;
using ladder::MakeTetGen;
using ladder::ReadOFF;
using ladder::ReadPoly;
using ladder::Surface;
#endif

//------------------------------------------------------------------------------
// The ladder. For wavelet rungs the parameter is the number of voxels per axis (5 n^3
// tetrahedra); for TetGen rungs it is TetGen's maximum volume (-a), with -q1.414. The expected
// counts were measured with Debian's VTK 9.1 and TetGen 1.5.0 (docs/datasets.md).
struct Rung
{
  const char* Name;
  const char* Family;
  double Parameter;
  vtkIdType Points;
  vtkIdType Tetrahedra;
};

const Rung Ladder[] = {
  // clang-format off
  { "wavelet_100k", "wavelet", 27, 21952, 98415 },
  { "wavelet_300k", "wavelet", 39, 64000, 296595 },
  { "wavelet_1m",   "wavelet", 58, 205379, 975560 },
  { "wavelet_3m",   "wavelet", 84, 614125, 2963520 },
  { "wavelet_10m",  "wavelet", 126, 2048383, 10001880 },
  { "wavelet_30m",  "wavelet", 182, 6128487, 30142840 },
  { "torus_100k",   "torus",   0.002, 30494, 140344 },
  { "torus_300k",   "torus",   0.0005, 58363, 298546 },
  { "torus_1m",     "torus",   0.00013, 202432, 1099635 },
  { "torus_3m",     "torus",   0.00004, 508965, 2957927 },
  { "torus_10m",    "torus",   0.0000118, 1658938, 9917097 },
  { "torus_30m",    "torus",   0.0000039, 4887186, 29722399 },
  { "comb_100k",    "comb",    0.0022, 22708, 96956 },
  { "comb_300k",    "comb",    0.0008, 59426, 272607 },
  { "comb_1m",      "comb",    0.00019, 191575, 998543 },
  { "comb_3m",      "comb",    0.000063, 533988, 2941679 },
  { "comb_10m",     "comb",    0.0000185, 1671602, 9710436 },
  { "lattice_100k", "lattice", 0.017, 36302, 117321 },
  { "lattice_300k", "lattice", 0.0095, 90286, 332679 },
  { "lattice_1m",   "lattice", 0.0021, 190033, 793729 },
  { "lattice_3m",   "lattice", 0.00053, 640377, 3014983 },
  { "lattice_10m",  "lattice", 0.00016, 1967640, 9959796 },
  // clang-format on
};

// The lattice's boundary comes from vtkThreshold and vtkDataSetSurfaceFilter, whose output is
// ordered otherwise from VTK 9.3 on: TetGen meshes the same solid into other counts. Measured with
// Debian 13's VTK 9.3.0 and TetGen 1.5.0 (make test-debian13); 0 where not measured.
struct Counts
{
  const char* Name;
  vtkIdType Points;
  vtkIdType Tetrahedra;
};
const Counts LatticeFromVTK93[] = {
  { "lattice_100k", 36327, 117455 },
  { "lattice_300k", 90549, 333947 },
  { "lattice_1m", 190416, 795189 },
  { "lattice_3m", 639935, 3012908 },
  { "lattice_10m", 1967954, 9961671 },
};

// The rung as the VTK it is built against makes it (its expected counts; 0 where unknown).
Rung Expected(const Rung& rung)
{
  Rung expected = rung;
#if VTK_VERSION_NUMBER >= VTK_VERSION_CHECK(9, 3, 0)
  for (const Counts& counts : LatticeFromVTK93)
  {
    if (std::string(counts.Name) == rung.Name)
    {
      expected.Points = counts.Points;
      expected.Tetrahedra = counts.Tetrahedra;
    }
  }
#endif
  return expected;
}

// Whether `points` and `tets` are what `rung` expects with this VTK (any, where it knows none).
bool AsExpected(const Rung& rung, vtkIdType points, vtkIdType tets)
{
  const Rung expected = Expected(rung);
  return expected.Points == 0 || (points == expected.Points && tets == expected.Tetrahedra);
}

bool IsTetGenFamily(const std::string& family)
{
  return family == "torus" || family == "comb" || family == "lattice";
}

//------------------------------------------------------------------------------
struct Options
{
  std::string OutputDirectory;
  std::vector<std::string> Families;
  std::vector<std::string> Rungs;
  vtkIdType MaxTets = -1;
  std::string Inputs = TRC_TETGEN_INPUTS;
  std::string Compressor = "zlib";
  std::vector<std::pair<std::string, std::string>> Comparisons; // rung, reference file
  bool Verify = false;
  bool VerifyExisting = false;
  bool List = false;
};

void Usage(std::ostream& os)
{
  os << "Usage: MakeDatasetLadder [options] <output directory>\n"
        "  --family NAME      wavelet, torus, comb or lattice (repeatable; default all)\n"
        "  --rung NAME        only this rung, e.g. torus_1m (repeatable)\n"
        "  --max-tets N       skip rungs of more than N tetrahedra (expected counts)\n"
        "  --inputs DIR       TetGen inputs torus.off and comb.poly (default " TRC_TETGEN_INPUTS
        ")\n"
        "  --compressor NAME  zlib (default), lz4, lzma or none\n"
        "  --verify           read every file back and check it against the table\n"
        "  --verify-existing  generate nothing: check the files already in the directory\n"
        "  --compare RUNG=FILE  check that RUNG is identical to the mesh in FILE (points,\n"
        "                     tetrahedra and point arrays; e.g. a shipped mesh it reproduces)\n"
        "  --list             print the selected rungs (a Markdown table) and exit\n";
}

bool ParseArguments(int argc, char* argv[], Options& options)
{
  for (int i = 1; i < argc; ++i)
  {
    const std::string arg = argv[i];
    auto value = [&](std::string& out)
    {
      if (i + 1 >= argc)
      {
        std::cerr << "error: " << arg << " needs a value\n";
        return false;
      }
      out = argv[++i];
      return true;
    };
    std::string text;
    if (arg == "--family")
    {
      if (!value(text))
      {
        return false;
      }
      options.Families.push_back(text);
    }
    else if (arg == "--rung")
    {
      if (!value(text))
      {
        return false;
      }
      options.Rungs.push_back(text);
    }
    else if (arg == "--max-tets")
    {
      if (!value(text))
      {
        return false;
      }
      char* end = nullptr;
      options.MaxTets = std::strtoll(text.c_str(), &end, 10);
      if (*end != '\0' || options.MaxTets < 0)
      {
        std::cerr << "error: --max-tets wants a non-negative integer, not " << text << "\n";
        return false;
      }
    }
    else if (arg == "--inputs")
    {
      if (!value(options.Inputs))
      {
        return false;
      }
    }
    else if (arg == "--compressor")
    {
      if (!value(options.Compressor))
      {
        return false;
      }
      if (options.Compressor != "zlib" && options.Compressor != "lz4" &&
        options.Compressor != "lzma" && options.Compressor != "none")
      {
        std::cerr << "error: unknown compressor " << options.Compressor << "\n";
        return false;
      }
    }
    else if (arg == "--verify")
    {
      options.Verify = true;
    }
    else if (arg == "--verify-existing")
    {
      options.VerifyExisting = true;
    }
    else if (arg == "--compare")
    {
      if (!value(text))
      {
        return false;
      }
      const auto equals = text.find('=');
      if (equals == std::string::npos || equals == 0 || equals + 1 == text.size())
      {
        std::cerr << "error: --compare wants RUNG=FILE, not " << text << "\n";
        return false;
      }
      options.Comparisons.emplace_back(text.substr(0, equals), text.substr(equals + 1));
    }
    else if (arg == "--list")
    {
      options.List = true;
    }
    else if (arg == "-h" || arg == "--help")
    {
      Usage(std::cout);
      std::exit(EXIT_SUCCESS);
    }
    else if (!arg.empty() && arg[0] == '-')
    {
      std::cerr << "error: unknown option " << arg << "\n";
      return false;
    }
    else if (options.OutputDirectory.empty())
    {
      options.OutputDirectory = arg;
    }
    else
    {
      std::cerr << "error: more than one output directory given\n";
      return false;
    }
  }
  for (const auto& family : options.Families)
  {
    if (family != "wavelet" && !IsTetGenFamily(family))
    {
      std::cerr << "error: unknown family " << family << "\n";
      return false;
    }
  }
  for (const auto& name : options.Rungs)
  {
    bool known = false;
    for (const Rung& rung : Ladder)
    {
      known = known || name == rung.Name;
    }
    if (!known)
    {
      std::cerr << "error: unknown rung " << name << " (see --list)\n";
      return false;
    }
  }
  return options.List || !options.OutputDirectory.empty();
}

//------------------------------------------------------------------------------
// Peak resident memory of this process so far, in MiB.
double PeakRSSMiB()
{
  struct rusage usage;
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_maxrss) / 1024.0;
}

//------------------------------------------------------------------------------
bool Write(vtkUnstructuredGrid* mesh, const std::string& fileName, const std::string& compressor)
{
  vtkNew<vtkXMLUnstructuredGridWriter> writer;
  writer->SetInputData(mesh);
  writer->SetFileName(fileName.c_str());
  writer->SetDataModeToAppended();
  writer->EncodeAppendedDataOff();
  writer->SetHeaderTypeToUInt64();
  // Point ids fit in 32 bits up to 2^31 points: half the connectivity on disk.
  writer->SetIdTypeToInt32();
  if (compressor == "zlib")
  {
    writer->SetCompressorTypeToZLib();
  }
  else if (compressor == "lz4")
  {
    writer->SetCompressorTypeToLZ4();
  }
  else if (compressor == "lzma")
  {
    writer->SetCompressorTypeToLZMA();
  }
  else
  {
    writer->SetCompressorTypeToNone();
  }
  return writer->Write() == 1;
}

// Reads a rung back and checks it: the expected counts, tetrahedra only, all positive, the
// scalar present and finite.
bool Verify(const std::string& fileName, const Rung& rung)
{
  vtkNew<vtkXMLUnstructuredGridReader> reader;
  reader->SetFileName(fileName.c_str());
  reader->Update();
  vtkUnstructuredGrid* mesh = reader->GetOutput();
  bool ok = true;
  auto fail = [&](const std::string& what)
  {
    std::cerr << "verify " << rung.Name << ": " << what << "\n";
    ok = false;
  };
  if (!AsExpected(rung, mesh->GetNumberOfPoints(), mesh->GetNumberOfCells()))
  {
    std::ostringstream text;
    text << mesh->GetNumberOfPoints() << " points and " << mesh->GetNumberOfCells()
         << " tetrahedra, expected " << Expected(rung).Points << " and "
         << Expected(rung).Tetrahedra << " (another VTK or TetGen version?)";
    fail(text.str());
    return false;
  }
  vtkIdType swapped = 0, degenerate = 0;
  if (!OrientMesh(mesh, swapped, degenerate))
  {
    fail("cells other than tetrahedra");
  }
  else if (swapped != 0 || degenerate != 0)
  {
    fail(
      std::to_string(swapped) + " negative and " + std::to_string(degenerate) + " flat tetrahedra");
  }
  const char* scalar = std::string(rung.Family) == "wavelet" ? "RTData" : "Synthetic";
  vtkDataArray* values = mesh->GetPointData()->GetScalars();
  if (!values || std::string(values->GetName() ? values->GetName() : "") != scalar ||
    values->GetNumberOfTuples() != mesh->GetNumberOfPoints())
  {
    fail(std::string("no point scalar ") + scalar);
  }
  else
  {
    double range[2];
    values->GetRange(range, 0);
    if (!std::isfinite(range[0]) || !std::isfinite(range[1]))
    {
      fail("non-finite scalars");
    }
  }
  return ok;
}

// True when the mesh in `fileName` equals the one in `referenceName`: the same points (as float),
// the same tetrahedra in the same order and every point array of the reference, value for value.
bool Compare(const std::string& fileName, const std::string& referenceName, const Rung& rung)
{
  vtkNew<vtkXMLUnstructuredGridReader> ours, theirs;
  ours->SetFileName(fileName.c_str());
  ours->Update();
  theirs->SetFileName(referenceName.c_str());
  theirs->Update();
  vtkUnstructuredGrid* a = ours->GetOutput();
  vtkUnstructuredGrid* b = theirs->GetOutput();
  auto fail = [&](const std::string& what)
  {
    std::cerr << "compare " << rung.Name << " with " << referenceName << ": " << what << "\n";
    return false;
  };
  if (b->GetNumberOfPoints() == 0)
  {
    return fail("cannot read the reference");
  }
  if (a->GetNumberOfPoints() != b->GetNumberOfPoints() ||
    a->GetNumberOfCells() != b->GetNumberOfCells())
  {
    return fail("different numbers of points or cells");
  }
  for (vtkIdType i = 0; i < a->GetNumberOfPoints(); ++i)
  {
    double p[3], q[3];
    a->GetPoint(i, p);
    b->GetPoint(i, q);
    for (int k = 0; k < 3; ++k)
    {
      if (static_cast<float>(p[k]) != static_cast<float>(q[k]))
      {
        return fail("point " + std::to_string(i) + " differs");
      }
    }
  }
  vtkDataArray* ca = a->GetCells()->GetConnectivityArray();
  vtkDataArray* cb = b->GetCells()->GetConnectivityArray();
  if (ca->GetNumberOfValues() != cb->GetNumberOfValues())
  {
    return fail("different connectivity sizes");
  }
  for (vtkIdType i = 0; i < ca->GetNumberOfValues(); ++i)
  {
    if (ca->GetComponent(i, 0) != cb->GetComponent(i, 0))
    {
      return fail("tetrahedron " + std::to_string(i / 4) + " differs");
    }
  }
  for (int k = 0; k < b->GetPointData()->GetNumberOfArrays(); ++k)
  {
    vtkDataArray* reference = b->GetPointData()->GetArray(k);
    if (!reference)
    {
      continue;
    }
    vtkDataArray* mine = a->GetPointData()->GetArray(reference->GetName());
    if (!mine || mine->GetNumberOfComponents() != reference->GetNumberOfComponents())
    {
      return fail(std::string("no point array ") + reference->GetName());
    }
    for (vtkIdType i = 0; i < reference->GetNumberOfTuples(); ++i)
    {
      for (int c = 0; c < reference->GetNumberOfComponents(); ++c)
      {
        if (mine->GetComponent(i, c) != reference->GetComponent(i, c))
        {
          return fail(std::string("point array ") + reference->GetName() + " differs at point " +
            std::to_string(i));
        }
      }
    }
  }
  std::cout << "  " << rung.Name << " is identical to " << referenceName << std::endl;
  return true;
}

std::string Thousands(vtkIdType value)
{
  std::string digits = std::to_string(value);
  for (int i = static_cast<int>(digits.size()) - 3; i > 0; i -= 3)
  {
    digits.insert(static_cast<size_t>(i), ",");
  }
  return digits;
}
// Whether the options select `rung` (its family, its name, its size).
bool Selected(const Options& options, const Rung& rung)
{
  const std::string family = rung.Family;
  if (!options.Families.empty() &&
    std::find(options.Families.begin(), options.Families.end(), family) == options.Families.end())
  {
    return false;
  }
  if (!options.Rungs.empty() &&
    std::find(options.Rungs.begin(), options.Rungs.end(), rung.Name) == options.Rungs.end())
  {
    return false;
  }
  return options.MaxTets < 0 || rung.Tetrahedra <= options.MaxTets;
}

// The table of the selected rungs (--list).
void ListRungs(const Options& options)
{
  std::cout << "| rung | family | parameter | points | tetrahedra |\n|---|---|---|---|---|\n";
  for (const Rung& rung : Ladder)
  {
    if (!Selected(options, rung))
    {
      continue;
    }
    const Rung expected = Expected(rung);
    std::cout << "| " << rung.Name << " | " << rung.Family << " | " << rung.Parameter << " | "
              << Thousands(expected.Points) << " | " << Thousands(expected.Tetrahedra) << " |\n";
  }
}

// The output directory, created where it does not exist; false (with a message) where it cannot
// be or lies in the source tree.
bool PrepareOutputDirectory(const std::string& directory)
{
  // Never write into the source tree (a build tree inside it, as ./build, is fine). Checked on
  // the normalised path before creating anything, and on the real path (symbolic links) after.
  auto inside = [](const std::string& path, const std::string& directory)
  { return path == directory || path.rfind(directory + "/", 0) == 0; };
  auto forbidden = [&](const std::string& path, bool real)
  {
    auto normal = [&](const std::string& p) {
      return real ? vtksys::SystemTools::GetRealPath(p) : vtksys::SystemTools::CollapseFullPath(p);
    };
    const std::string sources = normal(TRC_SOURCE_DIR);
    if (inside(normal(path), sources) && !inside(normal(path), normal(TRC_BINARY_DIR)))
    {
      std::cerr << "error: " << normal(path) << " is inside the source tree " << sources
                << "; write the ladder elsewhere\n";
      return true;
    }
    return false;
  };
  if (forbidden(directory, false))
  {
    return false;
  }
  if (!vtksys::SystemTools::FileIsDirectory(directory) &&
    !vtksys::SystemTools::MakeDirectory(directory))
  {
    std::cerr << "error: cannot create " << directory << "\n";
    return false;
  }
  if (forbidden(directory, true))
  {
    return false;
  }
  return true;
}

// An existing rung read back and checked (--verify-existing); true when it passes.
bool VerifyExistingRung(const Options& options, const Rung& rung)
{
  const std::string fileName = options.OutputDirectory + "/" + rung.Name + ".vtu";
  const double start = vtkTimerLog::GetUniversalTime();
  bool ok = Verify(fileName, rung);
  for (const auto& comparison : options.Comparisons)
  {
    ok = (comparison.first != rung.Name || Compare(fileName, comparison.second, rung)) && ok;
  }
  std::cout << rung.Name << ": " << (ok ? "verified" : "FAILED") << " ("
            << vtkTimerLog::GetUniversalTime() - start << " s)" << std::endl;
  return ok;
}

// Generates, orients, writes and checks `rung`: the number of its checks that failed, or -1
// where it could not be generated or written (a message says why).
int MakeRung(const Options& options, const Rung& rung)
{
  const std::string family = rung.Family;
  int failures = 0;
#ifndef TRC_HAVE_TETGEN
  if (IsTetGenFamily(family))
  {
    std::cerr << "skipping " << rung.Name
              << ": built without TiledRayCast::FiltersTetGen (TILEDRAYCAST_ENABLE_TETGEN)\n";
    return 0;
  }
#endif
  const double start = vtkTimerLog::GetUniversalTime();
  vtkSmartPointer<vtkUnstructuredGrid> mesh;
  std::string provenance;
  if (family == "wavelet")
  {
    mesh = MakeWavelet(static_cast<int>(rung.Parameter), provenance);
  }
#ifdef TRC_HAVE_TETGEN
  else
  {
    Surface surface;
    std::string input;
    bool read = false;
    if (family == "torus")
    {
      input = "torus.off";
      read = ReadOFF(options.Inputs + "/" + input, surface);
    }
    else if (family == "comb")
    {
      input = "comb.poly";
      read = ReadPoly(options.Inputs + "/" + input, surface);
    }
    else
    {
      input = "lattice";
      surface = MakeLattice(4);
      read = surface.PolyData && surface.PolyData->GetNumberOfPolys() > 0;
    }
    if (!read)
    {
      std::cerr << "error: cannot read " << options.Inputs << "/" << input << "\n";
      return -1;
    }
    std::string switches;
    mesh = MakeTetGen(surface, rung.Parameter, switches);
    std::ostringstream text;
    text << "vtkTetGenMesher (TetGen 1.5 library) -" << switches << " on " << input
         << "; scalar Synthetic = 0.5+0.5*sin(1.5x)*cos(1.5y)*cos(2z)";
    provenance = text.str();
  }
#endif
  if (!mesh)
  {
    std::cerr << "error: " << rung.Name << " could not be generated\n";
    return -1;
  }
  vtkIdType swapped = 0, degenerate = 0;
  if (!OrientMesh(mesh, swapped, degenerate))
  {
    std::cerr << "error: " << rung.Name << " holds cells other than tetrahedra\n";
    return -1;
  }
  AddProvenance(mesh, std::string("MakeDatasetLadder ") + rung.Name + ": " + provenance);
  const double generated = vtkTimerLog::GetUniversalTime();

  const std::string fileName = options.OutputDirectory + "/" + rung.Name + ".vtu";
  if (!Write(mesh, fileName, options.Compressor))
  {
    std::cerr << "error: cannot write " << fileName << "\n";
    return -1;
  }
  const double written = vtkTimerLog::GetUniversalTime();
  const vtkIdType points = mesh->GetNumberOfPoints();
  const vtkIdType tets = mesh->GetNumberOfCells();
  mesh = nullptr;

  char row[512];
  std::snprintf(row, sizeof(row), "| %s | %s | %s | %s | %.1f | %.1f | %.1f | %.0f |", rung.Name,
    family == "wavelet" ? "yes" : "no", Thousands(points).c_str(), Thousands(tets).c_str(),
    generated - start, written - generated,
    static_cast<double>(vtksys::SystemTools::FileLength(fileName)) / (1024.0 * 1024.0),
    PeakRSSMiB());
  std::cout << row << std::endl;
  if (swapped > 0 || degenerate > 0)
  {
    std::cout << "  (" << swapped << " tetrahedra reoriented, " << degenerate << " flat)"
              << std::endl;
  }
  if (!AsExpected(rung, points, tets))
  {
    std::cerr << rung.Name << ": expected " << Expected(rung).Points << " points and "
              << Expected(rung).Tetrahedra << " tetrahedra\n";
    ++failures;
  }
  if (options.Verify && !Verify(fileName, rung))
  {
    ++failures;
  }
  for (const auto& comparison : options.Comparisons)
  {
    if (comparison.first == rung.Name && !Compare(fileName, comparison.second, rung))
    {
      ++failures;
    }
  }
  return failures;
}

} // anonymous namespace

//------------------------------------------------------------------------------
int main(int argc, char* argv[])
{
#ifdef __GLIBC__
  // glibc gives the free top of the heap back to the system whenever a freed block leaves more
  // than its trim threshold there, and takes it back at the next allocation. After the large
  // arrays of a rung are freed, the XML writer's per-block buffers hit exactly that: a storm of
  // brk calls and page faults (wavelet_3m: writing took 12.2 s, 4.2 s of it system time, and
  // takes 2.1 s with this padding). 64 MiB of slack at the top of the heap stops it.
  mallopt(M_TOP_PAD, 64 << 20);
#endif
  Options options;
  if (!ParseArguments(argc, argv, options))
  {
    Usage(std::cerr);
    return EXIT_FAILURE;
  }
  if (options.List)
  {
    ListRungs(options);
    return EXIT_SUCCESS;
  }
  if (!PrepareOutputDirectory(options.OutputDirectory))
  {
    return EXIT_FAILURE;
  }

  if (!options.VerifyExisting)
  {
    std::cout << "| rung | convex | points | tetrahedra | generate (s) | write (s) | file (MiB) "
                 "| peak RSS so far (MiB) |\n|---|---|---|---|---|---|---|---|\n";
  }
  int failures = 0;
  for (const Rung& rung : Ladder)
  {
    if (!Selected(options, rung))
    {
      continue;
    }
    if (options.VerifyExisting)
    {
      failures += VerifyExistingRung(options, rung) ? 0 : 1;
      continue;
    }
    const int failed = MakeRung(options, rung);
    if (failed < 0)
    {
      return EXIT_FAILURE;
    }
    failures += failed;
  }
  if (failures > 0)
  {
    std::cerr << failures << " rungs differ from the table\n";
    return EXIT_FAILURE;
  }
  return EXIT_SUCCESS;
}
