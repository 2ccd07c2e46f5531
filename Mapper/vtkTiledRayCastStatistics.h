/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkTiledRayCastStatistics.h

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
/**
 * @class   vtkTiledRayCastStatistics
 * @brief   what vtkTiledRayCastVolumeMapper did in its last render
 *
 * Filled by the mapper at every Render() and readable from C++ and Python through
 * vtkTiledRayCastVolumeMapper::GetStatistics(). The counts describe the last frame; GPU times
 * are the last ones available (this frame's when the mapper's SynchronousStatistics is on, an
 * earlier frame's otherwise, read without stalling the GPU); GPU memory is what the mapper holds
 * now.
 */

#ifndef vtkTiledRayCastStatistics_h
#define vtkTiledRayCastStatistics_h

#include "vtkObject.h"
#include "vtkTiledRayCastMapperModule.h" // For export macro

#include <string> // For std::string
#include <vector> // For std::vector

class VTKTILEDRAYCASTMAPPER_EXPORT vtkTiledRayCastStatistics : public vtkObject
{
public:
  static vtkTiledRayCastStatistics* New();
  vtkTypeMacro(vtkTiledRayCastStatistics, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * Zero every per-frame count (GPU times and memory are kept).
   */
  void ResetFrameCounts();

  ///@{
  /**
   * Whether the last frame drew anything. False when the input could not be rendered (see
   * the mapper's validation report and the error it printed), when nothing was visible, and
   * when the mapper had no input at all (vtkVolume then never calls its Render(): the mapper's
   * Update(), which vtkVolume calls every frame, resets the counts).
   */
  vtkSetMacro(Rendered, bool);
  vtkGetMacro(Rendered, bool);
  ///@}

  ///@{
  /**
   * Whether the last frame copied the scene's depth buffer (what opaque geometry drawn before
   * the volume leaves there, which ends the rays). Skipped when the renderer cleared the depth
   * and draws no prop but volumes: the rays then run to the far plane without a copy.
   */
  vtkSetMacro(SceneDepthCopied, bool);
  vtkGetMacro(SceneDepthCopied, bool);
  ///@}

  ///@{
  /**
   * VTK's dual depth peeling for volumes (vtkRenderer::UseDepthPeelingForVolumes), where the
   * volume takes part in it (the compute pipeline, composite blending): the stage of the last
   * draw (0: outside the peeling; 1: before the first peel, the volume in front of and behind
   * the translucent geometry; 2: a peel, the volume between this peel's fragments and the last
   * one's; 3: the remainder after the last peel), and how many times the peeling has drawn the
   * volume in the renderer's current frame (one traversal each: 1 + peels, + 1 for a
   * remainder), and whether the last draw traversed the entries that the frame's first draw
   * listed, with no entry pass of its own (true in the draws after the first where the context
   * can clear a texture in place: OpenGL 4.4 or GL_ARB_clear_texture).
   */
  vtkSetMacro(DepthPeelingStage, int);
  vtkGetMacro(DepthPeelingStage, int);
  vtkSetMacro(NumberOfDepthPeelingDraws, int);
  vtkGetMacro(NumberOfDepthPeelingDraws, int);
  vtkSetMacro(DepthPeelingEntriesReused, bool);
  vtkGetMacro(DepthPeelingEntriesReused, bool);
  ///@}

  ///@{
  /**
   * Image size of the last render (of its rays: the viewport in pixels divided by the image
   * sample distance it used, vtkTiledRayCastVolumeMapper::SetImageSampleDistance), that
   * distance, and the number of rays that entered the mesh.
   */
  vtkSetVector2Macro(ImageSize, int);
  vtkGetVector2Macro(ImageSize, int);
  vtkSetMacro(ImageSampleDistance, double);
  vtkGetMacro(ImageSampleDistance, double);
  vtkSetMacro(NumberOfRays, vtkIdType);
  vtkGetMacro(NumberOfRays, vtkIdType);
  ///@}

  ///@{
  /**
   * Boundary layers: the first hit counts as layer 1; every depth-peeling pass that found at
   * least one re-entry adds one. NumberOfPeelPasses also counts the last, empty peel that ended
   * peeling. NumberOfNearPlaneRays is the number of rays that started inside the mesh at the
   * near plane (camera inside the mesh).
   */
  vtkSetMacro(NumberOfLayers, int);
  vtkGetMacro(NumberOfLayers, int);
  vtkSetMacro(NumberOfPeelPasses, int);
  vtkGetMacro(NumberOfPeelPasses, int);
  vtkSetMacro(NumberOfNearPlaneRays, vtkIdType);
  vtkGetMacro(NumberOfNearPlaneRays, vtkIdType);
  ///@}

  ///@{
  /**
   * Tiles: how many the viewport was cut into, and how many never ran a ray-casting pass
   * because none of their rays needed one (no mesh under them, or all rays done).
   */
  vtkSetMacro(NumberOfTiles, int);
  vtkGetMacro(NumberOfTiles, int);
  vtkSetMacro(NumberOfTilesSkipped, int);
  vtkGetMacro(NumberOfTilesSkipped, int);
  ///@}

  ///@{
  /**
   * Ray-casting passes: the total over all tiles and layers, and per tile that ran at least
   * one (summed over layers) the minimum, median and maximum. Z-update and occlusion-query
   * passes are counted separately.
   */
  vtkSetMacro(NumberOfRayCastPasses, vtkIdType);
  vtkGetMacro(NumberOfRayCastPasses, vtkIdType);
  vtkSetMacro(MinimumPassesPerTile, int);
  vtkGetMacro(MinimumPassesPerTile, int);
  vtkSetMacro(MedianPassesPerTile, double);
  vtkGetMacro(MedianPassesPerTile, double);
  vtkSetMacro(MaximumPassesPerTile, int);
  vtkGetMacro(MaximumPassesPerTile, int);
  vtkSetMacro(NumberOfZUpdatePasses, vtkIdType);
  vtkGetMacro(NumberOfZUpdatePasses, vtkIdType);
  vtkSetMacro(NumberOfOcclusionQueries, vtkIdType);
  vtkGetMacro(NumberOfOcclusionQueries, vtkIdType);
  ///@}

  ///@{
  /**
   * Which pipeline rendered: "Compute" or "Fragment" (see vtkTiledRayCastVolumeMapper's
   * Pipeline setting).
   */
  vtkSetStringMacro(Pipeline);
  vtkGetStringMacro(Pipeline);
  ///@}

  ///@{
  /**
   * Compute pipeline: the boundary-face crossings listed per pixel (entries; one per ray and
   * boundary layer in front of the opaque depth). In the compute pipeline this count, those
   * below and the
   * numbers of rays, layers and early terminations come from the GPU: they are this frame's
   * when SynchronousStatistics is on, else those of the latest frame whose counts had arrived.
   */
  vtkSetMacro(NumberOfEntries, vtkIdType);
  vtkGetMacro(NumberOfEntries, vtkIdType);
  ///@}

  ///@{
  /**
   * Compute pipeline: rays whose entry list lost entries, so that they missed boundary layers.
   * The list is sized from earlier frames (Render() never waits for this frame's count); a
   * frame it did not hold is drawn again at once when the frame is verified
   * (SynchronousStatistics, the first frame of a mesh or image size, a camera jump), so this is
   * 0 then; on other frames the mapper warns and the list grows for the next frame.
   */
  vtkSetMacro(NumberOfIncompleteRays, vtkIdType);
  vtkGetMacro(NumberOfIncompleteRays, vtkIdType);
  ///@}

  ///@{
  /**
   * Overlapping volumes (docs/mapper.md, "Overlapping volumes"): how many volumes this frame's
   * traversal integrated together (1 for a volume drawn alone; the same count in the statistics
   * of every volume of a group, whose first mapper drew them all), and the rays that met a
   * mixture of two or more of them (compute pipeline, counted as the other ray counts: with a
   * later frame, or at once with SynchronousStatistics; only in the statistics of the mapper
   * that drew the group).
   */
  vtkSetMacro(NumberOfGroupedVolumes, int);
  vtkGetMacro(NumberOfGroupedVolumes, int);
  vtkSetMacro(NumberOfMixedRays, vtkIdType);
  vtkGetMacro(NumberOfMixedRays, vtkIdType);
  ///@}

  ///@{
  /**
   * Whether this frame's traversal of overlapping volumes held one copy of the volumes' code for
   * all of them (three or more volumes of the same layout, integration and lighting: a warp whose
   * rays move different volumes runs one event body) rather than one copy per volume
   * (docs/mapper.md, "Overlapping volumes"). Only in the statistics of the mapper that drew the
   * group; false for a volume drawn alone.
   */
  vtkSetMacro(GroupCodeShared, bool);
  vtkGetMacro(GroupCodeShared, bool);
  vtkBooleanMacro(GroupCodeShared, bool);
  ///@}

  /**
   * Volumes apart (docs/mapper.md, "Volumes apart"): where a renderer holds several sets of this
   * module's volumes (a group of overlapping volumes, or a volume alone), the first of them that
   * VTK draws draws them all, farthest first (inside VTK's depth peeling, in each of its stages,
   * over one another before they reach the pass's targets). The number of sets this mapper's
   * volume drew in depth order in its last draw; 0 where it drew only itself (or its group).
   */
  vtkSetMacro(NumberOfVolumeSetsInDepthOrder, int);
  vtkGetMacro(NumberOfVolumeSetsInDepthOrder, int);

  ///@{
  /**
   * How many times this frame composed the GLSL of the programs it draws with (the mapper's own,
   * or a group's of overlapping volumes, in the statistics of the mapper that drew it) and
   * compared it with the programs built: only when what decides the programs changed (layout,
   * cell scalars, integration, blend mode, shading, empty-space skipping, the volumes of a
   * group), 0 on a steady frame.
   */
  vtkSetMacro(NumberOfShaderCompositions, int);
  vtkGetMacro(NumberOfShaderCompositions, int);
  ///@}

  ///@{
  /**
   * Compute pipeline: the tetrahedra the rays walked: in all, per ray on average and the most
   * of any ray.
   */
  vtkSetMacro(NumberOfSteps, vtkIdType);
  vtkGetMacro(NumberOfSteps, vtkIdType);
  vtkSetMacro(MaximumStepsPerRay, vtkIdType);
  vtkGetMacro(MaximumStepsPerRay, vtkIdType);
  double GetMeanStepsPerRay() const
  {
    return this->NumberOfRays > 0 ? static_cast<double>(this->NumberOfSteps) / this->NumberOfRays
                                  : 0.0;
  }
  ///@}

  ///@{
  /**
   * Rays that stopped because their opacity reached the mapper's early-ray-termination
   * threshold.
   */
  vtkSetMacro(NumberOfRaysTerminatedEarly, vtkIdType);
  vtkGetMacro(NumberOfRaysTerminatedEarly, vtkIdType);
  ///@}

  ///@{
  /**
   * GPU time of each phase in milliseconds (vtkOpenGLRenderTimer), and of the whole render:
   * first hit (with the near-plane pass), depth peeling, ray casting (with Z-update and query
   * passes), compositing. -1 until a measurement is available.
   */
  vtkSetMacro(FirstHitTime, double);
  vtkGetMacro(FirstHitTime, double);
  vtkSetMacro(PeelingTime, double);
  vtkGetMacro(PeelingTime, double);
  vtkSetMacro(RayCastingTime, double);
  vtkGetMacro(RayCastingTime, double);
  vtkSetMacro(CompositingTime, double);
  vtkGetMacro(CompositingTime, double);
  vtkSetMacro(TotalGPUTime, double);
  vtkGetMacro(TotalGPUTime, double);
  ///@}

  /**
   * What the last render rebuilt of the mesh (MeshBuildTime timed it): a combination of
   * MeshRebuildScalars, MeshRebuildPoints (the points moved and the CPU rebuilt them:
   * positions, bounds, orientation and degeneracy), MeshRebuildTopology (the cells changed, or
   * a tetrahedron of a moving mesh turned inside out: everything) and MeshRebuildPointsOnGPU
   * (only the points moved and went straight to the GPU, checked and written there: see
   * vtkTiledRayCastVolumeMapper::PointUpdates), 0 when nothing changed.
   */
  enum MeshRebuildFlags
  {
    MeshRebuildScalars = 1,
    MeshRebuildPoints = 2,
    MeshRebuildTopology = 4,
    MeshRebuildPointsOnGPU = 8
  };
  vtkSetMacro(MeshRebuild, int);
  vtkGetMacro(MeshRebuild, int);

  ///@{
  /**
   * CPU work of the last render, in seconds: rebuilding the mesh layout (0 when nothing
   * changed) and the transfer-function tables, and the whole Render() call.
   */
  vtkSetMacro(MeshBuildTime, double);
  vtkGetMacro(MeshBuildTime, double);
  vtkSetMacro(TransferFunctionBuildTime, double);
  vtkGetMacro(TransferFunctionBuildTime, double);
  vtkSetMacro(RenderTime, double);
  vtkGetMacro(RenderTime, double);
  ///@}

  ///@{
  /**
   * Bytes uploaded to the GPU during the last render (0 when only the camera moved).
   */
  vtkSetMacro(UploadedBytes, vtkIdType);
  vtkGetMacro(UploadedBytes, vtkIdType);
  ///@}

  ///@{
  /**
   * Time the last render spent uploading the mesh layout, in seconds (0 when nothing was
   * uploaded): the CPU's time in the upload calls, which return once the data is copied out of
   * the layout's arrays. The first frame of a large mesh spends it beside MeshBuildTime.
   */
  vtkSetMacro(MeshUploadTime, double);
  vtkGetMacro(MeshUploadTime, double);
  ///@}

  ///@{
  /**
   * GPU memory the mapper holds, in bytes: the mesh (layout textures and boundary faces),
   * the transfer-function textures, the per-pixel render targets, and their sum. Also the
   * mesh's bytes per tetrahedron.
   */
  vtkSetMacro(MeshBytes, vtkIdType);
  vtkGetMacro(MeshBytes, vtkIdType);
  vtkSetMacro(TransferFunctionBytes, vtkIdType);
  vtkGetMacro(TransferFunctionBytes, vtkIdType);
  vtkSetMacro(RenderTargetBytes, vtkIdType);
  vtkGetMacro(RenderTargetBytes, vtkIdType);
  vtkIdType GetTotalGPUBytes() const
  {
    return this->MeshBytes + this->TransferFunctionBytes + this->RenderTargetBytes;
  }
  vtkSetMacro(MeshBytesPerTetrahedron, double);
  vtkGetMacro(MeshBytesPerTetrahedron, double);
  ///@}

  /**
   * How many textures and texture buffers hold the mesh's layout: one per array, more where an
   * array is larger than the GPU's largest texture buffer (GL_MAX_TEXTURE_BUFFER_SIZE, 2^27
   * texels on NVIDIA's GPUs) and is split.
   */
  vtkSetMacro(NumberOfMeshTextures, int);
  vtkGetMacro(NumberOfMeshTextures, int);

  ///@{
  /**
   * The tables in use: the number of piecewise-linear transfer-function nodes the shader
   * splits segments at, and the pre-integration table resolution (0 when no table is used).
   */
  vtkSetMacro(NumberOfTransferFunctionNodes, int);
  vtkGetMacro(NumberOfTransferFunctionNodes, int);
  vtkSetVector3Macro(PreIntegrationTableSize, int);
  vtkGetVector3Macro(PreIntegrationTableSize, int);
  ///@}

  ///@{
  /**
   * The integration mode the last frame used (vtkTiledRayCastVolumeMapper::IntegrationModes:
   * the automatic mode's choice), and the automatic mode's predicted error of that choice in
   * 1/255 (0 for partial pre-integration; -1 when the mode was not automatic).
   */
  vtkSetMacro(IntegrationMode, int);
  vtkGetMacro(IntegrationMode, int);
  vtkSetMacro(PredictedError, double);
  vtkGetMacro(PredictedError, double);
  ///@}

  ///@{
  /**
   * Empty-space skipping (vtkTiledRayCastVolumeMapper::SetEmptySpaceSkipping): the tetrahedra
   * the transfer function leaves visible (all of them when nothing is skipped), and the faces
   * rays enter the mesh by (its boundary faces, or those of its visible part).
   */
  vtkSetMacro(NumberOfVisibleTetrahedra, vtkIdType);
  vtkGetMacro(NumberOfVisibleTetrahedra, vtkIdType);
  vtkSetMacro(NumberOfEntryFaces, vtkIdType);
  vtkGetMacro(NumberOfEntryFaces, vtkIdType);
  ///@}

#ifndef __VTK_WRAP__
  /**
   * Per-tile pass counts of the last render (tiles that ran no pass are left out); the mapper
   * fills this and the min/median/max above are computed from it by FinishTilePasses().
   */
  std::vector<int>& GetPassesPerTile()
  {
    return this->PassesPerTile;
  }
#endif
  void FinishTilePasses();

  /**
   * The statistics as one line of text, for logs and examples.
   */
  std::string GetSummary() const;

protected:
  vtkTiledRayCastStatistics();
  ~vtkTiledRayCastStatistics() override;

  bool Rendered = false;
  bool SceneDepthCopied = false;
  int DepthPeelingStage = 0;
  int NumberOfDepthPeelingDraws = 0;
  bool DepthPeelingEntriesReused = false;
  int ImageSize[2] = { 0, 0 };
  double ImageSampleDistance = 1.0;
  vtkIdType NumberOfRays = 0;
  int NumberOfLayers = 0;
  int NumberOfPeelPasses = 0;
  vtkIdType NumberOfNearPlaneRays = 0;
  int NumberOfTiles = 0;
  int NumberOfTilesSkipped = 0;
  vtkIdType NumberOfRayCastPasses = 0;
  int MinimumPassesPerTile = 0;
  double MedianPassesPerTile = 0;
  int MaximumPassesPerTile = 0;
  vtkIdType NumberOfZUpdatePasses = 0;
  vtkIdType NumberOfOcclusionQueries = 0;
  vtkIdType NumberOfRaysTerminatedEarly = 0;
  char* Pipeline = nullptr;
  vtkIdType NumberOfEntries = 0;
  vtkIdType NumberOfIncompleteRays = 0;
  int NumberOfGroupedVolumes = 0;
  vtkIdType NumberOfMixedRays = 0;
  bool GroupCodeShared = false;
  int NumberOfVolumeSetsInDepthOrder = 0;
  int NumberOfShaderCompositions = 0;
  vtkIdType NumberOfSteps = 0;
  vtkIdType MaximumStepsPerRay = 0;
  int MeshRebuild = 0;
  double FirstHitTime = -1;
  double PeelingTime = -1;
  double RayCastingTime = -1;
  double CompositingTime = -1;
  double TotalGPUTime = -1;
  double MeshBuildTime = 0;
  double TransferFunctionBuildTime = 0;
  double RenderTime = 0;
  vtkIdType UploadedBytes = 0;
  double MeshUploadTime = 0;
  vtkIdType MeshBytes = 0;
  vtkIdType TransferFunctionBytes = 0;
  vtkIdType RenderTargetBytes = 0;
  double MeshBytesPerTetrahedron = 0;
  int NumberOfMeshTextures = 0;
  int NumberOfTransferFunctionNodes = 0;
  int IntegrationMode = 0;
  double PredictedError = -1.0;
  vtkIdType NumberOfVisibleTetrahedra = 0;
  vtkIdType NumberOfEntryFaces = 0;
  int PreIntegrationTableSize[3] = { 0, 0, 0 };
  std::vector<int> PassesPerTile;

private:
  vtkTiledRayCastStatistics(const vtkTiledRayCastStatistics&) = delete;
  void operator=(const vtkTiledRayCastStatistics&) = delete;
};

#endif
