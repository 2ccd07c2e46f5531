/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkTetMesh.h

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
/**
 * @class   vtkTetMesh
 * @brief   a tetrahedral mesh with face adjacency, ready to be packed for the GPU
 *
 * vtkTetMesh is what vtkTetMeshBuilder produces from a vtkDataSet: the points (double precision,
 * input coordinates and input point ids), the tetrahedra (four point ids each, positively
 * oriented), the neighbour across each face, the list of boundary faces, the selected scalar
 * field reduced to one double per point or per tetrahedron, the input cell of every tetrahedron
 * and a vtkTetMeshValidationReport. The conventions are those of docs/design.md:
 *
 * - tetrahedron t has points p0..p3 with det[p1-p0, p2-p0, p3-p0] > 0, unless it is degenerate
 *   (flat to the builder's tolerance, then the sign is rounding noise and left as given);
 * - face i is the face opposite point i, its points in outward (counter-clockwise seen from
 *   outside) order given by GetFacePointIndices();
 * - the neighbour across face i is one word (n << 2) | j, j being the shared face in n, or
 *   vtkTetMesh::NoNeighbor; a boundary face is (t << 2) | i.
 *
 * The mesh is read-only for everyone but its builder. C++ code reads the contiguous arrays
 * through the raw-pointer accessors (not wrapped); Python reads counts, per-tetrahedron queries
 * and copies into VTK arrays (CopyTetPoints() and friends).
 *
 * Three time stamps tell consumers (the GPU layouts) what changed since they last looked:
 * GetTopologyTime() (tetrahedra, neighbours, boundary; implies everything else),
 * GetPointsTime() (positions, bounds, shift) and GetScalarsTime().
 *
 * @sa vtkTetMeshBuilder vtkTetMeshLayout vtkTetMeshValidationReport
 */

#ifndef vtkTetMesh_h
#define vtkTetMesh_h

#include "vtkNew.h" // For vtkNew
#include "vtkObject.h"
#include "vtkTetMeshValidationReport.h" // For vtkNew<vtkTetMeshValidationReport>
#include "vtkTiledRayCastMeshModule.h"  // For export macro
#include "vtkTimeStamp.h"               // For vtkTimeStamp

#include <cmath>   // For std::ldexp, std::ilogb
#include <cstdint> // For uint32_t

#ifndef __VTK_WRAP__
#include "vtkSMPTools.h"                      // For vtkSMPTools::Fill in vtkTetMeshWords
#include "vtkSmartPointer.h"                  // For vtkSmartPointer
#include "vtkTetMeshUninitializedAllocator.h" // For vtkTetMeshVector
#include "vtkTypeUInt32Array.h"               // For vtkTetMeshWords

#include <algorithm> // For std::swap

/**
 * The storage of the mesh's point ids and neighbour words: a vtkTypeUInt32Array of 4
 * components (one tuple per tetrahedron) behind the few std::vector operations the builder's
 * stages use. A layout shares the array object itself instead of copying it (32 bytes a
 * tetrahedron: 32 GB for a billion), and an object it holds always has the mesh's current
 * values or, after swap(), the mesh's former ones; never memory freed under it. Unlike
 * std::vector, resize() leaves new values undefined (every stage writes what it sizes).
 */
class vtkTetMeshWords
{
public:
  explicit vtkTetMeshWords(const char* name)
  {
    this->Array->SetName(name);
    this->Array->SetNumberOfComponents(4);
    this->Sync();
  }
  // The values' address is kept here, not asked of the array at each access: GetPointer() is
  // not inline (a call through the PLT for every word the builder's loops read, and no loop
  // over operator[] could be vectorised).
  uint32_t* data() { return this->Data; }
  const uint32_t* data() const { return this->Data; }
  uint32_t* begin() { return this->data(); }
  uint32_t* end() { return this->data() + this->size(); }
  const uint32_t* begin() const { return this->data(); }
  const uint32_t* end() const { return this->data() + this->size(); }
  size_t size() const { return static_cast<size_t>(this->Array->GetNumberOfValues()); }
  bool empty() const { return this->size() == 0; }
  uint32_t& operator[](size_t i) { return this->data()[i]; }
  uint32_t operator[](size_t i) const { return this->data()[i]; }
  void clear()
  {
    this->Array->SetNumberOfValues(0);
    this->Sync();
  }
  void resize(size_t n)
  {
    this->Array->SetNumberOfValues(static_cast<vtkIdType>(n));
    this->Sync();
    vtkTetMeshHugePages::Advise(this->Data, 4 * n);
  }
  void assign(size_t n, uint32_t value)
  {
    this->resize(n);
    vtkSMPTools::Fill(this->begin(), this->end(), value);
  }
  void reserve(size_t n)
  {
    if (this->empty()) // Allocate() drops the values
    {
      this->Array->Allocate(static_cast<vtkIdType>(n));
      this->Sync();
      vtkTetMeshHugePages::Advise(this->Data, 4 * n);
    }
  }
  /// Bytes allocated, and freeing them.
  size_t capacity_bytes() const { return static_cast<size_t>(this->Array->GetSize()) * 4; }
  void free()
  {
    this->Array->Initialize();
    this->Sync();
  }
  void push_back(uint32_t value)
  {
    this->Array->InsertNextValue(value);
    this->Sync();
  }
  void swap(vtkTetMeshWords& other)
  {
    std::swap(this->Array, other.Array);
    std::swap(this->Data, other.Data);
  }
  /// The array itself (4 components, named), for a layout to share.
  vtkTypeUInt32Array* GetArray() const { return this->Array; }

private:
  void Sync() { this->Data = this->Array->GetPointer(0); }

  vtkSmartPointer<vtkTypeUInt32Array> Array = vtkSmartPointer<vtkTypeUInt32Array>::New();
  uint32_t* Data = nullptr;
};
#endif

class vtkDoubleArray;
class vtkTetMeshBuilder;
class vtkTypeUInt32Array;

class VTKTILEDRAYCASTMESH_EXPORT vtkTetMesh : public vtkObject
{
public:
  static vtkTetMesh* New();
  vtkTypeMacro(vtkTetMesh, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * Per-tetrahedron flags (GetTetFlags()).
   * - Degenerate: zero or negligible volume (see vtkTetMeshBuilder::SetDegeneracyTolerance);
   *   kept in the mesh so that its neighbours stay connected through it.
   * - NonFiniteScalars: touches a NaN or infinite scalar; it is traversed but transparent.
   * - Inverted: was negatively oriented (and not degenerate) in the input and has been
   *   reoriented (p2 <-> p3).
   * - Overlapping: left out of the rendering, because it overlaps an earlier tetrahedron on the
   *   same side of a face they share (vtkTetMeshOverlapRule, docs/mesh-layout.md): it has no
   *   neighbour and none of its faces is a boundary face, so no ray ever enters it.
   */
  enum TetFlag
  {
    Degenerate = 1,
    NonFiniteScalars = 2,
    Inverted = 4,
    Overlapping = 8
  };

  ///@{
  /**
   * Sizes. Points are all the points of the input (unused ones included), so that point ids
   * are the input's.
   */
  vtkIdType GetNumberOfPoints() const { return static_cast<vtkIdType>(this->Points.size() / 3); }
  vtkIdType GetNumberOfTetrahedra() const
  {
    return static_cast<vtkIdType>(this->TetPoints.size() / 4);
  }
  vtkIdType GetNumberOfBoundaryFaces() const
  {
    return static_cast<vtkIdType>(this->BoundaryFaces.size());
  }
  ///@}

  /**
   * True when the scalars are per tetrahedron (cell scalars of the input, one value per
   * tetrahedron after splitting), false when they are per point.
   */
  bool GetHasCellScalars() const { return this->HasCellScalars; }

  /**
   * Range of the finite scalar values; (0, 0) when there is none.
   */
  void GetScalarRange(double range[2]) const;

  ///@{
  /**
   * The GPU layouts store every scalar minus this value, computed in double before the
   * subtraction becomes float, and the mapper shifts its transfer function's nodes by the same:
   * scalars far from zero (1e6 plus a few units) keep the precision of their differences. It is
   * the middle of the scalar range (0 when the range is not finite).
   */
  double GetScalarShift() const { return vtkTetMesh::ComputeScalarShift(this->ScalarRange); }
  static double ComputeScalarShift(const double range[2])
  {
    const double middle = 0.5 * range[0] + 0.5 * range[1];
    return middle - middle == 0.0 ? middle : 0.0; // finite
  }

  /**
   * And multiply them by this power of two (exact), after the shift: 1 unless the range's
   * half-width exceeds 2^32, and then a scale that brings it into [2^31, 2^32). Float holds
   * values up to 3.4e38, but the differences and gradients of scalars spanning +-3e38 overflow
   * it; scaled, they keep float's precision. The transfer function's nodes, the tables' scalar
   * maps, the blend modes' ranges and the gradient-opacity magnitudes are scaled alike.
   */
  double GetScalarScale() const { return vtkTetMesh::ComputeScalarScale(this->ScalarRange); }
  static double ComputeScalarScale(const double range[2])
  {
    const double half = 0.5 * range[1] - 0.5 * range[0];
    if (!(half > 4294967296.0) || half - half != 0.0) // up to 2^32, or not finite
    {
      return 1.0;
    }
    return std::ldexp(1.0, 31 - std::ilogb(half));
  }
  ///@}

  /**
   * Bounds of all points (xmin, xmax, ymin, ymax, zmin, zmax).
   */
  void GetBounds(double bounds[6]) const;

  /**
   * The longest edge of any tetrahedron (its length in the mesh's coordinates): the longest
   * segment a ray can have inside one. Measured by the orientation pass of every build, the
   * points-only ones included (an upper bound where a later stage left tetrahedra out).
   */
  double GetLongestEdge() const { return this->LongestEdge; }

  /**
   * The centre of the bounds. GPU layouts store coordinates relative to it in single
   * precision; scalar gradients and offsets (ComputeScalarGradient()) are also expressed in
   * these shifted coordinates.
   */
  void GetShift(double shift[3]) const;

  /**
   * What the builder found in the input. Never null.
   */
  vtkTetMeshValidationReport* GetReport();

  /**
   * Points of face `face` of any tetrahedron, as indices 0..3 into its four points, in outward
   * order: face 0 = (1,2,3), 1 = (0,3,2), 2 = (0,1,3), 3 = (0,2,1).
   */
  static void GetFacePointIndices(int face, int indices[3]);

  ///@{
  /**
   * Per-tetrahedron queries, bounds-checked (an error and a neutral value for a bad id).
   * GetNeighborTet()/GetNeighborFace() decode the neighbour word: -1 on a boundary face.
   */
  void GetTetPointIds(vtkIdType tet, vtkIdType ids[4]);
  vtkIdType GetNeighborTet(vtkIdType tet, int face);
  int GetNeighborFace(vtkIdType tet, int face);
  vtkIdType GetTetInputCellId(vtkIdType tet);
  int GetTetFlags(vtkIdType tet);
  ///@}

  /**
   * Signed volume of a tetrahedron: positive unless it is degenerate (then it may be zero or
   * tiny of either sign). Computed from the points on each call.
   */
  double ComputeSignedVolume(vtkIdType tet);

  /**
   * The four outward face normals of a tetrahedron (n0.xyz, n1.xyz, n2.xyz, n3.xyz), normal i
   * on face i. With unit false they are the cross products (b-a)x(c-a) of the face's points in
   * outward order, so their length is twice the face area; with unit true they are normalised
   * (a zero-area face gives a zero vector). Computed from the points in double precision.
   */
  void ComputeFaceNormals(vtkIdType tet, double normals[12], bool unit = false);

  /**
   * The linear scalar field of a tetrahedron as s(x) = g . (x - shift) + c, returned as
   * (g.x, g.y, g.z, c), with shift = GetShift(). With cell scalars, or for a degenerate
   * tetrahedron, g = 0 and c is the cell value or the mean of the four point values. Returns
   * false (and g = 0, c = NaN) when the tetrahedron touches a non-finite scalar, or when the
   * mesh has no scalars.
   */
  bool ComputeScalarGradient(vtkIdType tet, double gradientAndOffset[4]);

  ///@{
  /**
   * Copies of the contiguous arrays into VTK arrays (resized here), for Python and tests:
   * tetrahedron points (4 components), neighbour words (4 components), boundary face words
   * (1 component), input cell ids (1 component), points (3 components), and the scalars
   * (1 component, per point or per tetrahedron).
   */
  void CopyTetPoints(vtkTypeUInt32Array* out);
  void CopyTetNeighbors(vtkTypeUInt32Array* out);
  void CopyBoundaryFaces(vtkTypeUInt32Array* out);
  void CopyTetInputCellIds(vtkTypeUInt32Array* out);
  void CopyPoints(vtkDoubleArray* out);
  void CopyScalars(vtkDoubleArray* out);
  ///@}

  ///@{
  /**
   * When the parts of the mesh last changed. A topology change also changes points and
   * scalars; GetMTime() is the latest of the three.
   */
  vtkMTimeType GetTopologyTime() const { return this->TopologyTime.GetMTime(); }
  vtkMTimeType GetPointsTime() const { return this->PointsTime.GetMTime(); }
  vtkMTimeType GetScalarsTime() const { return this->ScalarsTime.GetMTime(); }
  ///@}

  /**
   * Forget everything (an empty mesh); the report is reset too.
   */
  void Initialize();

#ifndef __VTK_WRAP__
  /// The neighbour word of a boundary face.
  static constexpr uint32_t NoNeighbor = 0xFFFFFFFFu;

  /// Face i's points as indices into the tetrahedron's points, outward order.
  static constexpr int FacePoints[4][3] = { { 1, 2, 3 }, { 0, 3, 2 }, { 0, 1, 3 }, { 0, 2, 1 } };

  ///@{
  /**
   * Contiguous storage (C++ only). GetPoints(): xyz per point. GetTetPoints(): 4 point ids per
   * tetrahedron. GetTetNeighbors(): 4 neighbour words per tetrahedron. GetBoundaryFaces(): one
   * word (t << 2) | i per boundary face, ordered by tetrahedron then face. GetPointScalars():
   * one value per point, or null with cell scalars; GetCellScalars(): one value per
   * tetrahedron, or null with point scalars. GetTetInputCellIds(): the input cell of each
   * tetrahedron. GetTetFlags(): TetFlag bits per tetrahedron. Pointers stay valid until the
   * next build changes the corresponding part.
   */
  const double* GetPoints() const
  {
    return this->Points.data();
  }
  const uint32_t* GetTetPoints() const
  {
    return this->TetPoints.data();
  }
  const uint32_t* GetTetNeighbors() const
  {
    return this->TetNeighbors.data();
  }
  /**
   * The arrays behind GetTetPoints() and GetTetNeighbors() (4 components, one tuple per
   * tetrahedron), for a layout to share rather than copy: they hold the mesh's values until
   * the next full build, which may give the mesh other array objects.
   */
  vtkTypeUInt32Array* GetTetPointsArray() const
  {
    return this->TetPoints.GetArray();
  }
  vtkTypeUInt32Array* GetTetNeighborsArray() const
  {
    return this->TetNeighbors.GetArray();
  }
  const uint32_t* GetBoundaryFaces() const
  {
    return this->BoundaryFaces.data();
  }
  const double* GetPointScalars() const
  {
    return this->HasCellScalars || this->PointScalars.empty() ? nullptr : this->PointScalars.data();
  }
  const double* GetCellScalars() const
  {
    return !this->HasCellScalars || this->CellScalars.empty() ? nullptr : this->CellScalars.data();
  }
  const uint32_t* GetTetInputCellIds() const
  {
    return this->TetInputCellIds.data();
  }
  /**
   * The input point of each of the mesh's points, or null when they are the input's points in
   * its order (the builder's PointOrdering off).
   */
  const uint32_t* GetPointInputIds() const
  {
    return this->PointInputIds.empty() ? nullptr : this->PointInputIds.data();
  }
  const uint8_t* GetTetFlags() const
  {
    return this->TetFlags.data();
  }
  ///@}

  /// True when the mesh holds a scalar value per point or per tetrahedron.
  bool HasScalars() const
  {
    return this->HasCellScalars ? !this->CellScalars.empty() : !this->PointScalars.empty();
  }

  ///@{
  /**
   * Unchecked versions of the geometric helpers, for the layouts' inner loops.
   */
  void ComputeFaceNormalsFast(vtkIdType tet, double normals[12], bool unit) const;
  bool ComputeScalarGradientFast(vtkIdType tet, double gradientAndOffset[4]) const;
  double ComputeDeterminantFast(vtkIdType tet) const;
  ///@}
#endif

protected:
  vtkTetMesh();
  ~vtkTetMesh() override;

  bool CheckTet(vtkIdType tet, const char* method);

  // Everything is written by vtkTetMeshBuilder and its stages (vtkTetMeshBuildState.h) only.
  friend class vtkTetMeshBuilder;
  friend class vtkTetMeshCellExtraction;
  friend class vtkTetMeshDefectSearch;
  friend class vtkTetMeshFaceMatching;
  friend class vtkTetMeshOrientation;
  friend class vtkTetMeshScalarExtraction;
  friend class vtkTetMeshSpatialOrder;

#ifndef __VTK_WRAP__
  vtkTetMeshVector<double> Points;
  vtkTetMeshWords TetPoints{ "TetPoints" };
  vtkTetMeshWords TetNeighbors{ "TetNeighbors" };
  vtkTetMeshVector<uint32_t> BoundaryFaces;
  vtkTetMeshVector<uint32_t> TetInputCellIds;
  vtkTetMeshVector<uint32_t> PointInputIds; // empty: the input's points in its order
  vtkTetMeshVector<uint8_t> TetFlags;
  vtkTetMeshVector<double> PointScalars;
  vtkTetMeshVector<double> CellScalars;
#endif
  bool HasCellScalars = false;
  double ScalarRange[2] = { 0.0, 0.0 };
  double Bounds[6] = { 0.0, -1.0, 0.0, -1.0, 0.0, -1.0 };
  double Shift[3] = { 0.0, 0.0, 0.0 };
  double LongestEdge = 0.0;
  vtkNew<vtkTetMeshValidationReport> Report;
  vtkTimeStamp TopologyTime;
  vtkTimeStamp PointsTime;
  vtkTimeStamp ScalarsTime;

private:
  vtkTetMesh(const vtkTetMesh&) = delete;
  void operator=(const vtkTetMesh&) = delete;
};

#endif
