/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkTetMeshValidationReport.h

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
/**
 * @class   vtkTetMeshValidationReport
 * @brief   what vtkTetMeshBuilder found wrong (and fixed) in an unstructured grid
 *
 * The builder never crashes on bad input: it counts what it finds here, fixes what can be fixed
 * (inverted tetrahedra are reoriented, non-tetrahedral 3D cells are split) and marks the input
 * unusable, with a message, when nothing can be rendered (no 3D cells, no usable scalars).
 * Mappers read the report to decide whether to draw and what to tell the user; users read it
 * from C++ or Python with the getters below or as text with GetSummary().
 *
 * Counts refer to the input grid (cells, points) or to the tetrahedra after splitting
 * (tetrahedra, faces).
 */

#ifndef vtkTetMeshValidationReport_h
#define vtkTetMeshValidationReport_h

#include "vtkObject.h"
#include "vtkSmartPointer.h"           // For vtkSmartPointer
#include "vtkTiledRayCastMeshModule.h" // For export macro

#include <string> // For std::string

class vtkIdTypeArray;

class VTKTILEDRAYCASTMESH_EXPORT vtkTetMeshValidationReport : public vtkObject
{
public:
  static vtkTetMeshValidationReport* New();
  vtkTypeMacro(vtkTetMeshValidationReport, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * Forget everything: all counts zero, usable, no messages.
   */
  void Reset();

  ///@{
  /**
   * Size of the input grid and of the tetrahedral mesh built from it.
   */
  vtkSetMacro(NumberOfInputPoints, vtkIdType);
  vtkGetMacro(NumberOfInputPoints, vtkIdType);
  vtkSetMacro(NumberOfInputCells, vtkIdType);
  vtkGetMacro(NumberOfInputCells, vtkIdType);
  vtkSetMacro(NumberOfTetrahedra, vtkIdType);
  vtkGetMacro(NumberOfTetrahedra, vtkIdType);
  vtkSetMacro(NumberOfBoundaryFaces, vtkIdType);
  vtkGetMacro(NumberOfBoundaryFaces, vtkIdType);
  ///@}

  ///@{
  /**
   * Cells other than linear tetrahedra. Split cells are 3D cells (hexahedra, wedges, pyramids,
   * voxels, higher-order cells) that were split into tetrahedra; ignored cells are cells of
   * dimension lower than 3 (vertices, lines, polygons), which hold no volume, and 3D cells of
   * types VTK cannot split (abstract higher-order and parametric types). Invalid cells refer to
   * point ids outside the grid or have the wrong number of points; they are ignored too.
   */
  vtkSetMacro(NumberOfSplitCells, vtkIdType);
  vtkGetMacro(NumberOfSplitCells, vtkIdType);
  vtkSetMacro(NumberOfIgnoredCells, vtkIdType);
  vtkGetMacro(NumberOfIgnoredCells, vtkIdType);
  vtkSetMacro(NumberOfInvalidCells, vtkIdType);
  vtkGetMacro(NumberOfInvalidCells, vtkIdType);
  ///@}

  ///@{
  /**
   * Geometric defects. Inverted tetrahedra (negative signed volume) were reoriented.
   * Degenerate tetrahedra have a volume that is zero or negligible against the cube of their
   * longest edge; they are kept in the mesh (their faces still connect their neighbours) but
   * hold no volume, so they contribute nothing to an image.
   */
  vtkSetMacro(NumberOfInvertedTetrahedra, vtkIdType);
  vtkGetMacro(NumberOfInvertedTetrahedra, vtkIdType);
  vtkSetMacro(NumberOfDegenerateTetrahedra, vtkIdType);
  vtkGetMacro(NumberOfDegenerateTetrahedra, vtkIdType);
  ///@}

  ///@{
  /**
   * Topological defects. A non-manifold face is shared by more than two tetrahedra. Two
   * tetrahedra on the same side of a face they share overlap: the later one in input order is
   * left out of the rendering (an overlapping tetrahedron; the reference renderer leaves it out
   * too, see vtkTetMeshOverlapRule), and the first one of each side are neighbours. A
   * crack face is a boundary face that coincides geometrically with another boundary face
   * without sharing its points (unwelded points, as along the periodic seam of
   * post_tets5_classic). Rays leave the mesh through one and re-enter through the other.
   * Duplicate points are points with exactly the same coordinates as an earlier point.
   */
  vtkSetMacro(NumberOfNonManifoldFaces, vtkIdType);
  vtkGetMacro(NumberOfNonManifoldFaces, vtkIdType);
  vtkSetMacro(NumberOfOverlappingTetrahedra, vtkIdType);
  vtkGetMacro(NumberOfOverlappingTetrahedra, vtkIdType);
  vtkSetMacro(NumberOfCrackFaces, vtkIdType);
  vtkGetMacro(NumberOfCrackFaces, vtkIdType);
  vtkSetMacro(NumberOfDuplicatePoints, vtkIdType);
  vtkGetMacro(NumberOfDuplicatePoints, vtkIdType);
  ///@}

  ///@{
  /**
   * Composite input (a vtkDataObjectTree merged by vtkTetMeshBlockMerger; 0 otherwise): its
   * leaves, the empty ones skipped, and the points merged with an identical point (coordinates
   * and scalar) of an earlier block. Set by the mapper, not by the builder.
   */
  vtkSetMacro(NumberOfBlocks, vtkIdType);
  vtkGetMacro(NumberOfBlocks, vtkIdType);
  vtkSetMacro(NumberOfEmptyBlocks, vtkIdType);
  vtkGetMacro(NumberOfEmptyBlocks, vtkIdType);
  vtkSetMacro(NumberOfSharedPoints, vtkIdType);
  vtkGetMacro(NumberOfSharedPoints, vtkIdType);
  ///@}

  ///@{
  /**
   * Scalar defects: NaN or infinite scalar values (counted per point or per cell, following
   * the scalar mode). Tetrahedra that touch a non-finite value are transparent.
   */
  vtkSetMacro(NumberOfNonFiniteScalars, vtkIdType);
  vtkGetMacro(NumberOfNonFiniteScalars, vtkIdType);
  ///@}

  /**
   * Ids of the input cells whose tetrahedra are degenerate, so users can find them.
   */
  vtkIdTypeArray* GetDegenerateCellIds();

  ///@{
  /**
   * Usability. When the grid cannot be rendered at all (empty grid, no 3D cells, no scalars
   * selected), Usable is false and ErrorMessage says why. SetError() marks the report unusable,
   * ClearError() usable again (the builder, when a rebuild mends what was wrong).
   */
  bool GetUsable() const { return this->ErrorMessage.empty(); }
  void SetError(const std::string& message);
  void ClearError();
  const char* GetErrorMessage() const { return this->ErrorMessage.c_str(); }
  ///@}

  /**
   * True when the builder found anything worth telling the user about: split, ignored or
   * invalid cells, inverted or degenerate tetrahedra, non-manifold or crack faces, duplicate points
   * or non-finite scalars.
   */
  bool HasDefects() const;

  /**
   * True when the input has a problem its user should hear of: ignored or invalid cells,
   * degenerate tetrahedra, non-manifold or crack faces, overlapping tetrahedra, duplicate points
   * or non-finite scalars. Split cells and reoriented (inverted) tetrahedra are normal service:
   * counted, not a problem. The mapper warns (once per build) only when this is true.
   */
  bool HasProblems() const;

  /**
   * HasProblems() but for degenerate tetrahedra and duplicate points, which a mesh cut exactly
   * at planes has wherever a plane passes through or next to its points (what the mapper warns
   * about with vtkTiledRayCastVolumeMapper::WarnAboutDegenerateCells off).
   */
  bool HasProblemsBesidesDegeneracy() const;

  /**
   * A one-paragraph description of the mesh and of every defect found, for messages and logs.
   */
  std::string GetSummary() const;

  /**
   * Copy all counts and messages from another report.
   */
  void DeepCopy(vtkTetMeshValidationReport* other);

protected:
  vtkTetMeshValidationReport();
  ~vtkTetMeshValidationReport() override;

  vtkIdType NumberOfInputPoints = 0;
  vtkIdType NumberOfInputCells = 0;
  vtkIdType NumberOfTetrahedra = 0;
  vtkIdType NumberOfBoundaryFaces = 0;
  vtkIdType NumberOfSplitCells = 0;
  vtkIdType NumberOfIgnoredCells = 0;
  vtkIdType NumberOfInvalidCells = 0;
  vtkIdType NumberOfInvertedTetrahedra = 0;
  vtkIdType NumberOfDegenerateTetrahedra = 0;
  vtkIdType NumberOfNonManifoldFaces = 0;
  vtkIdType NumberOfOverlappingTetrahedra = 0;
  vtkIdType NumberOfCrackFaces = 0;
  vtkIdType NumberOfDuplicatePoints = 0;
  vtkIdType NumberOfNonFiniteScalars = 0;
  vtkIdType NumberOfBlocks = 0;
  vtkIdType NumberOfEmptyBlocks = 0;
  vtkIdType NumberOfSharedPoints = 0;
  vtkSmartPointer<vtkIdTypeArray> DegenerateCellIds;
  std::string ErrorMessage;

private:
  vtkTetMeshValidationReport(const vtkTetMeshValidationReport&) = delete;
  void operator=(const vtkTetMeshValidationReport&) = delete;
};

#endif
