/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkTiledRayCastVolumetricPeel.h

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
/**
 * @class   vtkTiledRayCastVolumetricPeel
 * @brief   which stage of VTK's dual depth peeling is drawing a volume, and its textures
 *
 * With vtkRenderer::UseDepthPeelingForVolumes, vtkDualDepthPeelingPass draws the volumes once
 * before its first peel, once per peel and once for the remainder, and asks each time for the
 * volume between depths it holds in its own textures (vtkTiledRayCastVolumetricPeelRanges.glsl says
 * which). It tells its image ray caster through shader replacements (vtkOpenGLRenderPass's
 * PreReplaceShaderValues) and binds its textures to the sampler names they declare
 * (SetShaderParameters). The compute pipeline takes part through the same public interface:
 * Update() asks the pass for the declarations it would replace //VTK::DepthPeeling::Dec with
 * and reads the stage from the samplers declared (outerDepthTex and innerDepthTex before the
 * peels; with lastFrontColorTex in a peel; depthRangeTex for the remainder), and SetUniforms()
 * has the pass bind its textures to the mapper's programs, which declare the same names.
 *
 * Private to the module: not wrapped, not installed.
 */

#ifndef vtkTiledRayCastVolumetricPeel_h
#define vtkTiledRayCastVolumetricPeel_h

class vtkAbstractVolumeMapper;
class vtkOpenGLRenderPass;
class vtkShaderProgram;
class vtkVolume;

class vtkTiledRayCastVolumetricPeel
{
public:
  enum Stage
  {
    NotPeeling = 0,  // not inside VTK's dual depth peeling
    BeforePeels = 1, // outside the translucent geometry's range, before the first peel
    Peel = 2,        // one peel
    Remainder = 3,   // what the last peel left, alpha blended
    UnknownStage = 4 // inside the peeling, with declarations this class does not know
  };
  // The stages a program is built for (1 to 3).
  static constexpr int NumberOfStages = 3;

  vtkTiledRayCastVolumetricPeel() = default;

  /**
   * The stage of VTK's dual depth peeling drawing `volume` now (NotPeeling when the volume is
   * drawn outside its peels). Valid until the mapper's Render() returns.
   */
  Stage Update(vtkAbstractVolumeMapper* mapper, vtkVolume* volume);
  Stage GetStage() const { return this->CurrentStage; }

  /**
   * The pass binds its textures for this stage to `program`'s samplers (a program built with
   * TRC_PEEL_STAGE defined as the stage).
   */
  void SetUniforms(vtkShaderProgram* program) const;

  /**
   * VTK's dual depth peeling pass among the volume's render passes (nullptr outside its peels).
   */
  static vtkOpenGLRenderPass* FindPass(vtkVolume* volume);

private:
  vtkTiledRayCastVolumetricPeel(const vtkTiledRayCastVolumetricPeel&) = delete;
  void operator=(const vtkTiledRayCastVolumetricPeel&) = delete;

  Stage CurrentStage = NotPeeling;
  vtkOpenGLRenderPass* Pass = nullptr;
  vtkAbstractVolumeMapper* Mapper = nullptr;
  vtkVolume* Volume = nullptr;
};

#endif
// VTK-HeaderTest-Exclude: vtkTiledRayCastVolumetricPeel.h
