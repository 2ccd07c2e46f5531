/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkTiledRayCastComputePipeline.h

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
/**
 * @class   vtkTiledRayCastComputePipeline
 * @brief   the mapper's compute pipeline: entry lists, one traversal dispatch, one composite
 *
 * On GPUs whose graphics pipe is a small corner of the chip (the H100 and H200 run fragment
 * shaders on 4 of their 132 multiprocessors), the paper's fragment passes leave most of the
 * GPU idle. This pipeline keeps one raster pass, over the boundary faces only, and moves the
 * rest to an OpenGL 4.3 compute dispatch that runs on every multiprocessor:
 *
 * 1. ListEntries: the boundary faces (front faces, with the exact-coverage test of the
 *    fragment pipeline) and, where the near plane cuts the mesh, the near-plane slices are
 *    rasterised once; every fragment appends (lambda, tet and face) to its pixel's list. This
 *    replaces the first hit and every depth-peeling pass.
 * 2. Traverse: one invocation per pixel (8x4 workgroups) takes its entries in depth order and
 *    walks the ray through every layer, with the same walk (vtkTiledRayCastWalk.glsl) and the
 *    same peeling rules as the fragment pipeline. The ray state stays in registers; the colour
 *    is written once (RGBA16); the list heads are reset for the next frame as they are read, so
 *    nothing is cleared. The GPU counts rays, steps, layers and terminations per workgroup.
 *    The list is sized from the counts of earlier frames (BeginFrame), never from this
 *    frame's, so Render() does not wait for the GPU; an entry that finds it full marks its
 *    pixel, whose ray is then counted as incomplete.
 * 3. FinishEntries, on verified frames only (SynchronousStatistics, the first frame of a mesh
 *    or image size, a camera jump): waits for the frame's counts and, if rays were
 *    incomplete, grows the list and draws the frame again. On other frames such rays (a
 *    moving view asking for far more entries than the frames before) miss layers, are
 *    counted, and the mapper warns; the list has grown by the next frame.
 * 4. Composite: one light full-screen pass blends the colour into VTK's framebuffer.
 *
 * The counts of a frame are read without waiting during a later frame (double-buffered, with
 * a fence), or at once with SynchronousStatistics.
 *
 * Target memory per pixel: a list head (4 B), the colour (8 B) and 12 B per entry (one per
 * pixel and boundary layer).
 *
 * The mapper sets the frame's, the mesh's and the integration's uniforms through
 * vtkTiledRayCastProgramSetup, on the raster programs and on the compute program alike.
 * Private to the module: not wrapped, not installed.
 */

#ifndef vtkTiledRayCastComputePipeline_h
#define vtkTiledRayCastComputePipeline_h

#include "vtkNew.h"                        // For vtkNew
#include "vtkTiledRayCastGroupTraversal.h" // For the traversal of overlapping volumes
#include "vtkTiledRayCastStorageBuffer.h"  // For the storage buffers
#include "vtkType.h"                       // For vtkIdType

#include <cstdint> // For std::uint32_t
#include <string>  // For std::string
#include <utility> // For std::pair
#include <vector>  // For std::vector

class vtkOpenGLFramebufferObject;
class vtkOpenGLRenderWindow;
class vtkOpenGLVertexArrayObject;
class vtkShaderProgram;
class vtkTextureObject;
class vtkTiledRayCastComputeShader;
class vtkTiledRayCastPeelAccumulation;
class vtkTiledRayCastPhaseTimers;
class vtkTiledRayCastStatistics;
class vtkTiledRayCastVolumetricPeel;
class vtkWindow;

/**
 * What a pipeline needs from the mapper to run a program: the uniforms of the frame (rays,
 * opaque depth), of the mesh textures, of the exact-coverage test, of the integration and of
 * compositing rays over the viewport's pixels.
 */
class vtkTiledRayCastProgramSetup
{
public:
  virtual ~vtkTiledRayCastProgramSetup() = default;
  virtual void SetFrameUniforms(vtkShaderProgram* program) = 0;
  virtual void SetMeshUniforms(vtkShaderProgram* program) = 0;
  virtual void SetCoverageUniforms(vtkShaderProgram* program) = 0;
  virtual void SetIntegrationUniforms(vtkShaderProgram* program) = 0;
  virtual void SetSampleScaleUniforms(vtkShaderProgram* program) = 0;
  // The textures only the entry pass reads (a group's volume's boundary faces, active only
  // while its entries are listed).
  virtual void ActivateEntryTextures(bool) {}
};

class vtkTiledRayCastComputePipeline
{
public:
  vtkTiledRayCastComputePipeline();
  ~vtkTiledRayCastComputePipeline();

  using Replacements = std::vector<std::pair<std::string, std::string>>;

  /**
   * Build (or keep) the programs from the mapper's GLSL pieces: `common` replaces
   * //TRC::Common::Dec, //TRC::Layout::Dec and //TRC::Integration::Dec. False with a message
   * when a program does not compile.
   */
  bool UpdatePrograms(
    vtkOpenGLRenderWindow* window, const Replacements& common, std::string& error);

  /**
   * The programs of a group of overlapping volumes traversed together (vtkTiledRayCastVolumeGroup):
   * `members[k]` is volume k's `common` code as for UpdatePrograms, composed from `inputs[k]`.
   * Each volume lists its entries with its own raster programs; one traversal integrates them
   * all.
   */
  bool UpdateGroupPrograms(vtkOpenGLRenderWindow* window,
    const std::vector<vtkTiledRayCastGroupTraversal::Inputs>& inputs,
    const std::vector<Replacements>& members, std::string& error);

  /**
   * The group's traversal for `stage` (0 outside VTK's dual depth peeling, else its stage),
   * built on first use after UpdateGroupPrograms. False with a message when it does not build.
   */
  bool PrepareGroupStage(int stage, std::string& error);

  /**
   * Whether the group's programs hold one copy of the volumes' code for all of them.
   */
  bool GetGroupCodeShared() const { return this->Group.GetSharedCode(); }

  /**
   * Whether the group's programs are to be built (UpdateGroupPrograms) for volumes of these
   * inputs, in the group's order: false when they were last built for them, so that a steady
   * frame composes and compares no GLSL.
   */
  bool GroupProgramsChanged(const std::vector<vtkTiledRayCastGroupTraversal::Inputs>& inputs) const
  {
    return this->Group.Changed(inputs);
  }

  /**
   * Taking part in VTK's dual depth peeling (vtkTiledRayCastVolumetricPeel): the programs of
   * `stage` (1 to 3), built from UpdatePrograms' pieces on first use, and the back colour the
   * traversal then writes besides the colour, the size of the targets. False with a message
   * when a program does not build or the GPU cannot allocate the colour.
   */
  bool PreparePeel(vtkOpenGLRenderWindow* window, int stage, std::string& error);

  /**
   * Per-pixel targets for an image of this size (they only grow). False with a message when
   * the GPU cannot allocate them.
   */
  bool UpdateTargets(vtkOpenGLRenderWindow* window, int width, int height, std::string& error);

  /**
   * One volume of a group's frame: its uniforms and what its entry pass draws.
   */
  struct Member
  {
    vtkTiledRayCastProgramSetup* Setup = nullptr;
    vtkIdType NumberOfBoundaryFaces = 0;
    vtkIdType NumberOfTetrahedra = 0;
    bool NearPlaneCutsMesh = false;
    bool Mirrored = false;
  };

  /**
   * What one frame draws.
   */
  struct Frame
  {
    vtkOpenGLRenderWindow* Window = nullptr;
    int Width = 0;
    int Height = 0;
    vtkIdType NumberOfBoundaryFaces = 0;
    vtkIdType NumberOfTetrahedra = 0;
    bool NearPlaneCutsMesh = false;
    bool Mirrored = false;
    int MaximumSteps = 0;
    bool Verify = false; // wait for this frame's counts (SynchronousStatistics)
    // The view (vtkTiledRayCastFrameGeometry): direction in object coordinates, and the
    // fraction of the viewport the mesh's bounds cover.
    float ViewDirection[3] = { 0, 0, 1 };
    double BoundsCoverage = 0;
    float PeelEpsilon = 0;
    float ViewportOrigin[2] = { 0, 0 };
    int Viewport[4] = { 0, 0, 0, 0 }; // the caller's, which compositing draws into
    // A group's frame (two or more volumes, UpdateGroupPrograms): the volumes, in the order of
    // the programs; the counts above are their sums. The scene's depth (the caller's texture
    // unit) and the early termination are shared.
    std::vector<Member> Members;
    int OpaqueDepthUnit = -1;
    float EarlyTerminationOpacity = 1.f;
    // Taking part in VTK's dual depth peeling (PreparePeel): the stage (0: not peeling), and
    // the pass, which binds its textures to the programs. One ray per pixel of the pass's
    // textures, which the viewport (origin 0) covers.
    int PeelStage = 0;
    const vtkTiledRayCastVolumetricPeel* Peel = nullptr;
    // The volume drawn in the peeling (a group's first): its later stages traverse the entries
    // its first stage listed (the view is the same in every draw of a frame).
    const void* PeelVolume = nullptr;
    // Several sets of volumes in the stage, drawn farthest first: the colours go over the
    // stage's accumulation, which composites them once (null: composited here).
    vtkTiledRayCastPeelAccumulation* Accumulation = nullptr;
  };

  /**
   * A whole frame, phases 1 to 4, with the statistics of its tiles and passes: the caller has
   * pushed the framebuffer bindings, set the viewport to the image and activated the textures;
   * Render pops the bindings before compositing. False, with `error` set, when a phase failed
   * (nothing is composited then).
   */
  bool Render(const Frame& frame, vtkTiledRayCastProgramSetup& setup,
    vtkTiledRayCastPhaseTimers& timers, vtkTiledRayCastStatistics* stats, std::string& error);

  /**
   * Before the frame: puts the latest counts that have arrived in the statistics, sizes the
   * entry list from them, and decides whether this frame is verified (FinishEntries); a frame
   * that `reuse`s the list of an earlier draw (VTK's depth peeling) neither sizes nor verifies
   * it. False with a message when the list cannot grow.
   */
  bool BeginFrame(
    const Frame& frame, bool reuse, vtkTiledRayCastStatistics* stats, std::string& error);

  /**
   * Phase 1, the entry list, into the pipeline's own framebuffer (the caller has pushed the
   * framebuffer bindings and set the viewport to the image).
   */
  void ListEntries(const Frame& frame, vtkTiledRayCastProgramSetup& setup);

  /**
   * Phase 2: the traversal dispatch.
   */
  void Traverse(const Frame& frame, vtkTiledRayCastProgramSetup& setup);

  /**
   * Phase 3, on verified frames only (else it returns at once): waits for the frame's counts
   * and, if rays were incomplete (the list lost entries), grows the list to what the view
   * asked for and draws the frame again. False with a message when the list cannot grow.
   */
  bool FinishEntries(const Frame& frame, vtkTiledRayCastProgramSetup& setup,
    vtkTiledRayCastStatistics* stats, std::string& error);

  /**
   * Phase 4, into the caller's framebuffer, viewport and blending (premultiplied colour),
   * the colour of each ray spread over the viewport's pixels (setup's sample scale).
   */
  void Composite(const Frame& frame, vtkTiledRayCastProgramSetup& setup);

  /**
   * Wait for this frame's counts and put them in the statistics (SynchronousStatistics).
   */
  void ReadCounts(vtkTiledRayCastStatistics* stats);

  /**
   * Rays that reached the step bound in one layer in the latest counts read (a mesh whose
   * neighbour links loop): the mapper warns.
   */
  vtkIdType GetNumberOfRaysStopped() const { return this->RaysStopped; }

  /**
   * Rays of the counts read since the last call whose lists lost entries (a moving view
   * asking for far more entries than the frames before it; never on a verified frame): the
   * mapper warns.
   */
  vtkIdType TakeNumberOfRaysIncomplete()
  {
    const vtkIdType incomplete = this->RaysIncomplete;
    this->RaysIncomplete = 0;
    return incomplete;
  }

  /**
   * The traversal's workgroups (its tiles) for a frame.
   */
  static int GetNumberOfTiles(const Frame& frame);

  /**
   * The colour texture the traversal writes (the mapper activates it for compositing).
   */
  vtkTextureObject* GetColorTexture();

  /**
   * GPU memory of the per-pixel targets and the entry list, in bytes.
   */
  vtkIdType GetTargetBytes() const;

  void ReleaseGraphicsResources(vtkWindow* window);

private:
  vtkTiledRayCastComputePipeline(const vtkTiledRayCastComputePipeline&) = delete;
  void operator=(const vtkTiledRayCastComputePipeline&) = delete;

  struct RasterProgram
  {
    vtkShaderProgram* Shader = nullptr; // owned by the window's shader cache
    vtkNew<vtkOpenGLVertexArrayObject> VAO;
    std::string Key;
  };
  bool ReadyRaster(vtkOpenGLRenderWindow* window, RasterProgram& program, const std::string& vs,
    const std::string& fs, const std::string& gs, std::string& error);
  void BindBuffers();
  bool GrowEntries(vtkIdType needed, std::string& error);

  void ReadCountsInto(int buffer, vtkTiledRayCastStatistics* stats);
  // The latest counts read into the statistics (frames whose own have not arrived show them).
  void ReportCounts(vtkTiledRayCastStatistics* stats) const;

  static Replacements ProgramReplacements(const Replacements& common, bool group);
  // `source` with the replacements made in order (every occurrence of each tag).
  static std::string Substituted(std::string source, const Replacements& replacements);
  void ListMemberEntries(const Frame& frame, const Member& member, RasterProgram& faces,
    RasterProgram& slices, vtkTiledRayCastProgramSetup& setup, bool group, int index);
  void SetGroupUniforms(const Frame& frame);

  RasterProgram FacesProgram;
  RasterProgram NearSliceProgram;
  RasterProgram CompositeProgram;
  vtkNew<vtkTiledRayCastComputeShader> Traversal;
  // Overlapping volumes: each volume's entry programs, and the traversal of them all.
  RasterProgram GroupFaces[vtkTiledRayCastGroupTraversal::MaximumMembers];
  RasterProgram GroupSlices[vtkTiledRayCastGroupTraversal::MaximumMembers];
  vtkTiledRayCastGroupTraversal Group;
  // VTK's dual depth peeling: the programs of its stages 1 to 3, built from PeelCommon (the
  // pieces of the latest UpdatePrograms) when a stage first needs them, and the back colour.
  struct PeelPrograms
  {
    RasterProgram Composite;
    vtkNew<vtkTiledRayCastComputeShader> Traversal;
    bool Built = false;
  };
  PeelPrograms Peel[3];
  Replacements PeelCommon;
  vtkNew<vtkTextureObject> BackColor;
  // Words per entry node: 3, or 4 in a group's list (the volume's index).
  vtkIdType EntryWords = 3;

  vtkNew<vtkTextureObject> EntryHeads;
  vtkNew<vtkTextureObject> Color;
  vtkNew<vtkOpenGLFramebufferObject> Framebuffer;
  vtkTiledRayCastStorageBuffer EntryNodes;
  vtkTiledRayCastStorageBuffer EntryCount;
  // The counts of the last two frames: one being written while the other is read. The
  // traversal counts in GPU memory (atomics), then copies them where the CPU reads them.
  vtkTiledRayCastStorageBuffer RayCounts[2];
  vtkTiledRayCastStorageBuffer CountsRead[2];
  bool CountsPending[2] = { false, false };
  std::vector<std::uint32_t> LastCounts; // the latest read, empty before the first
  int CountsBuffer = 0;                  // this frame's
  vtkIdType EntryCapacity = 0;
  int TargetSize[2] = { 0, 0 };
  vtkIdType RaysStopped = 0;
  vtkIdType RaysIncomplete = 0;
  vtkIdType EntriesAsked = 0; // by the latest view counted
  vtkIdType RaysCounted = 0;  // and its rays
  // Whether a frame was verified since the targets were allocated, this frame is, and the
  // mesh the list was last sized for.
  bool Verified = false;
  bool Verifying = false;
  vtkIdType ListedFaces = 0;
  vtkIdType ListedTetrahedra = 0;
  float LastDirection[3] = { 0, 0, 0 };
  double LastCoverage = 0;
  // Inside VTK's depth peeling the list serves every draw of the volume's frame: the traversal
  // leaves the heads as they are for that volume (EntriesKeptFor, null when the traversal set
  // them back to 0), the draws after the first list nothing, and the next listing clears them.
  const void* EntriesKeptFor = nullptr;
  size_t EntriesKeptMembers = 0; // and the volumes of its group (0: alone)
};

#endif
