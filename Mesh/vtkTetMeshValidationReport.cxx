/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkTetMeshValidationReport.cxx

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "vtkTetMeshValidationReport.h"

#include "vtkIdTypeArray.h"
#include "vtkObjectFactory.h"

#include <sstream>

vtkStandardNewMacro(vtkTetMeshValidationReport);

//------------------------------------------------------------------------------
vtkTetMeshValidationReport::vtkTetMeshValidationReport()
  : DegenerateCellIds(vtkSmartPointer<vtkIdTypeArray>::New())
{
}

//------------------------------------------------------------------------------
vtkTetMeshValidationReport::~vtkTetMeshValidationReport() = default;

//------------------------------------------------------------------------------
void vtkTetMeshValidationReport::Reset()
{
  this->NumberOfInputPoints = 0;
  this->NumberOfInputCells = 0;
  this->NumberOfTetrahedra = 0;
  this->NumberOfBoundaryFaces = 0;
  this->NumberOfSplitCells = 0;
  this->NumberOfIgnoredCells = 0;
  this->NumberOfInvalidCells = 0;
  this->NumberOfInvertedTetrahedra = 0;
  this->NumberOfDegenerateTetrahedra = 0;
  this->NumberOfNonManifoldFaces = 0;
  this->NumberOfOverlappingTetrahedra = 0;
  this->NumberOfCrackFaces = 0;
  this->NumberOfDuplicatePoints = 0;
  this->NumberOfNonFiniteScalars = 0;
  this->NumberOfBlocks = 0;
  this->NumberOfEmptyBlocks = 0;
  this->NumberOfSharedPoints = 0;
  this->DegenerateCellIds->Reset();
  this->ErrorMessage.clear();
  this->Modified();
}

//------------------------------------------------------------------------------
vtkIdTypeArray* vtkTetMeshValidationReport::GetDegenerateCellIds()
{
  return this->DegenerateCellIds;
}

//------------------------------------------------------------------------------
void vtkTetMeshValidationReport::SetError(const std::string& message)
{
  // An empty message would read as "usable": keep a generic one instead.
  this->ErrorMessage = message.empty() ? std::string("the grid cannot be rendered") : message;
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkTetMeshValidationReport::ClearError()
{
  if (!this->ErrorMessage.empty())
  {
    this->ErrorMessage.clear();
    this->Modified();
  }
}

//------------------------------------------------------------------------------
bool vtkTetMeshValidationReport::HasDefects() const
{
  return this->NumberOfSplitCells > 0 || this->NumberOfIgnoredCells > 0 ||
    this->NumberOfInvalidCells > 0 || this->NumberOfInvertedTetrahedra > 0 ||
    this->NumberOfDegenerateTetrahedra > 0 || this->NumberOfNonManifoldFaces > 0 ||
    this->NumberOfOverlappingTetrahedra > 0 || this->NumberOfCrackFaces > 0 ||
    this->NumberOfDuplicatePoints > 0 || this->NumberOfNonFiniteScalars > 0;
}

//------------------------------------------------------------------------------
bool vtkTetMeshValidationReport::HasProblems() const
{
  return this->HasProblemsBesidesDegeneracy() || this->NumberOfDegenerateTetrahedra > 0 ||
    this->NumberOfDuplicatePoints > 0;
}

//------------------------------------------------------------------------------
bool vtkTetMeshValidationReport::HasProblemsBesidesDegeneracy() const
{
  return this->NumberOfIgnoredCells > 0 || this->NumberOfInvalidCells > 0 ||
    this->NumberOfNonManifoldFaces > 0 || this->NumberOfOverlappingTetrahedra > 0 ||
    this->NumberOfCrackFaces > 0 || this->NumberOfNonFiniteScalars > 0;
}

//------------------------------------------------------------------------------
std::string vtkTetMeshValidationReport::GetSummary() const
{
  std::ostringstream text;
  if (!this->GetUsable())
  {
    text << "unusable: " << this->ErrorMessage << ". ";
  }
  text << this->NumberOfInputCells << " input cells and " << this->NumberOfInputPoints
       << " points gave " << this->NumberOfTetrahedra << " tetrahedra with "
       << this->NumberOfBoundaryFaces << " boundary faces";
  if (this->NumberOfBlocks > 0)
  {
    text << " (a composite input of " << this->NumberOfBlocks << " blocks, "
         << this->NumberOfEmptyBlocks << " empty, merged into one grid with "
         << this->NumberOfSharedPoints << " points shared between blocks)";
  }
  struct Item
  {
    vtkIdType Count;
    const char* What;
  };
  const Item items[] = {
    { this->NumberOfSplitCells, "non-tetrahedral 3D cells split into tetrahedra" },
    { this->NumberOfIgnoredCells, "cells of dimension < 3 ignored" },
    { this->NumberOfInvalidCells, "invalid cells (bad point ids) ignored" },
    { this->NumberOfInvertedTetrahedra, "inverted tetrahedra reoriented" },
    { this->NumberOfDegenerateTetrahedra, "degenerate (zero-volume) tetrahedra" },
    { this->NumberOfNonManifoldFaces, "non-manifold faces (shared by more than two cells)" },
    { this->NumberOfOverlappingTetrahedra,
      "overlapping tetrahedra left out (on the same side of a shared face as an earlier one)" },
    { this->NumberOfCrackFaces, "crack faces (coincident but not shared)" },
    { this->NumberOfDuplicatePoints, "duplicate points" },
    { this->NumberOfNonFiniteScalars, "NaN or infinite scalars (made transparent)" },
  };
  for (const Item& item : items)
  {
    if (item.Count > 0)
    {
      text << "; " << item.Count << " " << item.What;
    }
  }
  text << ".";
  return text.str();
}

//------------------------------------------------------------------------------
void vtkTetMeshValidationReport::DeepCopy(vtkTetMeshValidationReport* other)
{
  if (!other || other == this)
  {
    return;
  }
  this->NumberOfInputPoints = other->NumberOfInputPoints;
  this->NumberOfInputCells = other->NumberOfInputCells;
  this->NumberOfTetrahedra = other->NumberOfTetrahedra;
  this->NumberOfBoundaryFaces = other->NumberOfBoundaryFaces;
  this->NumberOfSplitCells = other->NumberOfSplitCells;
  this->NumberOfIgnoredCells = other->NumberOfIgnoredCells;
  this->NumberOfInvalidCells = other->NumberOfInvalidCells;
  this->NumberOfInvertedTetrahedra = other->NumberOfInvertedTetrahedra;
  this->NumberOfDegenerateTetrahedra = other->NumberOfDegenerateTetrahedra;
  this->NumberOfNonManifoldFaces = other->NumberOfNonManifoldFaces;
  this->NumberOfOverlappingTetrahedra = other->NumberOfOverlappingTetrahedra;
  this->NumberOfCrackFaces = other->NumberOfCrackFaces;
  this->NumberOfDuplicatePoints = other->NumberOfDuplicatePoints;
  this->NumberOfNonFiniteScalars = other->NumberOfNonFiniteScalars;
  this->NumberOfBlocks = other->NumberOfBlocks;
  this->NumberOfEmptyBlocks = other->NumberOfEmptyBlocks;
  this->NumberOfSharedPoints = other->NumberOfSharedPoints;
  this->DegenerateCellIds->DeepCopy(other->DegenerateCellIds);
  this->ErrorMessage = other->ErrorMessage;
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkTetMeshValidationReport::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Usable: " << (this->GetUsable() ? "yes" : "no") << "\n";
  if (!this->GetUsable())
  {
    os << indent << "ErrorMessage: " << this->ErrorMessage << "\n";
  }
  os << indent << "NumberOfInputPoints: " << this->NumberOfInputPoints << "\n";
  os << indent << "NumberOfInputCells: " << this->NumberOfInputCells << "\n";
  os << indent << "NumberOfTetrahedra: " << this->NumberOfTetrahedra << "\n";
  os << indent << "NumberOfBoundaryFaces: " << this->NumberOfBoundaryFaces << "\n";
  os << indent << "NumberOfSplitCells: " << this->NumberOfSplitCells << "\n";
  os << indent << "NumberOfIgnoredCells: " << this->NumberOfIgnoredCells << "\n";
  os << indent << "NumberOfInvalidCells: " << this->NumberOfInvalidCells << "\n";
  os << indent << "NumberOfInvertedTetrahedra: " << this->NumberOfInvertedTetrahedra << "\n";
  os << indent << "NumberOfDegenerateTetrahedra: " << this->NumberOfDegenerateTetrahedra << "\n";
  os << indent << "NumberOfNonManifoldFaces: " << this->NumberOfNonManifoldFaces << "\n";
  os << indent << "NumberOfOverlappingTetrahedra: " << this->NumberOfOverlappingTetrahedra << "\n";
  os << indent << "NumberOfCrackFaces: " << this->NumberOfCrackFaces << "\n";
  os << indent << "NumberOfDuplicatePoints: " << this->NumberOfDuplicatePoints << "\n";
  os << indent << "NumberOfNonFiniteScalars: " << this->NumberOfNonFiniteScalars << "\n";
  os << indent << "NumberOfBlocks: " << this->NumberOfBlocks << "\n";
  os << indent << "NumberOfEmptyBlocks: " << this->NumberOfEmptyBlocks << "\n";
  os << indent << "NumberOfSharedPoints: " << this->NumberOfSharedPoints << "\n";
}
