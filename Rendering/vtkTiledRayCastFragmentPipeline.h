/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkTiledRayCastFragmentPipeline.h

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
/**
 * @class   vtkTiledRayCastFragmentPipeline
 * @brief   the mapper's fragment pipeline (the paper's): tiles, first hit, peels, ray-cast layers
 *
 * The paper's pipeline, in fragment passes over per-pixel render targets: two ping-pong sets of
 * (state, colour, entry) RGBA32F textures with a shared depth buffer, one framebuffer per set.
 *
 * 1. First hit: the boundary faces (front faces, exact coverage of pixel centres) and, where
 *    the near plane cuts the mesh, the near-plane slices, depth-tested into set 0.
 * 2. Ray-cast layer: per screen tile, rounds of k traversal passes, each round ending with a
 *    Z-update (rays no longer active get depth 0, so later passes skip them) and an occlusion
 *    query counting the tile's active rays; the GPU skips the passes of a tile whose count is
 *    zero (conditional rendering) and the CPU polls the counts without waiting.
 * 3. Peel: the next boundary layer behind where the rays left the mesh; the layers go on until a
 *    peel finds no re-entry (the one wait of the CPU per layer).
 * 4. Composite: every tile brought to set 0, the opaque and entered rays counted, the colour
 *    blended into the caller's framebuffer.
 *
 * The mapper sets the frame's, the mesh's and the integration's uniforms through
 * vtkTiledRayCastProgramSetup, as for vtkTiledRayCastComputePipeline. Private to the module:
 * not wrapped, not installed.
 */

#ifndef vtkTiledRayCastFragmentPipeline_h
#define vtkTiledRayCastFragmentPipeline_h

#include "vtkNew.h"                          // For vtkNew
#include "vtkTiledRayCastOcclusionQueries.h" // For the occlusion queries
#include "vtkType.h"                         // For vtkIdType

#include <string>  // For std::string
#include <utility> // For std::pair
#include <vector>  // For std::vector

class vtkObject;
class vtkOpenGLFramebufferObject;
class vtkOpenGLRenderWindow;
class vtkOpenGLState;
class vtkOpenGLVertexArrayObject;
class vtkShaderProgram;
class vtkTextureObject;
class vtkTiledRayCastPhaseTimers;
class vtkTiledRayCastProgramSetup;
class vtkTiledRayCastStatistics;
class vtkWindow;

class vtkTiledRayCastFragmentPipeline
{
public:
  vtkTiledRayCastFragmentPipeline();
  ~vtkTiledRayCastFragmentPipeline();

  using Replacements = std::vector<std::pair<std::string, std::string>>;

  /**
   * Build (or keep) the programs from the mapper's GLSL pieces: `version` replaces
   * //TRC::Version, `common` replaces //TRC::Common::Dec, //TRC::Layout::Dec and
   * //TRC::Integration::Dec. False with a message when a program does not compile.
   */
  bool UpdatePrograms(vtkOpenGLRenderWindow* window, const std::string& version,
    const Replacements& common, std::string& error);

  /**
   * Render targets for an image of this size. They only grow: renderers of different sizes in
   * one window share them, each using the lower-left pixels. False with a message when the GPU
   * cannot allocate them.
   */
  bool UpdateTargets(vtkOpenGLRenderWindow* window, int width, int height, std::string& error);

  /**
   * What one frame draws.
   */
  struct Frame
  {
    vtkOpenGLRenderWindow* Window = nullptr;
    vtkObject* Reporter = nullptr; // warnings and OpenGL errors are reported as its own
    int Width = 0;                 // the rays: the image
    int Height = 0;
    int Viewport[4] = { 0, 0, 0, 0 }; // the caller's, which compositing draws into
    vtkIdType NumberOfBoundaryFaces = 0;
    vtkIdType NumberOfTetrahedra = 0;
    bool NearPlaneCutsMesh = false;
    bool Mirrored = false;
    int MaximumSteps = 0;
    float PeelEpsilon = 0;
    int TileSize = 0; // 0: one tile
    int TetsPerPass = 0;
    int OcclusionQueryInterval = 1;
    int MaximumPassesPerLayer = 0;
  };

  /**
   * The GPU work of a frame, from the first hit to compositing into the caller's framebuffer,
   * with the statistics of its layers, passes, tiles and rays. The caller has pushed the
   * framebuffer bindings, set the viewport to the image and activated the textures; Render pops
   * the bindings before compositing.
   */
  void Render(const Frame& frame, vtkTiledRayCastProgramSetup& setup,
    vtkTiledRayCastPhaseTimers& timers, vtkTiledRayCastStatistics* stats);

  /**
   * The render targets as textures the passes read.
   */
  void ActivateTextures(bool activate);

  /**
   * GPU memory per pixel: two sets of state, colour and entry (16 B each) and two depth
   * buffers.
   */
  static vtkIdType GetBytesPerPixel() { return 2 * 48 + 8; }

  /**
   * The per-pixel targets only (when the mapper changes to the compute pipeline).
   */
  void ReleaseTargets(vtkWindow* window);
  void ReleaseGraphicsResources(vtkWindow* window);

private:
  vtkTiledRayCastFragmentPipeline(const vtkTiledRayCastFragmentPipeline&) = delete;
  void operator=(const vtkTiledRayCastFragmentPipeline&) = delete;

  // A program of the window's shader cache (the cache owns it) and the empty vertex array every
  // draw binds: vertices are generated from gl_VertexID.
  struct Program
  {
    vtkShaderProgram* Shader = nullptr;
    vtkNew<vtkOpenGLVertexArrayObject> VAO;
    std::string Key;
    void Release();
  };

  // A screen tile, in pixels of the image.
  struct Tile
  {
    int X0, Y0, X1, Y1;
    int Parity = 0;                 // which of the two target sets holds its latest state
    int Passes = 0;                 // ray-casting passes run this frame
    bool Running = false;           // still has rays to advance in the current layer
    unsigned int LastQuery = 0;     // latest count of the tile's active rays
    unsigned int PreviousQuery = 0; // the count before it
  };

  // Ray-casting passes issued, and the tile count they were conditioned on: the GPU skipped
  // them when that count was zero.
  struct PassBlock
  {
    size_t TileIndex;
    unsigned int Condition;
    int Passes;
  };

  void MakeTiles();
  vtkShaderProgram* Use(vtkOpenGLRenderWindow* window, Program& program);
  void SetTargetUniforms(vtkShaderProgram* program, int parity);
  void DrawRectangle(Program& program, int x0, int y0, int x1, int y1);
  void DrawViewport(Program& program);
  void BindTargets(vtkOpenGLState* state, int parity);
  bool RenderFirstHit(vtkOpenGLRenderWindow* window);
  unsigned int Peel(vtkOpenGLRenderWindow* window);
  void RayCastLayer(vtkOpenGLRenderWindow* window);
  void CountActiveRays(vtkOpenGLRenderWindow* window, Tile& tile);
  void CopyTile(vtkOpenGLRenderWindow* window, Tile& tile, bool markInactive);
  void MakeTilesIdentical(vtkOpenGLRenderWindow* window);
  void Composite(vtkOpenGLRenderWindow* window);
  void FinishStatistics();

  // Programs.
  Program FirstHitProgram, PeelProgram, NearSliceProgram, TraversalProgram, CopyProgram,
    CountProgram, CompositeProgram;

  // Render targets: two ping-pong sets of (state, colour, entry) and a shared depth buffer.
  vtkNew<vtkTextureObject> State[2];
  vtkNew<vtkTextureObject> Color[2];
  vtkNew<vtkTextureObject> Entry[2];
  vtkNew<vtkTextureObject> Depth;
  vtkNew<vtkOpenGLFramebufferObject> Framebuffer[2];
  int TargetSize[2] = { 0, 0 };

  vtkTiledRayCastOcclusionQueries Queries;
  std::vector<Tile> Tiles;
  std::vector<PassBlock> PassBlocks;
  unsigned int NearPlaneQuery = 0;

  // The frame being rendered (during Render only).
  const Frame* Current = nullptr;
  vtkTiledRayCastProgramSetup* Setup = nullptr;
  vtkTiledRayCastStatistics* Stats = nullptr;
};

#endif
// VTK-HeaderTest-Exclude: vtkTiledRayCastFragmentPipeline.h
