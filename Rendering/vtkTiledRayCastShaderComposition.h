/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkTiledRayCastShaderComposition.h

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
/**
 * @class   vtkTiledRayCastShaderComposition
 * @brief   the GLSL pieces both pipelines build their programs from, and when to rebuild them
 *
 * The walk of every program reads the mesh through a layout's access code (compact, with or
 * without cell scalars, or the paper's), integrates with one integration mode's code (partial
 * pre-integration, or a 2D or 3D table; the blend modes', with shading, with gradient opacity)
 * and may skip empty space. Inputs holds what decides these pieces; Changed() is true when they
 * differ from those of the programs last built (Built()), so that the pieces are composed, and
 * the programs compared, only when an input changed rather than every frame.
 * vtkTiledRayCastGroupComposition does the same for the traversal of overlapping volumes.
 *
 * Private to the module: not wrapped, not installed.
 */

#ifndef vtkTiledRayCastShaderComposition_h
#define vtkTiledRayCastShaderComposition_h

#include <string>  // For std::string
#include <utility> // For std::pair
#include <vector>  // For std::vector

class vtkOpenGLRenderWindow;

class vtkTiledRayCastShaderComposition
{
public:
  using Replacements = std::vector<std::pair<std::string, std::string>>;

  /**
   * What decides the programs' GLSL.
   */
  struct Inputs
  {
    vtkOpenGLRenderWindow* Window = nullptr; // whose shader cache holds the programs
    bool Compute = false;                    // which pipeline's programs
    bool PaperLayout = false;
    bool CellScalars = false;
    // The compact layout's texture buffers (vtkTetMeshLayout::GetNumberOfTextureBuffers()): how
    // many per tetrahedron array and for the points, texel i in buffer i >> TextureBufferShift.
    int TextureBufferShift = 0;
    int TetTextureBuffers = 1;
    int PointTextureBuffers = 1;
    int IntegrationMode = -1; // vtkTiledRayCastVolumeMapper's (never automatic)
    int BlendMode = -1;       // vtkVolumeMapper's
    bool Shading = false;
    bool GradientOpacity = false;
    bool SkipEmptySpace = false; // vtkTiledRayCastVisibleMesh's

    bool operator==(const Inputs& other) const;
    bool operator!=(const Inputs& other) const { return !(*this == other); }
  };

  /**
   * The replacements of //TRC::Common::Dec, //TRC::Layout::Dec and //TRC::Integration::Dec;
   * `meshDefinitions` (vtkTiledRayCastVisibleMesh::GetShaderDefinitions(), which SkipEmptySpace
   * stands for in the inputs) go before the common code.
   */
  static Replacements Compose(const Inputs& inputs, const std::string& meshDefinitions);

  /**
   * The declarations of texture buffer array `name` split over `buffers` texture buffers
   * ("in_<name>", "in_<name>_1", ...) and the function trcFetch<name>(uint i) that reads its
   * texel i (of GLSL type `texel`).
   */
  static std::string TextureBufferFetch(
    const char* name, const char* sampler, const char* texel, int buffers, int shift);

  /**
   * Whether `inputs` differ from those of the programs last built (always, before any).
   */
  bool Changed(const Inputs& inputs) const { return !this->Valid || inputs != this->Last; }

  /**
   * The programs of `inputs` are built.
   */
  void Built(const Inputs& inputs)
  {
    this->Last = inputs;
    this->Valid = true;
  }

  /**
   * The programs are gone (released): build them on the next frame.
   */
  void Reset() { this->Valid = false; }

private:
  Inputs Last;
  bool Valid = false;
};

/**
 * The same for the programs of a group of overlapping volumes (vtkTiledRayCastVolumeGroup):
 * they hold every volume's pieces in the group's order, so they are composed again when a
 * volume's inputs change (its layout, cell scalars, integration, blend mode, empty space) or
 * the volumes do (their number or order), and not on a steady frame. Volumes of the same
 * inputs make the same programs whichever mappers they belong to: the key is the inputs alone.
 */
class vtkTiledRayCastGroupComposition
{
public:
  using Inputs = vtkTiledRayCastShaderComposition::Inputs;

  bool Changed(const std::vector<Inputs>& members) const
  {
    return !this->Valid || members != this->Last;
  }
  void Built(const std::vector<Inputs>& members)
  {
    this->Last = members;
    this->Valid = true;
  }
  void Reset() { this->Valid = false; }

private:
  std::vector<Inputs> Last;
  bool Valid = false;
};

#endif
// VTK-HeaderTest-Exclude: vtkTiledRayCastShaderComposition.h
