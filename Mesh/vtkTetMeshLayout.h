/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkTetMeshLayout.h

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
/**
 * @class   vtkTetMeshLayout
 * @brief   a vtkTetMesh packed into the arrays that a GPU mapper uploads as textures
 *
 * A layout turns a vtkTetMesh into a few named, flat arrays (vtkFloatArray or
 * vtkTypeUInt32Array), each meant to become one texture: a texture buffer (1D, one texel per
 * tuple; sampled with texelFetch on a samplerBuffer/usamplerBuffer) or a 2D texture (tuple
 * `row * width + column` is texel (column, row)). Coordinates are single precision, relative to
 * GetShift() (the centre of the mesh bounds), which the mapper folds back into its model matrix
 * in double precision.
 *
 * The mesh arrays (GetArray()) hold what ray traversal reads. The boundary faces, which the
 * mapper rasterises to start rays and peel layers, are one more array (GetBoundaryArray()),
 * kept apart so that both byte counts can be quoted: GetNumberOfBytes() excludes it,
 * GetNumberOfBytesWithBoundary() includes it.
 *
 * Build() packs everything; UpdatePoints() repacks what depends on positions (the mesh's
 * topology unchanged); UpdateScalars() what depends on scalars. An array's MTime changes
 * exactly when its content is rewritten: a mapper re-uploads those arrays and no others. Update()
 * picks the cheapest of the three from the mesh's time stamps and does nothing when the mesh has
 * not changed since. Build() fails, with an error and GetValid() false, when the mesh does not fit
 * the texture limits (SetMaximumTextureSize(), SetMaximumTextureBufferSize() and
 * SetMaximumTextureBuffersPerArray(); the mapper sets the first two from GL_MAX_TEXTURE_SIZE and
 * GL_MAX_TEXTURE_BUFFER_SIZE) or when the mesh is unusable. A texture buffer array larger than
 * one texture buffer is uploaded as several (GetNumberOfTextureBuffers()).
 *
 * @sa vtkTetMeshPaperLayout vtkTetMeshCompactLayout vtkTetMesh
 */

#ifndef vtkTetMeshLayout_h
#define vtkTetMeshLayout_h

#include "vtkObject.h"
#include "vtkSmartPointer.h"           // For vtkSmartPointer
#include "vtkTiledRayCastMeshModule.h" // For export macro
#include "vtkTimeStamp.h"              // For vtkTimeStamp

#include <string> // For std::string
#include <vector> // For std::vector

class vtkDataArray;
class vtkTetMesh;

class VTKTILEDRAYCASTMESH_EXPORT vtkTetMeshLayout : public vtkObject
{
public:
  vtkTypeMacro(vtkTetMeshLayout, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * What kind of texture an array becomes.
   */
  enum ArrayKinds
  {
    TextureBuffer = 0,
    Texture2D = 1
  };

  /**
   * What the last Update() (or Build/UpdatePoints/UpdateScalars) did: a combination of these
   * bits (as vtkTetMeshBuilder's RebuildFlags). UpdatedAll = a full Build().
   */
  enum UpdateKinds
  {
    UpdatedNothing = 0,
    UpdatedScalars = 1,
    UpdatedPoints = 2,
    UpdatedTopology = 4,
    UpdatedAll = 7
  };

  /**
   * Pack the whole mesh. Returns false (with an error) when it cannot: unusable mesh, texture
   * limits exceeded.
   */
  virtual bool Build(vtkTetMesh* mesh) = 0;

  /**
   * Repack what depends on point positions (and the shift); the tetrahedra and their
   * neighbours must not have changed since the last Build(). The default calls Build().
   */
  virtual bool UpdatePoints(vtkTetMesh* mesh);

  /**
   * Repack what depends on the scalars only. The default calls Build().
   */
  virtual bool UpdateScalars(vtkTetMesh* mesh);

  /**
   * Bring the arrays up to date with the mesh, doing the least work its time stamps allow; a
   * changed setting of the layout (texture width or limits) takes a Build().
   */
  bool Update(vtkTetMesh* mesh);

  /**
   * Whether the arrays hold a packed mesh (the last Build() succeeded).
   */
  vtkGetMacro(Valid, bool);

  /**
   * Why the last Build() failed ("" when it did not).
   */
  const char* GetErrorMessage() const { return this->ErrorMessage.c_str(); }

  ///@{
  /**
   * The mesh arrays, in a fixed order documented by each layout. GetArray() returns nullptr
   * for a bad index.
   */
  int GetNumberOfArrays() const { return static_cast<int>(this->Arrays.size()); }
  vtkDataArray* GetArray(int index);
  const char* GetArrayName(int index);
  int GetArrayKind(int index);
  ///@}

  /**
   * Width and height in texels: (width, height) for a 2D texture, (number of texels, 1) for a
   * texture buffer.
   */
  void GetArrayTextureSize(int index, int size[2]);

  ///@{
  /**
   * The boundary faces, one texture buffer (see each layout for its texels).
   */
  vtkDataArray* GetBoundaryArray();
  ///@}

  ///@{
  /**
   * Bytes the GPU holds: the mesh arrays (texels times texel size, padding included), the
   * boundary array, and both; per tetrahedron (0 for an empty mesh).
   */
  vtkIdType GetNumberOfBytes();
  vtkIdType GetNumberOfBoundaryBytes();
  vtkIdType GetNumberOfBytesWithBoundary();
  double GetBytesPerTet();
  double GetBytesPerTetWithBoundary();
  ///@}

  /**
   * The shift the coordinates are relative to (the mesh's, at the last build or points
   * update).
   */
  void GetShift(double shift[3]) const;

  ///@{
  /**
   * Texture limits: the largest width or height of a 2D texture (default 16384), the largest
   * number of texels of a texture buffer (default 2^27) and how many texture buffers one array
   * may be split into (default 8). The mapper sets the first two from the OpenGL context
   * (GL_MAX_TEXTURE_SIZE, GL_MAX_TEXTURE_BUFFER_SIZE: 2^27 on NVIDIA's GPUs, 134M tetrahedra).
   */
  vtkSetClampMacro(MaximumTextureSize, int, 1, VTK_INT_MAX);
  vtkGetMacro(MaximumTextureSize, int);
  vtkSetClampMacro(MaximumTextureBufferSize, vtkIdType, 1, VTK_ID_MAX);
  vtkGetMacro(MaximumTextureBufferSize, vtkIdType);
  vtkSetClampMacro(MaximumTextureBuffersPerArray, int, 1, 64);
  vtkGetMacro(MaximumTextureBuffersPerArray, int);
  ///@}

  ///@{
  /**
   * How a texture buffer array is split: into buffers of GetTextureBufferSize() texels (the
   * largest power of two within MaximumTextureBufferSize, so that a shader finds texel i in
   * buffer i >> GetTextureBufferShift() at i & (size - 1)), the last one shorter.
   * GetNumberOfTextureBuffers() is 1 for a 2D texture, 0 for a bad index.
   */
  int GetTextureBufferShift() const;
  vtkIdType GetTextureBufferSize() const { return vtkIdType(1) << this->GetTextureBufferShift(); }
  int GetNumberOfTextureBuffers(int index);
  ///@}

  /**
   * What the last Update() (or Build/UpdatePoints/UpdateScalars) did (UpdateKinds).
   */
  vtkGetMacro(LastUpdate, int);

  /**
   * Number of tetrahedra packed.
   */
  vtkGetMacro(NumberOfTetrahedra, vtkIdType);

protected:
  vtkTetMeshLayout();
  ~vtkTetMeshLayout() override;

  struct ArrayInfo
  {
    vtkSmartPointer<vtkDataArray> Array;
    int Kind = TextureBuffer;
    int Width = 0; // 2D textures only
  };

  /**
   * Common checks before packing: a usable mesh. Sets the error and returns false otherwise.
   */
  bool CheckMesh(vtkTetMesh* mesh);

  /**
   * Record a failure: error message, vtkErrorMacro, Valid false.
   */
  void Fail(const std::string& message);

  /**
   * Record what was packed (mesh, time stamps, shift) after a successful pass.
   */
  void Packed(vtkTetMesh* mesh, int what);

  std::vector<ArrayInfo> Arrays;
  ArrayInfo Boundary;
  bool Valid = false;
  std::string ErrorMessage;
  double Shift[3] = { 0.0, 0.0, 0.0 };
  int MaximumTextureSize = 16384;
  vtkIdType MaximumTextureBufferSize = vtkIdType(1) << 27;
  int MaximumTextureBuffersPerArray = 8;
  int LastUpdate = UpdatedNothing;
  vtkIdType NumberOfTetrahedra = 0;

  // What the arrays were packed from.
  const vtkTetMesh* PackedMesh = nullptr;
  vtkMTimeType PackedTopologyTime = 0;
  vtkMTimeType PackedPointsTime = 0;
  vtkMTimeType PackedScalarsTime = 0;
  // When the arrays were last packed: a setting changed since (MTime newer) takes a Build().
  vtkTimeStamp PackedTime;
  // The mesh (and its time) of the last attempt, and when it failed: Update() does not repeat
  // a failure (nor its error message) while nothing changed.
  const vtkTetMesh* FailedMesh = nullptr;
  vtkMTimeType FailedMeshTime = 0;
  vtkTimeStamp FailedTime;

private:
  vtkTetMeshLayout(const vtkTetMeshLayout&) = delete;
  void operator=(const vtkTetMeshLayout&) = delete;
};

#endif
