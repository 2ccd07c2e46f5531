/*=========================================================================

  Program:   TiledRayCast
  Module:    GeneratedMeshes.cxx

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "GeneratedMeshes.h"

#include "vtkCellArray.h"
#include "vtkCellType.h"
#include "vtkFloatArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkSMPTools.h"
#include "vtkTypeInt32Array.h"
#include "vtkTypeInt64Array.h"
#include "vtkUnsignedCharArray.h"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <iostream>
#include <vector>

namespace generated
{
namespace
{
// Expected counts: wavelet6 6 n^3 tetrahedra on (n + 1)^3 points; gym6 6 (3 a^2 (n - a) + a^3)
// for the a voxels per axis inside a slab, on the points next to a kept voxel.
const Rung Rungs[] = {
  // clang-format off
  { "wavelet6_1m",   "wavelet6", 55,  175616,    998250 },
  { "wavelet6_10m",  "wavelet6", 119, 1728000,   10110954 },
  { "wavelet6_100m", "wavelet6", 256, 16974593,  100663296 },
  { "wavelet6_300m", "wavelet6", 368, 50243409,  299016192 },
  { "wavelet6_1b",   "wavelet6", 550, 167284151, 998250000 },
  { "gym6_1m",       "gym6",     79,  217728,    1009050 },
  { "gym6_100m",     "gym6",     370, 17697771,  99932784 },
  { "gym6_300m",     "gym6",     533, 52126200,  299806350 },
  { "gym6_1b",       "gym6",     798, 171679775, 1001156112 },
  // clang-format on
};

// The point scalar of vtkRTAnalyticSource's defaults (whole extent [-10,10]^3, centre 0,
// maximum 255, standard deviation 0.5, frequencies 60/30/40, magnitudes 10/18/5) at (x, y, z).
float RTData(double x, double y, double z)
{
  // The source works on (centre - index) / (extent width): here -x / 20.
  const double u = -x / 20.0, v = -y / 20.0, w = -z / 20.0;
  const double sum = u * u + v * v + w * w;
  return static_cast<float>(255.0 * std::exp(-sum * 2.0) + 10.0 * std::sin(60.0 * u) +
    18.0 * std::sin(30.0 * v) + 5.0 * std::cos(40.0 * w));
}

// The 6 tetrahedra of a voxel around its diagonal from corner 0 to corner 7 (corner bits x, y,
// z): one per order of the axes; an odd order has its last two points swapped (positive volume).
const int VoxelTets[6][4] = {
  { 0, 1, 3, 7 }, // x y z
  { 0, 2, 7, 3 }, // y x z (odd)
  { 0, 2, 6, 7 }, // y z x
  { 0, 4, 7, 6 }, // z y x (odd)
  { 0, 4, 5, 7 }, // z x y
  { 0, 1, 7, 5 }, // x z y (odd)
};

struct Layout
{
  bool AllKept; // wavelet6: every voxel (the family compared once, not per voxel)
  int N = 0;
  std::vector<char> Inside; // per voxel index along an axis: inside a slab (gym6)

  Layout(const std::string& family, int n)
    : AllKept(family == "wavelet6")
    , N(n)
    , Inside(n)
  {
    for (int i = 0; i < n; ++i)
    {
      this->Inside[i] = ((vtkIdType(i) * 13) / n) % 3 == 0;
    }
  }

  bool Kept(int i, int j, int k) const
  {
    if (this->AllKept)
    {
      return true;
    }
    return int(this->Inside[i]) + int(this->Inside[j]) + int(this->Inside[k]) >= 2;
  }

  // Kept, and inside the n^3 voxels.
  bool KeptInside(int i, int j, int k) const
  {
    return i >= 0 && j >= 0 && k >= 0 && i < this->N && j < this->N && k < this->N &&
      this->Kept(i, j, k);
  }

  // Whether lattice point (i, j, k) is a corner of a kept voxel.
  bool Used(int i, int j, int k) const
  {
    for (int dk = -1; dk <= 0; ++dk)
    {
      for (int dj = -1; dj <= 0; ++dj)
      {
        for (int di = -1; di <= 0; ++di)
        {
          if (this->KeptInside(i + di, j + dj, k + dk))
          {
            return true;
          }
        }
      }
    }
    return false;
  }
};

// Counts per slice `k` (kept voxels, or used points), then their exclusive prefix sum.
template <typename CountSlice>
std::vector<vtkIdType> SliceOffsets(int slices, CountSlice count)
{
  std::vector<vtkIdType> offsets(slices + 1, 0);
  vtkSMPTools::For(0, slices, 1,
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType k = begin; k < end; ++k)
      {
        offsets[k + 1] = count(static_cast<int>(k));
      }
    });
  for (int k = 0; k < slices; ++k)
  {
    offsets[k + 1] += offsets[k];
  }
  return offsets;
}

// The Morton code of lattice point (i, j, k), 21 bits per axis.
uint64_t MortonCode(vtkIdType i, vtkIdType j, vtkIdType k)
{
  uint64_t code = 0;
  for (int b = 0; b < 21; ++b)
  {
    code |= ((uint64_t(i) >> b & 1u) << (3 * b)) | ((uint64_t(j) >> b & 1u) << (3 * b + 1)) |
      ((uint64_t(k) >> b & 1u) << (3 * b + 2));
  }
  return code;
}

// `pointIds` (lattice index to point id, -1 for an unused point; empty: every point, in lattice
// order) renumbered along the Morton curve of the lattice indices of an m^3 lattice.
void RenumberAlongMorton(vtkIdType m, std::vector<vtkIdType>& pointIds)
{
  const vtkIdType lattice = m * m * m;
  std::vector<std::pair<uint64_t, vtkIdType>> keyed(static_cast<size_t>(lattice));
  vtkSMPTools::For(0, lattice, 1 << 16,
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType p = begin; p < end; ++p)
      {
        const bool used = pointIds.empty() || pointIds[p] >= 0;
        keyed[p] = { used ? MortonCode(p % m, (p / m) % m, p / (m * m)) : ~uint64_t(0), p };
      }
    });
  vtkSMPTools::Sort(keyed.begin(), keyed.end());
  pointIds.assign(static_cast<size_t>(lattice), -1);
  vtkSMPTools::For(0, lattice, 1 << 16,
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType r = begin; r < end; ++r)
      {
        if (keyed[r].first != ~uint64_t(0))
        {
          pointIds[keyed[r].second] = r;
        }
      }
    });
}

template <typename IdArray>
vtkSmartPointer<vtkCellArray> MakeCells(const Layout& layout,
  const std::vector<vtkIdType>& voxelOffsets, const std::vector<vtkIdType>& pointIds)
{
  using Id = typename IdArray::ValueType;
  const int n = layout.N;
  const vtkIdType m = n + 1;
  const vtkIdType numTets = 6 * voxelOffsets[n];
  vtkNew<IdArray> connectivity;
  connectivity->SetNumberOfValues(4 * numTets);
  vtkNew<IdArray> offsets;
  offsets->SetNumberOfValues(numTets + 1);
  Id* conn = connectivity->GetPointer(0);
  Id* offs = offsets->GetPointer(0);
  vtkSMPTools::For(0, n, 1,
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType k = begin; k < end; ++k)
      {
        vtkIdType t = 6 * voxelOffsets[k];
        for (int j = 0; j < n; ++j)
        {
          for (int i = 0; i < n; ++i)
          {
            if (!layout.Kept(i, j, int(k)))
            {
              continue;
            }
            Id corner[8];
            for (int c = 0; c < 8; ++c)
            {
              const vtkIdType lattice =
                (i + (c & 1)) + m * ((j + ((c >> 1) & 1)) + m * (k + ((c >> 2) & 1)));
              corner[c] = static_cast<Id>(pointIds.empty() ? lattice : pointIds[lattice]);
            }
            for (const auto& tet : VoxelTets)
            {
              for (int p = 0; p < 4; ++p)
              {
                conn[4 * t + p] = corner[tet[p]];
              }
              offs[t] = static_cast<Id>(4 * t);
              ++t;
            }
          }
        }
      }
    });
  offs[numTets] = static_cast<Id>(4 * numTets);
  vtkNew<vtkCellArray> cells;
  cells->SetData(offsets, connectivity);
  return cells.Get();
}
} // namespace

//------------------------------------------------------------------------------
const Rung* FindRung(const std::string& name)
{
  for (const Rung& rung : Rungs)
  {
    if (name == rung.Name)
    {
      return &rung;
    }
  }
  return nullptr;
}

//------------------------------------------------------------------------------
const Rung* GetRungs(int& count)
{
  count = static_cast<int>(sizeof(Rungs) / sizeof(Rungs[0]));
  return Rungs;
}

//------------------------------------------------------------------------------
vtkSmartPointer<vtkUnstructuredGrid> MakeMesh(const std::string& family, int n, bool mortonPoints)
{
  if ((family != "wavelet6" && family != "gym6") || n < 1)
  {
    std::cerr << "unknown generated family " << family << " (wavelet6 or gym6)\n";
    return nullptr;
  }
  const Layout layout(family, n);
  const vtkIdType m = n + 1;
  const std::vector<vtkIdType> voxelOffsets = SliceOffsets(n,
    [&](int k)
    {
      vtkIdType kept = 0;
      for (int j = 0; j < n; ++j)
      {
        for (int i = 0; i < n; ++i)
        {
          kept += layout.Kept(i, j, k) ? 1 : 0;
        }
      }
      return kept;
    });

  // The points: every lattice point (wavelet6), or those of kept voxels renumbered in order.
  std::vector<vtkIdType> pointIds;
  vtkIdType numPoints = m * m * m;
  if (family == "gym6")
  {
    pointIds.assign(static_cast<size_t>(m * m * m), -1);
    const std::vector<vtkIdType> pointOffsets = SliceOffsets(int(m),
      [&](int k)
      {
        vtkIdType used = 0;
        for (int j = 0; j < m; ++j)
        {
          for (int i = 0; i < m; ++i)
          {
            used += layout.Used(i, j, k) ? 1 : 0;
          }
        }
        return used;
      });
    vtkSMPTools::For(0, m, 1,
      [&](vtkIdType begin, vtkIdType end)
      {
        for (vtkIdType k = begin; k < end; ++k)
        {
          vtkIdType next = pointOffsets[k];
          for (int j = 0; j < m; ++j)
          {
            for (int i = 0; i < m; ++i)
            {
              if (layout.Used(i, j, int(k)))
              {
                pointIds[i + m * (j + m * k)] = next++;
              }
            }
          }
        }
      });
    numPoints = pointOffsets[m];
  }
  if (mortonPoints)
  {
    RenumberAlongMorton(m, pointIds);
  }
  vtkNew<vtkFloatArray> coordinates;
  coordinates->SetNumberOfComponents(3);
  coordinates->SetNumberOfTuples(numPoints);
  vtkNew<vtkFloatArray> scalars;
  scalars->SetName("RTData");
  scalars->SetNumberOfTuples(numPoints);
  float* xyz = coordinates->GetPointer(0);
  float* s = scalars->GetPointer(0);
  const double h = 20.0 / n;
  vtkSMPTools::For(0, m * m * m, 1 << 16,
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType lattice = begin; lattice < end; ++lattice)
      {
        const vtkIdType id = pointIds.empty() ? lattice : pointIds[lattice];
        if (id < 0)
        {
          continue;
        }
        const double x = -10.0 + h * (lattice % m);
        const double y = -10.0 + h * ((lattice / m) % m);
        const double z = -10.0 + h * (lattice / (m * m));
        xyz[3 * id] = static_cast<float>(x);
        xyz[3 * id + 1] = static_cast<float>(y);
        xyz[3 * id + 2] = static_cast<float>(z);
        s[id] = RTData(x, y, z);
      }
    });

  const vtkIdType numTets = 6 * voxelOffsets[n];
  vtkSmartPointer<vtkCellArray> cells = 4 * numTets < VTK_INT_MAX
    ? MakeCells<vtkTypeInt32Array>(layout, voxelOffsets, pointIds)
    : MakeCells<vtkTypeInt64Array>(layout, voxelOffsets, pointIds);
  pointIds = std::vector<vtkIdType>();
  vtkNew<vtkUnsignedCharArray> types;
  types->SetNumberOfValues(numTets);
  std::memset(types->GetPointer(0), VTK_TETRA, static_cast<size_t>(numTets));

  auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
  vtkNew<vtkPoints> points;
  points->SetData(coordinates);
  grid->SetPoints(points);
  grid->SetCells(types, cells);
  grid->GetPointData()->SetScalars(scalars);
  return grid;
}

//------------------------------------------------------------------------------
vtkSmartPointer<vtkUnstructuredGrid> MakeRung(const Rung& rung, bool mortonPoints)
{
  vtkSmartPointer<vtkUnstructuredGrid> grid = MakeMesh(rung.Family, rung.Voxels, mortonPoints);
  if (grid &&
    (grid->GetNumberOfPoints() != rung.Points || grid->GetNumberOfCells() != rung.Tetrahedra))
  {
    std::cerr << rung.Name << ": " << grid->GetNumberOfPoints() << " points and "
              << grid->GetNumberOfCells() << " tetrahedra, expected " << rung.Points << " and "
              << rung.Tetrahedra << "\n";
    return nullptr;
  }
  return grid;
}
//------------------------------------------------------------------------------
vtkIdType CountBoundaryFaces(const std::string& family, int n)
{
  const Layout layout(family, n);
  const std::vector<vtkIdType> perSlice = SliceOffsets(n,
    [&](int k)
    {
      static const int steps[6][3] = { { 1, 0, 0 }, { -1, 0, 0 }, { 0, 1, 0 }, { 0, -1, 0 },
        { 0, 0, 1 }, { 0, 0, -1 } };
      vtkIdType faces = 0;
      for (int j = 0; j < n; ++j)
      {
        for (int i = 0; i < n; ++i)
        {
          if (!layout.Kept(i, j, k))
          {
            continue;
          }
          for (const auto& d : steps)
          {
            faces += layout.KeptInside(i + d[0], j + d[1], k + d[2]) ? 0 : 2;
          }
        }
      }
      return faces;
    });
  return perSlice[n];
}
} // namespace generated
