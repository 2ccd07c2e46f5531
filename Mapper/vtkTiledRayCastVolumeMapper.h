/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkTiledRayCastVolumeMapper.h

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
/**
 * @class   vtkTiledRayCastVolumeMapper
 * @brief   GPU volume rendering of tetrahedral meshes: tiled ray casting with depth peeling
 *
 * A drop-in vtkUnstructuredGridVolumeMapper that renders a vtkUnstructuredGrid (or a composite
 * data set of them, see SetInputData(vtkDataObjectTree*)) on the GPU inside
 * VTK's own render window, after Bernardon, Pagot, Comba and Silva, "GPU-based Tiled Ray Casting
 * using Depth Peeling" (2004), on today's OpenGL:
 *
 * - the mesh is packed once into textures (a compact layout of point and neighbour indices, or
 *   the paper's 144-byte layout) and re-uploaded only when the data changes;
 * - every ray walks from tetrahedron to neighbour, integrating the transfer function along each
 *   segment exactly the way VTK's unstructured-grid mappers define it, until the ray leaves the
 *   mesh, the opaque geometry or the far plane stops it, or it is opaque (early ray
 *   termination), and re-enters non-convex meshes where their boundary takes it back in;
 * - by default (OpenGL 4.3, see Pipeline) one raster pass lists per pixel every place where the
 *   ray enters the mesh (the boundary's front faces, and the near plane where the camera is
 *   inside), and one compute dispatch over 8x4-pixel tiles walks every ray through all its
 *   layers; the paper's pipeline, in fragment shaders, finds the entries by a first-hit pass and
 *   depth peeling of the boundary, one layer at a time, and walks the rays in passes over screen
 *   tiles, up to TetsPerPass tetrahedra per pass;
 * - the result is composited into the render window, clipped by opaque geometry already drawn.
 *
 * The optical model is that of vtkUnstructuredGridPartialPreIntegration: the opacity transfer
 * function divided by the scalar opacity unit distance is an attenuation coefficient per world
 * unit, the colour is emitted in proportion to it; see docs/design.md. Only the first component
 * of the volume property is used, on one scalar per point or cell (see VectorMode).
 *
 * After each render, GetStatistics() tells what was done (pipeline, rays, tetrahedra per ray,
 * layers, tiles skipped, rays terminated early, GPU time per phase, GPU memory held) and
 * GetValidationReport() what the mesh builder found in the input. A frame in which the mapper
 * draws nothing (bad input, or no input at all, which vtkVolume does not even hand to Render())
 * leaves GetStatistics()->GetRendered() false.
 *
 * Progress: while a render (re)builds the CPU mesh (the first render, and whenever the input
 * changed), the mapper invokes vtkCommand::ProgressEvent as any vtkAlgorithm does
 * (GetProgress() from 0 to 0.9 while the mesh is built, 1 once it is packed for the GPU); a
 * frame that rebuilds nothing invokes none.
 *
 * This class is abstract: New() returns the OpenGL implementation through VTK's object factory
 * (vtkOpenGLTiledRayCastVolumeMapper), as for VTK's own volume mappers.
 */

#ifndef vtkTiledRayCastVolumeMapper_h
#define vtkTiledRayCastVolumeMapper_h

#include "vtkTetScalarSelection.h"       // For VectorModes and the inline forwarders
#include "vtkTiledRayCastMapperModule.h" // For export macro
#include "vtkUnstructuredGridVolumeMapper.h"
#include "vtkVolumeMapper.h" // For the blend modes' values

class vtkDataObjectTree;
class vtkRenderWindow;
class vtkTetMeshValidationReport;
class vtkTiledRayCastStatistics;
class vtkVolumeProperty;

class VTKTILEDRAYCASTMAPPER_EXPORT vtkTiledRayCastVolumeMapper
  : public vtkUnstructuredGridVolumeMapper
{
public:
  static vtkTiledRayCastVolumeMapper* New();
  vtkTypeMacro(vtkTiledRayCastVolumeMapper, vtkUnstructuredGridVolumeMapper);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * How a segment's colour and opacity are obtained from its entry scalar, exit scalar and
   * length.
   */
  enum IntegrationModes
  {
    /**
     * Moreland and Angel's partial pre-integration (the Psi table of
     * vtkUnstructuredGridPartialPreIntegration), with every segment split at the transfer
     * function's nodes: no table depends on the transfer function, so it is both the most
     * accurate mode and the cheapest to change. The default.
     */
    PARTIAL_PRE_INTEGRATION = 0,
    /**
     * A 3D table of (entry scalar, exit scalar, length), as in the paper, computed exactly and
     * at the resolution the transfer function needs; rebuilt when the transfer function changes.
     */
    PRE_INTEGRATION_3D = 1,
    /**
     * A 2D table of (entry scalar, exit scalar) for one reference length; other lengths are
     * corrected in opacity. The cheapest table, the least accurate.
     */
    PRE_INTEGRATION_2D = 2,
    /**
     * The cheapest of the three whose predicted error stays within MaximumError: the 2D table,
     * else the 3D table, else partial pre-integration. The error is predicted from the mesh's
     * segments and the transfer function when either changes (docs/mapper.md, "Automatic
     * integration"); GetStatistics()->GetIntegrationMode() says which mode was taken. The
     * choice is made on a worker thread: until it is, frames use partial pre-integration
     * (the first choice of a mapper, and every one with SynchronousStatistics, is waited for).
     */
    AUTOMATIC_INTEGRATION = 3
  };

  ///@{
  /**
   * The integration mode (see IntegrationModes). Default AUTOMATIC_INTEGRATION: within
   * MaximumError (1/255) of the exact integral, the cheapest mode; PARTIAL_PRE_INTEGRATION
   * for the exact integral whatever it costs.
   */
  vtkSetClampMacro(IntegrationMode, int, PARTIAL_PRE_INTEGRATION, AUTOMATIC_INTEGRATION);
  vtkGetMacro(IntegrationMode, int);
  void SetIntegrationModeToPartialPreIntegration()
  {
    this->SetIntegrationMode(PARTIAL_PRE_INTEGRATION);
  }
  void SetIntegrationModeToPreIntegration3D() { this->SetIntegrationMode(PRE_INTEGRATION_3D); }
  void SetIntegrationModeToPreIntegration2D() { this->SetIntegrationMode(PRE_INTEGRATION_2D); }
  void SetIntegrationModeToAutomatic() { this->SetIntegrationMode(AUTOMATIC_INTEGRATION); }
  const char* GetIntegrationModeAsString();
  static const char* GetIntegrationModeAsString(int mode);
  ///@}

  ///@{
  /**
   * The error budget of AUTOMATIC_INTEGRATION: the largest difference, in 1/255 of a colour
   * channel, that a table may add to a pixel against the exact integral (before the
   * framebuffer's own rounding to 8 bits). Default 1.
   */
  vtkSetClampMacro(MaximumError, double, 0.0, 255.0);
  vtkGetMacro(MaximumError, double);
  ///@}

  /**
   * How the mesh is packed for the GPU.
   */
  enum MeshLayouts
  {
    /**
     * Point indices and neighbour indices per tetrahedron plus shared point positions and
     * scalars (about 35 bytes per tetrahedron); normals and gradients are computed on the fly.
     * The default.
     */
    COMPACT_LAYOUT = 0,
    /**
     * The paper's layout (its Figure 8): vertices, face normals, neighbours and the scalar
     * gradient of every tetrahedron in three RGBA32F 2D textures, 144 bytes per tetrahedron.
     */
    PAPER_LAYOUT = 1
  };

  ///@{
  /**
   * The GPU layout of the mesh (see MeshLayouts). Default COMPACT_LAYOUT.
   */
  vtkSetClampMacro(MeshLayout, int, COMPACT_LAYOUT, PAPER_LAYOUT);
  vtkGetMacro(MeshLayout, int);
  void SetMeshLayoutToCompact() { this->SetMeshLayout(COMPACT_LAYOUT); }
  void SetMeshLayoutToPaper() { this->SetMeshLayout(PAPER_LAYOUT); }
  const char* GetMeshLayoutAsString();
  ///@}

  ///@{
  /**
   * Store the tetrahedra along a Morton (Z-order) curve of their centroids (default on), so
   * that neighbouring tetrahedra, and the boundary faces the entry pass draws, lie close in
   * GPU memory. Measured on the H200 at 1024² (docs/benchmarks.md): 3 to 10 % off the frame;
   * it adds 35 to 105 % to the mesh's build time (docs/mesh-layout.md), paid when the
   * topology changes, not when only points or scalars do. Turn it off for meshes rebuilt
   * every frame that are already in a spatial order. The points are numbered along the same
   * kind of curve (vtkTetMeshBuilder::PointOrdering): on an H100 a billion tetrahedra whose
   * points came in lattice order drew in 1.9 s a frame, in 0.15 s with their points in Morton
   * order.
   */
  vtkSetMacro(SpatialOrdering, bool);
  vtkGetMacro(SpatialOrdering, bool);
  vtkBooleanMacro(SpatialOrdering, bool);
  ///@}

  /**
   * Where a deforming mesh's points are updated, in the frames where only they moved (same
   * cells, same scalars).
   */
  enum PointUpdates
  {
    /**
     * On the GPU where the OpenGL renderer is a GPU, on the CPU under a software rasteriser
     * (Mesa's llvmpipe: the GPU's passes would run on the same cores, in double precision
     * emulated, 2.5-4 times slower than the CPU's rebuild, docs/benchmarks.md).
     */
    AUTOMATIC_POINT_UPDATE = 0,
    /**
     * The CPU rebuilds the points (positions, orientation and degeneracy, the layout's point
     * texels) and uploads the point texels, 16 B a point.
     */
    CPU_POINT_UPDATE = 1,
    /**
     * The input's coordinates go to the GPU as they are (float or double), and compute shaders
     * check every tetrahedron's orientation and degeneracy as a full build would (in double
     * precision) and write the shifted points into the layout's point texels in place. A frame in
     * which a tetrahedron turned inside out or became flat (or back), or a coordinate is not
     * finite, is rebuilt on the CPU as with CPU_POINT_UPDATE; so is, after the GPU's update, the
     * CPU's copy of the points in a frame where the automatic integration makes its choice again
     * (it samples the mesh on the CPU). Needs the compact layout and OpenGL 4.3 (the CPU updates
     * the points otherwise).
     */
    GPU_POINT_UPDATE = 2
  };

  ///@{
  /**
   * Where a deforming mesh's points are updated (see PointUpdates). Default
   * AUTOMATIC_POINT_UPDATE. The statistics say what each frame did
   * (vtkTiledRayCastStatistics::GetMeshRebuild: MeshRebuildPointsOnGPU, MeshRebuildPoints).
   */
  vtkSetClampMacro(PointUpdate, int, AUTOMATIC_POINT_UPDATE, GPU_POINT_UPDATE);
  vtkGetMacro(PointUpdate, int);
  void SetPointUpdateToAutomatic() { this->SetPointUpdate(AUTOMATIC_POINT_UPDATE); }
  void SetPointUpdateToCPU() { this->SetPointUpdate(CPU_POINT_UPDATE); }
  void SetPointUpdateToGPU() { this->SetPointUpdate(GPU_POINT_UPDATE); }
  const char* GetPointUpdateAsString();
  ///@}

  /**
   * Which GPU pipeline casts the rays.
   */
  enum Pipelines
  {
    /**
     * The compute pipeline where the OpenGL context has compute shaders (OpenGL 4.3), the
     * fragment pipeline otherwise. The default.
     */
    AUTOMATIC_PIPELINE = 0,
    /**
     * OpenGL 4.3 compute shaders: one raster pass lists every boundary face that covers a pixel
     * (in a per-pixel list), then one compute dispatch walks every ray through the mesh and all
     * its boundary layers in place, and one light pass composites. On GPUs whose graphics pipe
     * is a small part of the chip (NVIDIA H100 and H200: 4 of 132 multiprocessors) it is many
     * times faster than the fragment pipeline. Refused, with an error, where the context lacks
     * OpenGL 4.3.
     */
    COMPUTE_PIPELINE = 1,
    /**
     * The paper's pipeline: first hit, depth peeling and tiled ray-casting passes in fragment
     * shaders, ping-ponging the ray state between render targets (OpenGL 3.3). TetsPerPass,
     * OcclusionQueryInterval, TileSize and MaximumNumberOfPassesPerLayer apply to it alone.
     */
    FRAGMENT_PIPELINE = 2
  };
  ///@{
  /**
   * The GPU pipeline (see Pipelines). Default AUTOMATIC_PIPELINE. The statistics say which one
   * rendered.
   */
  vtkSetClampMacro(Pipeline, int, AUTOMATIC_PIPELINE, FRAGMENT_PIPELINE);
  vtkGetMacro(Pipeline, int);
  void SetPipelineToAutomatic() { this->SetPipeline(AUTOMATIC_PIPELINE); }
  void SetPipelineToCompute() { this->SetPipeline(COMPUTE_PIPELINE); }
  void SetPipelineToFragment() { this->SetPipeline(FRAGMENT_PIPELINE); }
  const char* GetPipelineAsString();
  ///@}

  ///@{
  /**
   * The largest number of tetrahedra a ray advances in one ray-casting pass. 1 is the paper's
   * one-tetrahedron-per-pass ping-pong; 0 means no limit (a single pass per layer and tile).
   * Default 0 (see docs/benchmarks.md for the measurement behind it).
   */
  vtkSetClampMacro(TetsPerPass, int, 0, VTK_INT_MAX);
  vtkGetMacro(TetsPerPass, int);
  ///@}

  ///@{
  /**
   * Every how many ray-casting passes a tile checks whether its rays are all done (the paper's
   * Z-update and occlusion-query passes; their results are read without stalling the pipeline).
   * Has no effect when TetsPerPass is 0. Default 4.
   */
  vtkSetClampMacro(OcclusionQueryInterval, int, 1, VTK_INT_MAX);
  vtkGetMacro(OcclusionQueryInterval, int);
  ///@}

  ///@{
  /**
   * The side, in pixels, of the square screen tiles that ray-casting passes run over. 0 means
   * one tile covering the whole viewport. Default 256: measured on an H100, the fastest on two
   * meshes of four and within 6 % of the fastest on the others, where larger tiles win but lose
   * on the first two (docs/benchmarks.md, "Choice of defaults").
   */
  vtkSetClampMacro(TileSize, int, 0, VTK_INT_MAX);
  vtkGetMacro(TileSize, int);
  ///@}

  ///@{
  /**
   * Blend modes (vtkVolumeMapper's values; vtkUnstructuredGridVolumeMapper names the first
   * two): composite (default), maximum and minimum intensity (the transfer function at the
   * extreme scalar of the ray, colour times opacity), average intensity (the mean of opacity
   * times the scalar normalised to the data's range, over the length where the scalar lies in
   * AverageIPScalarRange, gray and opaque) and additive (that integral per scalar opacity unit
   * distance, gray, clamped to 1). Exact along each linear segment; the compute pipeline only.
   */
  void SetBlendModeToMinimumIntensity()
  {
    this->SetBlendMode(vtkVolumeMapper::MINIMUM_INTENSITY_BLEND);
  }
  void SetBlendModeToAverageIntensity()
  {
    this->SetBlendMode(vtkVolumeMapper::AVERAGE_INTENSITY_BLEND);
  }
  void SetBlendModeToAdditive() { this->SetBlendMode(vtkVolumeMapper::ADDITIVE_BLEND); }
  vtkSetVector2Macro(AverageIPScalarRange, double);
  vtkGetVectorMacro(AverageIPScalarRange, double, 2);
  ///@}

  ///@{
  /**
   * Interaction, with the names and meaning of vtkUnstructuredGridVolumeRayCastMapper's
   * settings. ImageSampleDistance is the distance in pixels between rays: 1 casts one ray per
   * pixel, 2 one ray per 2 x 2 pixels, whose colours are interpolated bilinearly over the
   * viewport (values below 1 are taken as 1: no supersampling). With AutoAdjustSampleDistances
   * on (the default) the distance is chosen every frame between MinimumImageSampleDistance and
   * MaximumImageSampleDistance (defaults 1 and 10) so that the volume's frame fits the time the
   * renderer allocated it (vtkProp::GetAllocatedRenderTime, from the render window's desired
   * update rate): while an interactor moves the camera (desired rate 15/s by default) a frame
   * that would take longer is drawn with fewer rays, and once the camera stops (still rate
   * 0.0001/s) every pixel has its ray again. The frame time is the mapper's GPU time, measured
   * by its timers. GetStatistics()->GetImageSampleDistance() says what the last frame used.
   */
  vtkSetClampMacro(ImageSampleDistance, float, 0.1f, 100.0f);
  vtkGetMacro(ImageSampleDistance, float);
  vtkSetClampMacro(MinimumImageSampleDistance, float, 0.1f, 100.0f);
  vtkGetMacro(MinimumImageSampleDistance, float);
  vtkSetClampMacro(MaximumImageSampleDistance, float, 0.1f, 100.0f);
  vtkGetMacro(MaximumImageSampleDistance, float);
  vtkSetClampMacro(AutoAdjustSampleDistances, vtkTypeBool, 0, 1);
  vtkGetMacro(AutoAdjustSampleDistances, vtkTypeBool);
  vtkBooleanMacro(AutoAdjustSampleDistances, vtkTypeBool);
  ///@}

  ///@{
  /**
   * Empty-space skipping by the transfer function (composite blending only): tetrahedra whose
   * scalars all map to zero opacity are left out of the walk, and rays jump over each run of
   * them to the next face of the visible part of the mesh (the depth peeling of non-convex
   * meshes). The image is the same; the statistics count the visible tetrahedra and the faces
   * rays enter them by. Reclassified only when the transfer function or the scalars change
   * (a pass over the tetrahedra, in TransferFunctionBuildTime). Default on.
   */
  vtkSetMacro(EmptySpaceSkipping, bool);
  vtkGetMacro(EmptySpaceSkipping, bool);
  vtkBooleanMacro(EmptySpaceSkipping, bool);
  ///@}

  ///@{
  /**
   * A ray stops once its accumulated opacity reaches this value (early ray termination). 1
   * disables early termination. The colour left out is at most 1 - this value. Default 0.999.
   */
  vtkSetClampMacro(EarlyRayTerminationOpacity, double, 0.0, 1.0);
  vtkGetMacro(EarlyRayTerminationOpacity, double);
  ///@}

  ///@{
  /**
   * A safety bound: the largest number of ray-casting passes one tile may run for one layer.
   * Reached only by a mesh whose neighbour links loop; the tile then stops with a warning.
   * Default 1000000.
   */
  vtkSetClampMacro(MaximumNumberOfPassesPerLayer, int, 1, VTK_INT_MAX);
  vtkGetMacro(MaximumNumberOfPassesPerLayer, int);
  ///@}

  ///@{
  /**
   * Upper bounds on the GPU textures the mesh may use, in texels: the largest texture buffer
   * and the largest side of a 2D texture. 0 (the default) means the GPU's own limits
   * (GL_MAX_TEXTURE_BUFFER_SIZE, GL_MAX_TEXTURE_SIZE); a positive value can only lower them.
   * The compact layout splits an array larger than one texture buffer over up to 8 of them
   * (NVIDIA's limit, 2^27 texels, holds 134M tetrahedra per buffer; the walk's neighbour words
   * hold 2^30); the paper layout's 2D textures are refused when too large.
   */
  vtkSetClampMacro(MaximumTextureBufferSize, vtkIdType, 0, VTK_ID_MAX);
  vtkGetMacro(MaximumTextureBufferSize, vtkIdType);
  vtkSetClampMacro(MaximumTextureSize, int, 0, VTK_INT_MAX);
  vtkGetMacro(MaximumTextureSize, int);
  ///@}

  ///@{
  /**
   * The most GPU memory the mesh may take, in bytes. 0 (the default) means what the driver
   * reports free (NVIDIA's GL_NVX_gpu_memory_info; no limit where the driver does not say); a
   * positive value can only lower it. A mesh that needs more is refused with an error that names
   * both sizes, and is never uploaded: before it is built where the input's counts tell (an
   * unstructured grid of one linear 3D cell type), once its layout is packed otherwise.
   */
  vtkSetClampMacro(MaximumGPUMemory, vtkIdType, 0, VTK_ID_MAX);
  vtkGetMacro(MaximumGPUMemory, vtkIdType);
  ///@}

  ///@{
  /**
   * How a scalar array of several components is reduced to the one scalar that is rendered
   * (vtkTetScalarSelection has the rule; the exact reference renderer follows the same).
   * DEFAULT (the default) is VTK 9.1's rule for unstructured grids (vtkProjectedTetrahedraMapper):
   * the colour transfer function's own vtkScalarsToColors::VectorMode and VectorComponent
   * (`property->GetRGBTransferFunction()->SetVectorComponent(1)`), component 0 with a gray
   * function. MAGNITUDE or COMPONENT (with VectorComponent) set here override the colour
   * function. Several components are never blended: dependent components
   * (IndependentComponentsOff with more than one component) and transfer functions set for
   * components other than the first are refused with an error, and nothing is drawn. The
   * values are vtkTetScalarSelection's, which holds them (see GetScalarSelection()).
   */
  enum VectorModes
  {
    DEFAULT = vtkTetScalarSelection::DEFAULT,
    MAGNITUDE = vtkTetScalarSelection::MAGNITUDE,
    COMPONENT = vtkTetScalarSelection::COMPONENT
  };
  void SetVectorMode(int mode);
  int GetVectorMode() { return this->ScalarSelection->GetVectorMode(); }
  void SetVectorModeToDefault() { this->SetVectorMode(DEFAULT); }
  void SetVectorModeToMagnitude() { this->SetVectorMode(MAGNITUDE); }
  void SetVectorModeToComponent() { this->SetVectorMode(COMPONENT); }
  void SetVectorComponent(int component);
  int GetVectorComponent() { return this->ScalarSelection->GetVectorComponent(); }
  ///@}

  /**
   * The mapper's whole scalar selection as one object, to hand along in one call
   * (vtkTetScalarSelection::CopySettings()): ScalarMode, ArrayAccessMode, ArrayId and ArrayName,
   * which vtkAbstractVolumeMapper holds and which are copied in at each call, and VectorMode and
   * VectorComponent, which it holds itself. Set them through the mapper's own setters: those
   * mark the mapper modified, a change made on the object returned does not.
   */
  vtkTetScalarSelection* GetScalarSelection();

  ///@{
  /**
   * Resolution of the pre-integration tables along the scalar axes (both) and along the
   * length axis. 0 (the default) chooses them from the transfer function: fine enough for its
   * narrowest feature, within the GPU's limits.
   */
  vtkSetClampMacro(PreIntegrationTableScalarSize, int, 0, 4096);
  vtkGetMacro(PreIntegrationTableScalarSize, int);
  vtkSetClampMacro(PreIntegrationTableLengthSize, int, 0, 1024);
  vtkGetMacro(PreIntegrationTableLengthSize, int);
  ///@}

  ///@{
  /**
   * When on, Render() waits at the end of each frame for the GPU timers (and, in the compute
   * pipeline, for the GPU's counts of rays, steps, layers and terminations), so that the
   * statistics hold this frame's (benchmarks and tests want this). When off (the default), they
   * are read during a later frame without stalling the GPU, and the statistics hold the latest
   * available.
   */
  vtkSetMacro(SynchronousStatistics, bool);
  vtkGetMacro(SynchronousStatistics, bool);
  vtkBooleanMacro(SynchronousStatistics, bool);
  ///@}

  ///@{
  /**
   * When on (the default), a warning tells of every problem the mesh builder finds in the input
   * (GetValidationReport()). Off, degenerate (zero-volume) tetrahedra and duplicate points are
   * counted in the report but not warned about: a mesh cut exactly at planes has them wherever a
   * plane passes through or next to its points (ParaView's plugin turns this off for the pieces
   * it cuts at the ranks' partition planes); the other problems are still warned about.
   */
  vtkSetMacro(WarnAboutDegenerateCells, bool);
  vtkGetMacro(WarnAboutDegenerateCells, bool);
  vtkBooleanMacro(WarnAboutDegenerateCells, bool);
  ///@}

  ///@{
  /**
   * Composite input. Besides a vtkUnstructuredGridBase, the input may be any vtkDataObjectTree
   * (vtkMultiBlockDataSet, vtkPartitionedDataSet, vtkPartitionedDataSetCollection) of
   * unstructured grids: `mapper->SetInputConnection(multiblockReader->GetOutputPort())` or
   * SetInputData(tree). Its blocks are merged into one mesh and rendered in one traversal, each
   * block's scalars selected on their own (by name with SelectScalarArray(name)), through the
   * one volume property; points of different blocks with the same coordinates and scalar are
   * merged, so that blocks sharing faces render as one mesh (vtkTetMeshBlockMerger). Empty
   * blocks are skipped (counted in the validation report); a block of another type (image or
   * polygonal data) is an error, and nothing is drawn.
   */
  using Superclass::SetInputData;
  virtual void SetInputData(vtkDataObjectTree* input);
  double* GetBounds() override;
  using Superclass::GetBounds;
  ///@}

  /**
   * Whether this mapper can render in `window` (a window already rendered once, so that its
   * OpenGL context exists) with its present settings: the context has what the chosen Pipeline
   * needs (OpenGL 3.3 or 3.2 with GL_ARB_explicit_attrib_location for the fragment pipeline and
   * the automatic choice, 4.3 for the compute pipeline) and the blend mode is composite. The
   * property is not consulted (may be null): whether it suits the input's scalars (several
   * components, see VectorMode) is known only with the input, and refused at Render(). VTK's name
   * and signature, as on vtkGPUVolumeRayCastMapper; 0 in this abstract class, the OpenGL
   * implementation answers.
   */
  virtual int IsRenderSupported(vtkRenderWindow* window, vtkVolumeProperty* property);

  /**
   * What the last Render() did. Never null.
   */
  vtkTiledRayCastStatistics* GetStatistics() { return this->Statistics; }

  /**
   * vtkVolume calls Update() on its mapper at the start of every frame and Render() only when
   * the mapper has an input. Without an input, Update() is the frame's only call: it resets the
   * statistics (nothing is drawn) before VTK's pipeline reports the missing input.
   */
  using Superclass::Update;
  void Update() override;

  /**
   * What the mesh builder found in the input at the last Render() (or Update()). Never null.
   */
  vtkTetMeshValidationReport* GetValidationReport() { return this->ValidationReport; }

protected:
  vtkTiledRayCastVolumeMapper();
  ~vtkTiledRayCastVolumeMapper() override;

  // vtkUnstructuredGridBase or vtkDataObjectTree.
  int FillInputPortInformation(int port, vtkInformation* info) override;

  int IntegrationMode = AUTOMATIC_INTEGRATION;
  int MeshLayout = COMPACT_LAYOUT;
  bool SpatialOrdering = true;
  int PointUpdate = AUTOMATIC_POINT_UPDATE;
  int Pipeline = AUTOMATIC_PIPELINE;
  int TetsPerPass = 0;
  int OcclusionQueryInterval = 4;
  int TileSize = 256;
  double EarlyRayTerminationOpacity = 0.999;
  bool EmptySpaceSkipping = true;
  double MaximumError = 1.0;
  float ImageSampleDistance = 1.0f;
  float MinimumImageSampleDistance = 1.0f;
  float MaximumImageSampleDistance = 10.0f;
  vtkTypeBool AutoAdjustSampleDistances = 1;
  double AverageIPScalarRange[2] = { VTK_DOUBLE_MIN, VTK_DOUBLE_MAX };
  int MaximumNumberOfPassesPerLayer = 1000000;
  vtkIdType MaximumTextureBufferSize = 0;
  int MaximumTextureSize = 0;
  vtkIdType MaximumGPUMemory = 0;
  int PreIntegrationTableScalarSize = 0;
  int PreIntegrationTableLengthSize = 0;
  bool SynchronousStatistics = false;
  bool WarnAboutDegenerateCells = true;

  vtkTiledRayCastStatistics* Statistics;
  vtkTetMeshValidationReport* ValidationReport;
  vtkTetScalarSelection* ScalarSelection;

private:
  vtkTiledRayCastVolumeMapper(const vtkTiledRayCastVolumeMapper&) = delete;
  void operator=(const vtkTiledRayCastVolumeMapper&) = delete;
};

#endif
