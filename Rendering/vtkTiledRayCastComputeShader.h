/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkTiledRayCastComputeShader.h

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
/**
 * @class   vtkTiledRayCastComputeShader
 * @brief   an OpenGL 4.3 compute program that is a vtkShaderProgram for its uniforms
 *
 * VTK 9.1's vtkShaderProgram and shader cache build vertex, fragment and geometry shaders only.
 * This class compiles and links one compute shader itself and then serves as any
 * vtkShaderProgram for uniforms (SetUniformi, SetUniform3f, SetUniformMatrix4x4, ...), so that
 * the mapper sets the same uniforms the same way on its raster programs and on its compute
 * program. It also holds the few raw GL calls the compute pipeline needs and VTK has no class
 * for: image-unit and storage-buffer bindings, dispatches and memory barriers. Like
 * vtkTiledRayCastOcclusionQueries, it keeps raw GL in one place.
 *
 * Needs a current OpenGL 4.3 context. Private to the module: not wrapped, not installed.
 */

#ifndef vtkTiledRayCastComputeShader_h
#define vtkTiledRayCastComputeShader_h

#include "vtkShaderProgram.h"

#include <string> // For std::string

class vtkOpenGLRenderWindow;
class vtkTextureObject;

class vtkTiledRayCastComputeShader : public vtkShaderProgram
{
public:
  static vtkTiledRayCastComputeShader* New();
  vtkTypeMacro(vtkTiledRayCastComputeShader, vtkShaderProgram);

  /**
   * Whether a context has what the compute pipeline needs: OpenGL 4.3 (compute shaders,
   * shader storage buffers, image load and store).
   */
  static bool IsSupported(vtkOpenGLRenderWindow* window);

  /**
   * Compile and link the source (the context must be current). On failure, returns false and
   * GetError() holds the compiler's or linker's log.
   */
  bool Build(const std::string& source);

  /**
   * The source it was built from (to rebuild only when it changes).
   */
  const std::string& GetSource() const { return this->Source; }

  /**
   * Make it the current program. VTK's shader cache forgets the program it had bound, so that
   * its next ReadyShaderProgram() binds again.
   */
  void Use(vtkOpenGLRenderWindow* window);

  /**
   * Run groupsX by groupsY workgroups.
   */
  void Dispatch(unsigned int groupsX, unsigned int groupsY);

  /**
   * Delete the GL program (the context must be current).
   */
  void ReleaseProgram();

  ///@{
  /**
   * Raw GL of the compute pipeline, in one place: bind level 0 of a texture to an image unit
   * (access: GL_READ_ONLY, GL_WRITE_ONLY or GL_READ_WRITE; format: the image's internal
   * format), unbind an image unit, and order shader writes before what reads them next
   * (glMemoryBarrier bits).
   */
  static void BindImage(
    unsigned int unit, vtkTextureObject* texture, unsigned int access, unsigned int format);
  static void UnbindImage(unsigned int unit);
  static void Barrier(unsigned int bits);
  ///@}

  /**
   * Turn GL_DEPTH_CLAMP on or off (vtkOpenGLState does not track it), returning whether it was
   * on. The passes over the boundary faces draw with it, so that no face is clipped at the
   * near plane: their fragment shader decides there (vtkTiledRayCastBoundaryFaceFS.glsl).
   */
  static bool SetDepthClamp(bool on);

  ///@{
  /**
   * Whether this context can zero a texture in place (OpenGL 4.4 or GL_ARB_clear_texture), and
   * zero level 0 of an unsigned-integer texture (glClearTexImage).
   */
  static bool CanClearImages();
  static void ClearImage(vtkTextureObject* texture);
  ///@}

protected:
  vtkTiledRayCastComputeShader();
  ~vtkTiledRayCastComputeShader() override;

  std::string Source;

private:
  vtkTiledRayCastComputeShader(const vtkTiledRayCastComputeShader&) = delete;
  void operator=(const vtkTiledRayCastComputeShader&) = delete;
};

#endif
