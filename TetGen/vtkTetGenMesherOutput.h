/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkTetGenMesherOutput.h

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
/**
 * @class   vtkTetGenMesherOutput
 * @brief   vtkTetGenMesher's output grid from TetGen's mesh
 *
 * The last step of vtkTetGenMesher::RequestData: the points (the surface's first, in input
 * order, then those TetGen added) in the precision asked for, the tetrahedra positively
 * oriented (checked per tetrahedron, not assumed of TetGen: docs/design.md makes it a promise
 * of every mesh), the region attributes, and the input's point data and original point ids on
 * the surface points (NaN or 0 on the added ones). Private to the module.
 */

#ifndef vtkTetGenMesherOutput_h
#define vtkTetGenMesherOutput_h

#include "vtkType.h" // For vtkIdType

#include <string> // For std::string
#include <vector> // For std::vector

class tetgenio;
class vtkPolyData;
class vtkTetGenMesher;
class vtkUnstructuredGrid;

class vtkTetGenMesherOutput
{
public:
  /**
   * Fill `output` from TetGen's `out` for `mesher`'s settings. `usedPointIds` maps TetGen's
   * surface points to `input`'s, whose coordinates TetGen was given as `coordinates`. False with
   * `error` when TetGen's mesh cannot be used.
   */
  static bool Fill(vtkTetGenMesher* mesher, vtkPolyData* input, const tetgenio& out,
    const std::vector<vtkIdType>& usedPointIds, const std::vector<double>& coordinates,
    vtkUnstructuredGrid* output, std::string& error);

private:
  static void MakeCells(const tetgenio& out, vtkUnstructuredGrid* output);
  static void CopyPointData(
    vtkPolyData* input, const std::vector<vtkIdType>& usedPointIds, vtkUnstructuredGrid* output);
};

#endif
// VTK-HeaderTest-Exclude: vtkTetGenMesherOutput.h
