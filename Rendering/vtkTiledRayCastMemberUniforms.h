/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkTiledRayCastMemberUniforms.h

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
/**
 * @class   vtkTiledRayCastMemberUniforms
 * @brief   one volume's uniforms of the traversal of overlapping volumes, by their plain names
 *
 * The traversal of overlapping volumes (vtkTiledRayCastGroupPrograms) holds every volume's
 * code with a suffix per volume: volume 1's mesh is in_Points_1, its rays in_rayOrigin0_1. This
 * program stands for volume k of such a program: a uniform set through it by its plain name
 * (SetUniformi("in_Points", ...)) goes to that name with the suffix, so each volume's mapper
 * sets its uniforms on the group's program with the setters it uses on its own programs.
 *
 * It shares the group program's GL handle and never owns it: Map() fills vtkShaderProgram's
 * cache of uniform locations (the plain name to the location of the suffixed one) from the
 * program's active uniforms; vtkShaderProgram's setters look there first and set the value on
 * the program in use (glUniform*), which is the group's program while it is used.
 *
 * Private to the module: not wrapped, not installed.
 */

#ifndef vtkTiledRayCastMemberUniforms_h
#define vtkTiledRayCastMemberUniforms_h

#include "vtkShaderProgram.h"

#include <string> // For std::string
#include <vector> // For std::vector

class vtkTiledRayCastMemberUniforms : public vtkShaderProgram
{
public:
  static vtkTiledRayCastMemberUniforms* New();
  vtkTypeMacro(vtkTiledRayCastMemberUniforms, vtkShaderProgram);

  /**
   * Stand for the uniforms of `program` whose names end with `suffix` (before any "[0]"), and
   * for those named in `plain` as they are (uniforms the volumes share, which this volume sets).
   * Plain names that have no suffixed uniform, and the `shared` ones (which the group sets
   * itself), are not set: the setters return false without a GL call.
   *
   * Where the volumes share one copy of their code (vtkTiledRayCastSharedMemberCode), the
   * uniforms named in `indexed` are arrays with one element per volume: this volume's is
   * element `index` (of an array of arrays, its inner array), and never another's.
   */
  void Map(vtkShaderProgram* program, const std::string& suffix,
    const std::vector<std::string>& shared = std::vector<std::string>(),
    const std::vector<std::string>& plain = std::vector<std::string>(),
    const std::vector<std::string>& indexed = std::vector<std::string>(), int index = -1);

  /**
   * Forget the program (it is being rebuilt or released).
   */
  void Unmap();

protected:
  vtkTiledRayCastMemberUniforms();
  ~vtkTiledRayCastMemberUniforms() override;

private:
  vtkTiledRayCastMemberUniforms(const vtkTiledRayCastMemberUniforms&) = delete;
  void operator=(const vtkTiledRayCastMemberUniforms&) = delete;
};

#endif
// VTK-HeaderTest-Exclude: vtkTiledRayCastMemberUniforms.h
