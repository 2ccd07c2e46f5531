/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkTiledRayCastSharedMemberCode.h

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
/**
 * @class   vtkTiledRayCastSharedMemberCode
 * @brief   one copy of the member code for every volume of a traversal of overlapping volumes
 *
 * Where every volume of a group has the same code (the same layout, texture buffer split,
 * integration, blend mode, lighting and empty-space skipping: copies of a mesh, or meshes alike),
 * the group's traversal need not hold one renamed copy per volume
 * (vtkTiledRayCastGroupTraversal::Rename). A warp whose rays move different volumes then runs
 * one event body instead of one per volume: with n volumes the renamed copies cost up to n
 * bodies an event, n^2 in all.
 *
 * Make() turns one volume's code into the code of all of them, chosen per call by the global
 * `trcMemberIndex`:
 * - each of its uniforms (but the ones the volumes share) becomes an array with one element per
 *   volume, `uniform vec3 in_rayDir0[TRC_GROUP_MEMBERS];`, read as `in_rayDir0[trcMemberIndex]`
 *   (an array that is not opaque may be indexed by any value);
 * - each of its samplers is declared once per volume with the group's suffix (`in_Points_v1`),
 *   since GLSL 4.3 indexes a sampler array only with a dynamically uniform value, and each read
 *   (`texelFetch(in_Points, i)`) goes through a function that reads the volume's own sampler, a
 *   branch per volume around the read alone (a warp whose rays read different volumes issues
 *   one read per volume it holds, not one event body).
 *
 * It refuses code that uses a sampler otherwise than as the first argument of texelFetch,
 * texture or textureLod (the paper layout passes its samplers to functions), or images: the
 * group then keeps the renamed copies.
 *
 * Private to the module: not wrapped, not installed.
 */

#ifndef vtkTiledRayCastSharedMemberCode_h
#define vtkTiledRayCastSharedMemberCode_h

#include <cctype> // For std::isalnum
#include <string> // For std::string
#include <vector> // For std::vector

class vtkTiledRayCastSharedMemberCode
{
public:
  /**
   * `code`, one volume's code, made the code of `count` volumes in `shared` (its first lines
   * define TRC_GROUP_SHARED_CODE and trcMemberIndex). `sharedUniforms` are left as they are
   * (declared once, one value for every volume). `indexed` lists the uniforms made arrays
   * (what vtkTiledRayCastMemberUniforms maps by index). False with the reason in `why` where
   * the code cannot be shared.
   */
  static bool Make(const std::string& code, int count,
    const std::vector<std::string>& sharedUniforms, std::string& shared,
    std::vector<std::string>& indexed, std::string& why);

  /**
   * Whether `c` may be part of a GLSL identifier (or number); the group's renaming reads words
   * with it too.
   */
  static bool IsIdentifierChar(char c)
  {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
  }

  /**
   * The suffix of volume k's samplers ("_v1").
   */
  static std::string Suffix(int k) { return "_v" + std::to_string(k); }
};

#endif
// VTK-HeaderTest-Exclude: vtkTiledRayCastSharedMemberCode.h
