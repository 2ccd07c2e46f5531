/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkTiledRayCastPreIntegrationTable.h

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
/**
 * @class   vtkTiledRayCastPreIntegrationTable
 * @brief   pre-integrated segment colours for the table-driven integration modes
 *
 * The colour and opacity of a ray segment as a function of its front scalar, back scalar and
 * (3D) world length, or of its two scalars for one reference length (2D), as in Bernardon et al.
 * (2004) after Engel et al. (2001). Every entry is computed with the exact segment integrator
 * (vtkTetRayIntegrator), in parallel; the GPU interpolates between entries, which is where the
 * error of these modes comes from.
 *
 * An entry holds the segment's mean colour, the premultiplied colour divided by alpha, and its
 * optical depth per unit length E (alpha = 1 - exp(-E L) for a segment of length L), not the
 * premultiplied colour and alpha themselves. E is the same at every length for given scalars
 * (D = L Int_0^1 tau(sf + (sb - sf) u) du), so it is exact along the length axis and for every
 * segment shorter than the table's first length, and it does not saturate where alpha does (a
 * near-opaque segment's alpha is 1 to float precision at every length but the shortest:
 * interpolated alpha was up to 89/255 off on meshes of near-opaque tets, and the 2D table's
 * opacity correction, which read D back from alpha, 181/255). It is not capped where alpha is 1
 * either: the optical depth itself, capped at 80 as it once was, made a segment shorter than
 * 1/80 of the table's first length (a ray grazing the mesh's silhouette) up to 206/255 too
 * transparent under a ScalarOpacityUnitDistance of 1e-12 (issue 28). Where alpha is 0 the mean
 * colour is its limit for short segments (the colour function at the middle of the scalars where
 * the opacity is 0 throughout).
 *
 * The resolution along the scalar axes follows the transfer function unless set: grid points
 * at most half the narrowest transfer-function feature apart over the data's scalar range,
 * within [32, 256] for 3D and [32, 1024] for 2D and the GPU's texture size. The length axis
 * (3D) has 64 entries by default, from 0 to the longest segment possible (the longest edge of
 * the mesh in world units). Rebuilt by Update() only when something it depends on changed.
 */

#ifndef vtkTiledRayCastPreIntegrationTable_h
#define vtkTiledRayCastPreIntegrationTable_h

#include "vtkObject.h"
#include "vtkRenderingTiledRayCastModule.h" // For export macro

#include <vector> // For std::vector

class vtkTetRayIntegrator;
class vtkTiledRayCastTransferFunction;
class vtkVolumeProperty;

class VTKRENDERINGTILEDRAYCAST_EXPORT vtkTiledRayCastPreIntegrationTable : public vtkObject
{
public:
  static vtkTiledRayCastPreIntegrationTable* New();
  vtkTypeMacro(vtkTiledRayCastPreIntegrationTable, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * 3 for a (front, back, length) table, 2 for a (front, back) table at ReferenceLength.
   */
  vtkSetClampMacro(Dimension, int, 2, 3);
  vtkGetMacro(Dimension, int);
  ///@}

  ///@{
  /**
   * Seconds a build may take (default 5). A few entries are integrated and timed first; where
   * the whole table would take longer (a transfer function with a feature far narrower than a
   * table can hold, such as a 1e-6-wide opacity spike, makes every entry across it an adaptive
   * integral), its scalar resolution is lowered to fit, never below 32, and
   * GetReducedFromScalarSize() says from what (0 when not reduced), for the mapper to say so.
   */
  vtkSetClampMacro(BuildTimeBudget, double, 0.01, VTK_DOUBLE_MAX);
  vtkGetMacro(BuildTimeBudget, double);
  vtkGetMacro(ReducedFromScalarSize, int);
  ///@}

  ///@{
  /**
   * Requested resolutions (0: automatic) and the largest texture side the GPU accepts.
   */
  vtkSetClampMacro(RequestedScalarSize, int, 0, 4096);
  vtkGetMacro(RequestedScalarSize, int);
  vtkSetClampMacro(RequestedLengthSize, int, 0, 1024);
  vtkGetMacro(RequestedLengthSize, int);
  vtkSetClampMacro(MaximumSize, int, 2, VTK_INT_MAX);
  vtkGetMacro(MaximumSize, int);
  ///@}

  ///@{
  /**
   * World lengths: the longest segment a ray can have in one tetrahedron (3D), and the length
   * of the 2D table.
   */
  vtkSetMacro(MaximumLength, double);
  vtkGetMacro(MaximumLength, double);
  vtkSetMacro(ReferenceLength, double);
  vtkGetMacro(ReferenceLength, double);
  ///@}

  /**
   * Recompute the table if the property, the transfer function, the scalar range or a setting
   * changed. Returns false (with an error) when the property cannot be integrated.
   */
  bool Update(vtkVolumeProperty* property, vtkTiledRayCastTransferFunction* transferFunction,
    const double scalarRange[2]);

  /**
   * Resolution: scalar (front), scalar (back), length (1 for 2D).
   */
  void GetSize(int size[3]) const;

  /**
   * The scalar range the grid spans (grid point i at min + i (max - min) / (size - 1)).
   */
  void GetScalarRange(double range[2]) const;

#ifndef __VTK_WRAP__
  /**
   * The table, (mean r, g, b, optical depth) float, front scalar fastest, then back scalar,
   * then length.
   */
  float* GetTable()
  {
    return this->Table.data();
  }
#endif

  /**
   * Mean colour and optical depth of table entry (front, back, length) (for tests).
   */
  void GetEntry(int front, int back, int length, double rgba[4]) const;

  vtkIdType GetNumberOfBytes() const
  {
    return static_cast<vtkIdType>(this->Table.size() * sizeof(float));
  }

protected:
  vtkTiledRayCastPreIntegrationTable();
  ~vtkTiledRayCastPreIntegrationTable() override;

  int Dimension = 3;
  int RequestedScalarSize = 0;
  int RequestedLengthSize = 0;
  int MaximumSize = 2048;
  double MaximumLength = 1.0;
  // The scalar size whose build fits the budget (at most size[0]).
  int FitBudget(
    vtkTetRayIntegrator* integrator, const int size[3], const double scalarRange[2]) const;

  double BuildTimeBudget = 5.0;
  int Planned[3] = { 0, 0, 0 }; // the size before the budget, which a rebuild compares
  int ReducedFromScalarSize = 0;
  double ReferenceLength = 1.0;
  int Size[3] = { 0, 0, 0 };
  double Range[2] = { 0, 1 };
  std::vector<float> Table;
  vtkMTimeType BuiltFrom = 0;
  vtkMTimeType BuiltTime = 0;

private:
  vtkTiledRayCastPreIntegrationTable(const vtkTiledRayCastPreIntegrationTable&) = delete;
  void operator=(const vtkTiledRayCastPreIntegrationTable&) = delete;
};

#endif
