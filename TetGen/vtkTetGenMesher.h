/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkTetGenMesher.h

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
/**
 * @class   vtkTetGenMesher
 * @brief   fills a closed surface with linear tetrahedra using TetGen
 *
 * The input is a closed, manifold, non-self-intersecting vtkPolyData surface made of
 * polygons and/or triangle strips (vertices and lines are ignored, with a warning). The output
 * is a vtkUnstructuredGrid of linear tetrahedra (VTK_TETRA), every one positively oriented
 * (det[p1-p0, p2-p0, p3-p0] > 0, as docs/design.md asks), that fills the enclosed volume.
 *
 * The filter calls TetGen 1.5 as a library ("tetgen -p" on the surface). The switches mirror
 * TetGen's: Quality (-q, with RadiusEdgeRatio and MinDihedralAngle), MaximumVolume (-a),
 * PreserveSurface (-Y), RegionAttributes (-A), holes and regions (the .poly file's hole and
 * region lists), Quiet (-Q, on by default). GetTetGenSwitches() returns the switch string of
 * the last run: `tetgen -<switches> file` on the same surface gives the same mesh.
 *
 * Input checks, each reported with vtkErrorMacro and an empty output (never a crash or an
 * exit): an empty input; polygons with fewer than three distinct points or with no area
 * (degenerate facets); boundary or non-manifold edges (vtkFeatureEdges; an open surface
 * encloses nothing); self-intersections (found by a TetGen -d pass before meshing, see
 * CheckSelfIntersections); and every error TetGen itself reports (it throws an int in its
 * library build: the code is kept in GetLastTetGenError()). GetErrorCode() is
 * vtkErrorCode::UserError after a failure.
 *
 * Points: the surface's points come first in the output, in input order (only the points used
 * by some facet are passed to TetGen, so an isolated input point is dropped), followed by the
 * points TetGen adds (Steiner points, inside the volume and, unless PreserveSurface is on, on
 * the surface). With PassPointData on, the input point data arrays are copied onto the
 * surface points; the added points get NaN in floating-point arrays and 0 in integer arrays
 * (nothing is interpolated: a NaN scalar makes TiledRayCast's mapper draw the tetrahedra that
 * touch it transparent, which says "no data" honestly). With GenerateOriginalPointIds on, the
 * point array "vtkOriginalPointIds" holds each output point's input id, or -1 for added points.
 * Cell data of the input is not passed (the facets are not tetrahedra). With RegionAttributes
 * on, the cell array "RegionAttribute" holds TetGen's region attribute of every tetrahedron.
 *
 * Progress: TetGen has no progress callback, so UpdateProgress() reports the phases this
 * filter can observe: 0.05 surface assembled, 0.1 surface checked, 0.15 TetGen input packed,
 * 0.85 TetGen done (the meshing itself is one silent step), 0.95 tetrahedra converted, 1.0.
 *
 * @warning TetGen is distributed under the GNU AGPL-3+ (or a commercial licence from WIAS).
 * This class lives in the optional module TiledRayCast::FiltersTetGen so that the rendering
 * module never links TetGen; a program that uses this class links TetGen and must follow its
 * licence. See TetGen/README.md.
 */

#ifndef vtkTetGenMesher_h
#define vtkTetGenMesher_h

#include "vtkFiltersTetGenModule.h" // For export macro
#include "vtkUnstructuredGridAlgorithm.h"

#include <string> // For std::string

class vtkPolyData;

class VTKFILTERSTETGEN_EXPORT vtkTetGenMesher : public vtkUnstructuredGridAlgorithm
{
public:
  static vtkTetGenMesher* New();
  vtkTypeMacro(vtkTetGenMesher, vtkUnstructuredGridAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * Quality meshing (TetGen -q): TetGen adds points until no tetrahedron has a radius-edge
   * ratio above RadiusEdgeRatio (default 2.0, TetGen's own; values near 1.1 may not
   * terminate, values below 1 are clamped) and, when MinDihedralAngle is positive, no
   * dihedral angle below MinDihedralAngle degrees (TetGen's "-q<ratio>/<angle>"). TetGen
   * bounds the ratio only away from small input angles. Off by default.
   */
  vtkSetMacro(Quality, bool);
  vtkGetMacro(Quality, bool);
  vtkBooleanMacro(Quality, bool);
  vtkSetClampMacro(RadiusEdgeRatio, double, 1.0, VTK_DOUBLE_MAX);
  vtkGetMacro(RadiusEdgeRatio, double);
  vtkSetClampMacro(MinDihedralAngle, double, 0.0, 70.0);
  vtkGetMacro(MinDihedralAngle, double);
  ///@}

  ///@{
  /**
   * Maximum tetrahedron volume (TetGen -a<volume>), in the input's units cubed. Zero (the
   * default) imposes none. TetGen meets it for all but a few tetrahedra next to the surface (9
   * of 140,344 on the test torus, at most 23% over), and with PreserveSurface on a coarse
   * surface it may not refine at all.
   */
  vtkSetClampMacro(MaximumVolume, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(MaximumVolume, double);
  ///@}

  ///@{
  /**
   * Keep the input surface as it is (TetGen -Y): no point is added on the surface, so the
   * boundary of the output is exactly the input's triangles (polygons triangulated). Off by
   * default.
   */
  vtkSetMacro(PreserveSurface, bool);
  vtkGetMacro(PreserveSurface, bool);
  vtkBooleanMacro(PreserveSurface, bool);
  ///@}

  ///@{
  /**
   * TetGen treats adjacent facets that meet at a dihedral angle above 179.9 degrees as one
   * planar facet and triangulates it afresh, which moves the boundary by the facets'
   * non-planarity (on the torus of the tests, 5e-10 of the volume with plain -p). Turning this
   * off (TetGen -M) keeps every input facet, so the output fills the input polyhedron to
   * rounding. On by default, as in TetGen.
   */
  vtkSetMacro(MergeCoplanarFacets, bool);
  vtkGetMacro(MergeCoplanarFacets, bool);
  vtkBooleanMacro(MergeCoplanarFacets, bool);
  ///@}

  ///@{
  /**
   * How polygons with more than three points reach TetGen. Off (the default): they are
   * triangulated with vtkTriangleFilter, and every triangle is one TetGen facet, which works
   * for non-planar polygons. On: every polygon is one TetGen facet, as a .poly file gives it,
   * and TetGen triangulates it; the polygon must then be planar. Triangle strips are always
   * split into triangles.
   */
  vtkSetMacro(PolygonsAsFacets, bool);
  vtkGetMacro(PolygonsAsFacets, bool);
  vtkBooleanMacro(PolygonsAsFacets, bool);
  ///@}

  ///@{
  /**
   * Look for self-intersections before meshing (a TetGen -d pass over the surface alone, cheap
   * next to the meshing). On by default: TetGen's meshing stops at the first intersection it
   * meets, but this pass counts the faces involved, for a better message.
   */
  vtkSetMacro(CheckSelfIntersections, bool);
  vtkGetMacro(CheckSelfIntersections, bool);
  vtkBooleanMacro(CheckSelfIntersections, bool);
  ///@}

  ///@{
  /**
   * Holes: points inside cavities that must stay empty (the hole list of a .poly file). TetGen
   * removes every tetrahedron it can reach from a hole point without crossing the surface.
   */
  void AddHole(double x, double y, double z);
  void AddHole(const double x[3]) { this->AddHole(x[0], x[1], x[2]); }
  void RemoveAllHoles();
  int GetNumberOfHoles() const;
  ///@}

  ///@{
  /**
   * Regions (the region list of a .poly file): a point inside a region, the attribute that
   * RegionAttributes gives its tetrahedra, and a maximum tetrahedron volume for that region
   * (zero or less: none besides MaximumVolume).
   */
  void AddRegion(double x, double y, double z, double attribute, double maximumVolume = 0.0);
  void RemoveAllRegions();
  int GetNumberOfRegions() const;
  ///@}

  ///@{
  /**
   * Give every tetrahedron its region's attribute (TetGen -A), in the cell array
   * "RegionAttribute" (double). Regions without a region point are numbered by TetGen. Off by
   * default.
   */
  vtkSetMacro(RegionAttributes, bool);
  vtkGetMacro(RegionAttributes, bool);
  vtkBooleanMacro(RegionAttributes, bool);
  ///@}

  ///@{
  /**
   * Copy the input's point data arrays onto the surface points of the output; points added by
   * TetGen get NaN (floating-point arrays) or 0 (integer arrays). Off by default.
   */
  vtkSetMacro(PassPointData, bool);
  vtkGetMacro(PassPointData, bool);
  vtkBooleanMacro(PassPointData, bool);
  ///@}

  ///@{
  /**
   * Add the point array "vtkOriginalPointIds": the input id of each output point, -1 for
   * points added by TetGen. Off by default.
   */
  vtkSetMacro(GenerateOriginalPointIds, bool);
  vtkGetMacro(GenerateOriginalPointIds, bool);
  vtkBooleanMacro(GenerateOriginalPointIds, bool);
  ///@}

  ///@{
  /**
   * Silence TetGen's progress printing on standard output (TetGen -Q). On by default. TetGen
   * still prints some error messages of its own.
   */
  vtkSetMacro(Quiet, bool);
  vtkGetMacro(Quiet, bool);
  vtkBooleanMacro(Quiet, bool);
  ///@}

  ///@{
  /**
   * Precision of the output points: vtkAlgorithm::DEFAULT_PRECISION (the default) keeps the
   * input points' type, SINGLE_PRECISION gives float, DOUBLE_PRECISION double. TetGen always
   * computes in double precision.
   */
  vtkSetClampMacro(OutputPointsPrecision, int, SINGLE_PRECISION, DEFAULT_PRECISION);
  vtkGetMacro(OutputPointsPrecision, int);
  ///@}

  /**
   * The TetGen switches of the last meshing run (without the leading dash), e.g.
   * "pq1.414a0.00013zJQ"; empty before the first run or when the input was rejected before
   * TetGen ran.
   */
  const char* GetTetGenSwitches() const { return this->TetGenSwitches.c_str(); }

  /**
   * TetGen's error code of the last run, 0 when TetGen succeeded or did not run. TetGen 1.5
   * uses 1 (out of memory), 2 (internal error), 3 (self-intersection), 4 (input feature too
   * small for its tolerance), 5 (two facets too close), 10 (input error).
   */
  vtkGetMacro(LastTetGenError, int);

  /**
   * Number of surface faces that the self-intersection check found intersecting another one
   * in the last run (0 when none or not checked).
   */
  vtkGetMacro(NumberOfIntersectingFaces, vtkIdType);

protected:
  vtkTetGenMesher();
  ~vtkTetGenMesher() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation* request, vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;
  // The steps of RequestData: the input's own checks (an error message, or nothing), TetGen's
  // self-intersection check (idem), and TetGen's switches for the settings.
  std::string CheckInput(vtkPolyData* input);
  std::string FindSelfIntersections();
  std::string MakeSwitches();

  bool Quality = false;
  double RadiusEdgeRatio = 2.0;
  double MinDihedralAngle = 0.0;
  double MaximumVolume = 0.0;
  bool PreserveSurface = false;
  bool MergeCoplanarFacets = true;
  bool PolygonsAsFacets = false;
  bool CheckSelfIntersections = true;
  bool RegionAttributes = false;
  bool PassPointData = false;
  bool GenerateOriginalPointIds = false;
  bool Quiet = true;
  int OutputPointsPrecision = vtkAlgorithm::DEFAULT_PRECISION;

  std::string TetGenSwitches;
  int LastTetGenError = 0;
  vtkIdType NumberOfIntersectingFaces = 0;

private:
  vtkTetGenMesher(const vtkTetGenMesher&) = delete;
  void operator=(const vtkTetGenMesher&) = delete;

  class vtkInternals;
  vtkInternals* Internals;
};

#endif
