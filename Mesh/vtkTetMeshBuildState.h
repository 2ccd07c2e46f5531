/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkTetMeshBuildState.h

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
/**
 * @class   vtkTetMeshBuildState
 * @brief   private: what vtkTetMeshBuilder's stages share between them and across builds
 *
 * vtkTetMeshBuilder::Build() is a pipeline of stages, one file each, that all work on this one
 * state: vtkTetMeshCellExtraction (points and cells), vtkTetMeshSpatialOrder (Morton order),
 * vtkTetMeshOrientation (signed volumes, degeneracy, flat tetrahedra), vtkTetMeshFaceMatching
 * (neighbours, non-manifold and overlapping faces, boundary faces), vtkTetMeshDefectSearch
 * (duplicate points, cracks) and vtkTetMeshScalarExtraction (scalars, non-finite values).
 *
 * The state holds the mesh being built, what it was built from (so that the next Build() can
 * tell what changed), and the scratch buffers the stages keep between builds. The validation
 * counters are not held here: each stage writes its own straight into the mesh's
 * vtkTetMeshValidationReport, which keeps them across partial rebuilds (a points-only build
 * does not search duplicates and cracks again, so their counts stay those of the last full
 * build).
 */

#ifndef vtkTetMeshBuildState_h
#define vtkTetMeshBuildState_h

#include "vtkNew.h"                // For vtkNew
#include "vtkSMPTools.h"           // For vtkSMPTools::For in ForBlocks
#include "vtkTetMesh.h"            // For vtkTetMesh
#include "vtkTetScalarSelection.h" // For vtkNew<vtkTetScalarSelection>
#include "vtkTimerLog.h"           // For vtkTimerLog in ScopedEvent
#include "vtkType.h"               // For vtkIdType, vtkMTimeType

#include <algorithm> // For std::min, std::max
#include <cstdint>   // For uint32_t
#include <string>    // For std::string
#include <vector>    // For std::vector

class vtkAbstractArray;
class vtkDataSet;
class vtkObject;
class vtkTetMeshValidationReport;

class vtkTetMeshBuildState
{
public:
  vtkTetMeshBuildState();

  vtkNew<vtkTetMesh> Mesh;

  /**
   * The mesh's validation report, where every stage writes its counters.
   */
  vtkTetMeshValidationReport* GetReport();

  /**
   * What identifies one part of the input: the object (compared by address only, never
   * dereferenced), its modification time and its size. Modification times are unique across
   * all VTK objects, so a new object at a recycled address still reads as changed; the size
   * catches cells or values appended without a Modified() call (InsertNextCell does not call
   * it).
   */
  struct Stamp
  {
    const void* Object = nullptr;
    vtkMTimeType MTime = 0;
    vtkIdType Size = 0;
    bool operator==(const Stamp& o) const
    {
      return this->Object == o.Object && this->MTime == o.MTime && this->Size == o.Size;
    }
    bool operator!=(const Stamp& o) const { return !(*this == o); }
  };
  static Stamp MakeStamp(vtkObject* object, vtkIdType size);
  static Stamp MakeStamp(vtkAbstractArray* array);
  /**
   * The stamps of the arrays that hold the input's cells (or of the data set itself where it
   * has no finer detail to go on).
   */
  static void GetTopologyStamps(vtkDataSet* input, std::vector<Stamp>& stamps);
  /**
   * The stamp of the input's explicit points (none for implicit points: they belong to the
   * topology stamp).
   */
  static Stamp GetPointsStamp(vtkDataSet* input);

  // What the mesh was built from.
  bool Valid = false;
  const void* Input = nullptr;
  std::vector<Stamp> TopologyStamps;
  Stamp PointsStamp;
  vtkIdType NumberOfPoints = -1;
  Stamp ScalarsStamp;
  int ScalarsCellFlag = -1;
  // Settings the mesh was built with.
  bool SpatialOrdering = false;
  bool PointOrdering = false;
  double DegeneracyTolerance = 0.0;
  vtkNew<vtkTetScalarSelection> ScalarSettings; // the scalar selection's settings, copied

  // Why the mesh cannot be used, kept across partial rebuilds: a topology error stands until
  // the next full build, a scalar error until the next scalar read.
  std::string TopologyError;
  std::string ScalarError;

  // The scalar values per input cell (cell scalars only), before mapping to tetrahedra.
  vtkTetMeshVector<double> InputCellScalars;

  // Scratch space of the face matching, kept between builds: allocating (and first touching)
  // tens of megabytes anew costs more than the matching itself.
  struct FaceEntry
  {
    // Sorted face of three point ids, for matching: bucketed by the smallest id, keyed by the
    // other two. 12 bytes: the entries of a million tetrahedra take 48 MB, and on a virtual
    // machine first touching fresh pages costs more than sorting them.
    uint32_t Mid;
    uint32_t Hi;
    uint32_t Face; // (t << 2) | i
  };
  vtkTetMeshVector<FaceEntry> FaceEntries;
  vtkTetMeshVector<uint32_t> FaceCounts;
  vtkTetMeshVector<uint64_t> BucketStarts;
  vtkTetMeshVector<uint8_t> FaceSides; // face matching: the parity of each face, 4 bits per tet
  // Likewise for the spatial sort (the permuted arrays are swapped with the mesh's).
  vtkTetMeshVector<uint64_t> SortKeys;
  vtkTetMeshVector<uint64_t> SortScratch;
  vtkTetMeshWords SortTetPoints{ "TetPoints" }; // swapped with the mesh's
  vtkTetMeshVector<uint32_t> SortCellIds;
  // Duplicate points (the search sorts SortKeys too): the canonical id of each point.
  vtkTetMeshVector<uint32_t> Canonical;

  /**
   * Bytes held by the scratch buffers, and freeing them.
   */
  vtkIdType GetScratchSize() const;
  void ReleaseScratch();

  /**
   * Splits [0, n) into `blocks` contiguous ranges processed in parallel, one call of f(block,
   * begin, end) per block. Used where each block needs its own private slice of an output (the
   * counting sorts), which a plain vtkSMPTools::For cannot promise.
   */
  template <typename F>
  static void ForBlocks(vtkIdType n, int blocks, F&& f)
  {
    vtkSMPTools::For(0, blocks, 1,
      [&](vtkIdType b0, vtkIdType b1)
      {
        for (vtkIdType b = b0; b < b1; ++b)
        {
          f(static_cast<int>(b), n * b / blocks, n * (b + 1) / blocks);
        }
      });
  }
  /**
   * How many blocks ForBlocks should cut `work` items into.
   */
  static int NumberOfBlocks(vtkIdType work);

  /**
   * A vtkTimerLog event for the lifetime of the object (a no-op unless logging is on): each
   * stage is one, and the benchmark prints them.
   */
  class ScopedEvent
  {
  public:
    explicit ScopedEvent(const char* name)
      : Name(name)
    {
      vtkTimerLog::MarkStartEvent(name);
    }
    ~ScopedEvent() { vtkTimerLog::MarkEndEvent(this->Name); }
    ScopedEvent(const ScopedEvent&) = delete;
    ScopedEvent& operator=(const ScopedEvent&) = delete;

  private:
    const char* Name;
  };
};

#endif
// VTK-HeaderTest-Exclude: vtkTetMeshBuildState.h
