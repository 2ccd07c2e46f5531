/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkTiledRayCastMemoryBudget.cxx

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "vtkTiledRayCastMemoryBudget.h"

#include "vtkCellType.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkTetMeshLayout.h"
#include "vtkUnstructuredGrid.h"
#include "vtk_glew.h"

#include <cstdio>
#include <string>

namespace
{
// The fewest tetrahedra one cell of `type` is split into (vtkOrderedTriangulator: a hexahedron
// or voxel into 5 or 6, a wedge into 3, a pyramid into 2); 0 for a type that bounds nothing.
vtkIdType FewestTets(int type)
{
  switch (type)
  {
    case VTK_TETRA:
      return 1;
    case VTK_HEXAHEDRON:
    case VTK_VOXEL:
      return 5;
    case VTK_WEDGE:
      return 3;
    case VTK_PYRAMID:
      return 2;
    default:
      return 0;
  }
}

// Bytes in GB, MB or kB, three significant digits.
std::string Size(vtkIdType bytes)
{
  const double b = static_cast<double>(bytes);
  const char* unit = b >= 1e9 ? "GB" : (b >= 1e6 ? "MB" : "kB");
  const double scaled = b / (b >= 1e9 ? 1e9 : (b >= 1e6 ? 1e6 : 1e3));
  char text[32];
  std::snprintf(text, sizeof(text), "%.3g %s", scaled, unit);
  return text;
}
}

//------------------------------------------------------------------------------
void vtkTiledRayCastMemoryBudget::Update(
  vtkOpenGLRenderWindow* window, vtkIdType userLimit, vtkIdType heldBytes)
{
  this->Window = window;
  this->UserLimit = userLimit;
  this->HeldBytes = heldBytes;
  this->Known = false;
}

//------------------------------------------------------------------------------
vtkIdType vtkTiledRayCastMemoryBudget::GetBytes()
{
  if (this->Known)
  {
    return this->Bytes;
  }
  this->Known = true;
  this->Bytes = -1;
  this->Source.clear();
  if (this->UserLimit > 0)
  {
    this->Bytes = this->UserLimit;
    this->Source = "the mapper's MaximumGPUMemory";
  }
  // NVIDIA's own driver's report only: Mesa 25's llvmpipe (Debian 13) exposes the extension and
  // answers with whatever its stack held (from 1 KiB to 2 TB free, changing from call to call).
  if (this->Window && GLEW_NVX_gpu_memory_info &&
    this->Window->GetState()->GetVendor().compare(0, 6, "NVIDIA") == 0)
  {
    // In KiB. What the mesh holds now is replaced, so it counts as free.
    int freeKiB = 0;
    this->Window->GetState()->vtkglGetIntegerv(
      GL_GPU_MEMORY_INFO_CURRENT_AVAILABLE_VIDMEM_NVX, &freeKiB);
    const vtkIdType available = 1024 * static_cast<vtkIdType>(freeKiB) + this->HeldBytes;
    if (freeKiB > 0 && (this->Bytes < 0 || available < this->Bytes))
    {
      this->Bytes = available;
      this->Source = "the GPU memory the driver reports free";
    }
  }
  return this->Bytes;
}

//------------------------------------------------------------------------------
std::string vtkTiledRayCastMemoryBudget::Refusal(
  vtkIdType needed, const std::string& mesh, const std::string& atLeast) const
{
  return "the mesh (" + mesh + ") needs " + atLeast + Size(needed) + " on the GPU (" +
    std::to_string(needed) + " bytes), more than the " + Size(this->Bytes) + " of " + this->Source +
    "; split it over several GPUs (ParaView under MPI, docs/parallel.md) or lower its resolution";
}

//------------------------------------------------------------------------------
bool vtkTiledRayCastMemoryBudget::CheckInput(
  vtkDataSet* input, bool paperLayout, std::string& error)
{
  auto* grid = vtkUnstructuredGrid::SafeDownCast(input);
  // IsHomogeneous() reads every cell type (90 ms for 300M cells): last.
  if (this->GetBytes() < 0 || !grid || grid->GetNumberOfCells() == 0 || !grid->IsHomogeneous())
  {
    return true;
  }
  const vtkIdType tets = grid->GetNumberOfCells() * FewestTets(grid->GetCellType(0));
  // Per tetrahedron 144 bytes (paper) or 32 (compact: its point ids and neighbours), and 16 per
  // point in the compact layout; the boundary, the visible set and scalars come on top.
  const vtkIdType needed = paperLayout ? 144 * tets : 32 * tets + 16 * grid->GetNumberOfPoints();
  if (needed <= this->Bytes)
  {
    return true;
  }
  error = this->Refusal(needed,
    std::to_string(tets) + " tetrahedra or more and " + std::to_string(grid->GetNumberOfPoints()) +
      " points, known before the build",
    "at least ");
  return false;
}

//------------------------------------------------------------------------------
bool vtkTiledRayCastMemoryBudget::CheckLayout(
  vtkTetMeshLayout* layout, vtkIdType visibleMeshBytes, std::string& error)
{
  const vtkIdType needed = layout->GetNumberOfBytes() + visibleMeshBytes;
  if (this->GetBytes() < 0 || needed <= this->Bytes)
  {
    return true;
  }
  error =
    this->Refusal(needed, std::to_string(layout->GetNumberOfTetrahedra()) + " tetrahedra", "");
  return false;
}
