/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkTetMeshBuilder.h

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
/**
 * @class   vtkTetMeshBuilder
 * @brief   builds a vtkTetMesh (tetrahedra, face adjacency, scalars, report) from a vtkDataSet
 *
 * Usage: set the scalar selection (GetScalarSelection(): the settings of a volume mapper, so
 * that a mapper hands its own along with vtkTetScalarSelection::CopySettings()), then call
 * Build(input) whenever the input may have changed. Build()
 * returns the builder's mesh (always the same object, never null) and does only the work that
 * the change requires:
 *
 * - nothing when neither the input nor the settings changed;
 * - points only (positions, bounds and shift, orientation and degeneracy checks) when only the
 *   point coordinates changed, as for a deforming mesh whose topology is fixed. Should a
 *   tetrahedron turn inside out (or a reoriented one become flat), the builder falls back to a
 *   full build, so the result always equals a full build of the moved mesh (tetrahedra in the
 *   order of the last full build). Duplicate points and cracks are not searched again on this
 *   path: their counts are those of the last full build;
 * - scalars only when only the scalar array (or the scalar settings) changed;
 * - everything when the cells, the number of points, the input object or a topology setting
 *   (SpatialOrdering, DegeneracyTolerance) changed.
 *
 * Progress: a Build() that rebuilds anything invokes vtkCommand::ProgressEvent, as
 * vtkAlgorithm::UpdateProgress does (call data: a double* fraction), at 0, after each phase of a
 * full build (weighted by the time the phase takes), and at 1 when it is done; a Build() that
 * finds nothing changed invokes none.
 *
 * GetLastRebuild() says what the last Build() did. Changes are detected from the modification
 * times of the arrays that hold each part (points, cell connectivity, offsets and types, the
 * selected scalar array) and from the setting values, so an array modified in place must be
 * marked Modified(), as everywhere in VTK.
 *
 * Input: a vtkUnstructuredGrid is read directly. Linear tetrahedra pass through; every other 3D
 * cell (hexahedron, wedge, pyramid, voxel, polyhedron, quadratic and higher-order cells) is
 * split into tetrahedra by vtkDataSetTriangleFilter, whose ordered triangulator splits a face
 * shared by two cells the same way in both (it orders by global point id), so the split is
 * conforming; one warning per build says how many cells were split. Cells of lower dimension
 * are ignored with one warning. Any other vtkDataSet (image data, structured or rectilinear
 * grids, vtkUnstructuredGridBase implementations) goes through the same split, cell by cell.
 * An empty input, an input without 3D cells or without the selected scalars is reported
 * unusable (an error, and GetReport()->GetUsable() false); nothing crashes.
 *
 * Scalars: chosen by the scalar selection (vtkTetScalarSelection: ScalarMode, ArrayAccessMode,
 * ArrayId, ArrayName, as vtkAbstractMapper::GetScalars); any numeric type; a multi-component
 * array is reduced to one component (VectorMode COMPONENT, the builder's default, with
 * VectorComponent) or to its magnitude (VectorMode MAGNITUDE). The builder sees no volume
 * property: VectorMode DEFAULT takes component 0, and a mapper resolves its selection with the
 * property first (vtkTetScalarSelection::SetVectorModeToResolved()).
 *
 * Validation (into the mesh's vtkTetMeshValidationReport): inverted tetrahedra (reoriented),
 * degenerate tetrahedra (6|V| <= DegeneracyTolerance * longest edge^3; kept, never
 * reoriented: the sign of a zero volume is noise), non-manifold faces
 * (more than two tetrahedra on one face) and overlapping tetrahedra (two on the same side of a
 * shared face: all but the first in input order on each side are left out, flagged
 * vtkTetMesh::Overlapping, see vtkTetMeshOverlapRule; decided at full builds only, like
 * duplicates and cracks), crack faces (boundary faces that overlap, in the same plane and facing
 * the other way, a boundary face made of coincident but distinct points), NaN/Inf scalars (their
 * tetrahedra flagged transparent) and duplicate points (exactly equal coordinates).
 *
 * Work is spread over threads with vtkSMPTools. Face matching buckets the faces by their
 * smallest point id with a parallel counting sort (no map of faces) and pairs the faces of
 * each small bucket through a small open-addressing table keyed by their two other ids.
 *
 * SpatialOrdering (off by default) sorts the tetrahedra along a Morton (Z-order) curve of their
 * centroids, so that tetrahedra close in space are close in memory; GetTetInputCellIds() maps
 * them back to the input cells. See docs/mesh-layout.md for what it costs.
 *
 * @sa vtkTetMesh vtkTetMeshValidationReport vtkTetMeshLayout
 */

#ifndef vtkTetMeshBuilder_h
#define vtkTetMeshBuilder_h

#include "vtkNew.h" // For vtkNew
#include "vtkObject.h"
#include "vtkTetScalarSelection.h"     // For vtkNew<vtkTetScalarSelection>
#include "vtkTiledRayCastMeshModule.h" // For export macro

#include <memory> // For std::unique_ptr
#include <string> // For std::string

class vtkDataArray;
class vtkDataSet;
class vtkTetMesh;
class vtkTetMeshBuildState;

class VTKTILEDRAYCASTMESH_EXPORT vtkTetMeshBuilder : public vtkObject
{
public:
  static vtkTetMeshBuilder* New();
  vtkTypeMacro(vtkTetMeshBuilder, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * What the last Build() rebuilt: a combination of these bits. RebuildAll = all three.
   */
  enum RebuildFlags
  {
    RebuildNothing = 0,
    RebuildScalars = 1,
    RebuildPoints = 2,
    RebuildTopology = 4,
    RebuildAll = 7
  };

  /**
   * Which scalars to read and how a multi-component array becomes one value (see above).
   * Defaults: VTK_SCALAR_MODE_DEFAULT (point scalars, else cell scalars), VectorMode COMPONENT,
   * component 0. Never null; a change to it is seen at the next Build().
   */
  vtkTetScalarSelection* GetScalarSelection() { return this->ScalarSelection; }

  ///@{
  /**
   * Sort the tetrahedra along a Morton curve of their centroids (default off).
   */
  vtkSetMacro(SpatialOrdering, bool);
  vtkGetMacro(SpatialOrdering, bool);
  vtkBooleanMacro(SpatialOrdering, bool);
  ///@}

  ///@{
  /**
   * Renumber the points along a Morton curve of their positions (default off): the mesh's point
   * ids are then not the input's, GetPointInputIds() maps them back. A tetrahedron's four points
   * then lie close in memory, which decides the GPU's frame on huge meshes read in another order
   * (docs/benchmarks.md: a billion tetrahedra 11 times faster).
   */
  vtkSetMacro(PointOrdering, bool);
  vtkGetMacro(PointOrdering, bool);
  vtkBooleanMacro(PointOrdering, bool);
  ///@}

  ///@{
  /**
   * A tetrahedron is degenerate when 6|V| <= DegeneracyTolerance * L^3, L its longest edge
   * (6|V|/L^3 is 0.707 for a regular tetrahedron). Default 1e-12: exactly flat tetrahedra and
   * those flat to rounding. Real meshes hold valid needle-shaped cells far below 1e-6 (the blunt
   * fin's boundary layer reaches 1.7e-7), so raise it with care.
   */
  vtkSetClampMacro(DegeneracyTolerance, double, 0.0, 1.0);
  vtkGetMacro(DegeneracyTolerance, double);
  ///@}

  /**
   * What Build(input) would rebuild now (RebuildFlags), without doing it: RebuildAll when the
   * cells, the point count or a setting changed (or nothing was built yet). A renderer that moves
   * a deforming mesh's points by other means (on the GPU) asks this to know that only the
   * points moved; Build() catches up with them later.
   */
  int GetPendingRebuild(vtkDataSet* input);

  /**
   * Bring the mesh up to date with `input` and the settings, doing only what changed (see
   * above), and return it. Never null; check GetMesh()->GetReport()->GetUsable().
   */
  vtkTetMesh* Build(vtkDataSet* input);

  /**
   * The mesh (the same object across builds).
   */
  vtkTetMesh* GetMesh();

  /**
   * Forget what was built: the next Build() is a full one.
   */
  void Invalidate();

  ///@{
  /**
   * The builder keeps its scratch buffers (face matching, spatial sort, duplicate search:
   * about 61 bytes per tetrahedron, 96 with spatial ordering) between builds, because allocating
   * and first touching fresh memory costs more than the work done in it. ReleaseScratchMemory()
   * frees them (a mapper may call it once the mesh is built, when topology changes are rare);
   * GetScratchMemorySize() says how many bytes they hold.
   *
   * Above MaximumKeptScratchMemory bytes (default 2^31: meshes of about 20M tetrahedra and more)
   * they are not kept: each stage frees its own when it ends, so that the stages' scratch does
   * not add up at the peak of a huge build (a spatially ordered build of 300M tetrahedra held
   * 29 GB of scratch, 96 bytes a tetrahedron, on top of the mesh and the layout).
   */
  void ReleaseScratchMemory();
  vtkIdType GetScratchMemorySize();
  vtkSetClampMacro(MaximumKeptScratchMemory, vtkIdType, 0, VTK_ID_MAX);
  vtkGetMacro(MaximumKeptScratchMemory, vtkIdType);
  ///@}

  ///@{
  /**
   * What the last Build() did (RebuildFlags bits) and how long it took (seconds, wall clock).
   */
  vtkGetMacro(LastRebuild, int);
  static const char* GetRebuildAsString(int rebuild);
  vtkGetMacro(LastBuildTime, double);
  ///@}

protected:
  vtkTetMeshBuilder();
  ~vtkTetMeshBuilder() override;

  vtkNew<vtkTetScalarSelection> ScalarSelection;
  bool SpatialOrdering = false;
  bool PointOrdering = false;
  double DegeneracyTolerance = 1e-12;
  vtkIdType MaximumKeptScratchMemory = vtkIdType(1) << 31;

  int LastRebuild = RebuildNothing;
  double LastBuildTime = 0.0;

private:
  vtkTetMeshBuilder(const vtkTetMeshBuilder&) = delete;
  void operator=(const vtkTetMeshBuilder&) = delete;

  // The stages of Build(), in the order they run (each a private class of its own over the
  // one build state: see vtkTetMeshBuildState.h).
  bool UpdatePoints(vtkDataSet* input);
  void BuildTopology(vtkDataSet* input);
  bool ExtractCells(vtkDataSet* input, std::string& error);
  void RunTopologyStages();
  void UpdateScalars(vtkDataSet* input);
  void FinishReport(vtkDataSet* input);

  std::unique_ptr<vtkTetMeshBuildState> State;
};

#endif
