/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkTiledRayCastUniforms.h

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
/**
 * @class   vtkTiledRayCastUniforms
 * @brief   the uniforms both pipelines' programs read, from the mapper's parts of this frame
 *
 * The mapper's internals hand the pipelines a vtkTiledRayCastProgramSetup; its setters forward
 * here. Every setter reads the parts as they are when it is called (the frame's geometry,
 * lighting and image size are recomputed before the passes run), so one object serves every
 * frame: Parts holds pointers to the mapper's own members, which outlive it.
 *
 * No OpenGL objects of its own. Private to the module: not wrapped, not installed.
 */

#ifndef vtkTiledRayCastUniforms_h
#define vtkTiledRayCastUniforms_h

class vtkShaderProgram;
class vtkTiledRayCastFrameGeometry;
class vtkTiledRayCastGradientOpacityNodes;
class vtkTiledRayCastIntegration;
class vtkTiledRayCastLighting;
class vtkTiledRayCastMeshBuild;
class vtkTiledRayCastMeshTextures;
class vtkTiledRayCastOpaqueDepth;
class vtkTiledRayCastVisibleMesh;
class vtkTiledRayCastVolumeMapper;

class vtkTiledRayCastUniforms
{
public:
  /**
   * What the uniforms are set from: the mapper's members (none may be null).
   */
  struct Parts
  {
    vtkTiledRayCastVolumeMapper* Mapper = nullptr; // blend mode, early termination
    const vtkTiledRayCastFrameGeometry* Geometry = nullptr;
    const int* ImageSize = nullptr; // the rays along x and y
    const int* Viewport = nullptr;  // origin and size of the caller's viewport
    vtkTiledRayCastOpaqueDepth* OpaqueDepth = nullptr;
    vtkTiledRayCastMeshBuild* Mesh = nullptr;
    vtkTiledRayCastMeshTextures* MeshTextures = nullptr;
    vtkTiledRayCastVisibleMesh* VisibleMesh = nullptr;
    vtkTiledRayCastIntegration* Integration = nullptr;
    const vtkTiledRayCastLighting* Lighting = nullptr;
    const vtkTiledRayCastGradientOpacityNodes* GradientOpacity = nullptr;
  };

  explicit vtkTiledRayCastUniforms(const Parts& parts)
    : Part(parts)
  {
  }

  // Rays, clipping, the opaque depth and early termination.
  void SetFrameUniforms(vtkShaderProgram* program);
  // The layout's textures, the faces rays enter by and the visible bits.
  void SetMeshUniforms(vtkShaderProgram* program);
  // Uniforms of the boundary-face passes: exact coverage of pixel centres (see the vertex shader).
  void SetCoverageUniforms(vtkShaderProgram* program);
  // The integration mode's tables or nodes, with blending and shading where they apply.
  void SetIntegrationUniforms(vtkShaderProgram* program);
  // Compositing: rays per viewport pixel along x and y (1 at an image sample distance of 1).
  void SetSampleScaleUniforms(vtkShaderProgram* program);

private:
  void SetBlendUniforms(vtkShaderProgram* program);
  void SetShadingUniforms(vtkShaderProgram* program);

  Parts Part;
};

#endif
// VTK-HeaderTest-Exclude: vtkTiledRayCastUniforms.h
