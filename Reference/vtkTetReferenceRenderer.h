/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkTetReferenceRenderer.h

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
/**
 * @class   vtkTetReferenceRenderer
 * @brief   exact CPU volume rendering of a tetrahedral mesh: the project's oracle
 *
 * Renders what a vtkUnstructuredGridVolumeMapper should show for a mesh, a volume property, a
 * camera and an image size, in double precision on the CPU, without approximation beyond
 * rounding and the stated tolerance of vtkTetRayIntegrator. Every accuracy figure of the project
 * is measured against it, so it shares no traversal code with the GPU path and needs no mesh
 * topology: its module (TiledRayCast::Reference) links neither the mesh module nor the GPU one,
 * and a test checks it on the link line. What it shares with them, in TiledRayCast::Integration,
 * is the definition of the image: the rule that picks the scalar a property takes from an array
 * (vtkTetScalarSelection), so that both render the same field, and the exact segment integral
 * (vtkTetRayIntegrator), which the GPU module's pre-integration tables also use.
 *
 * Per pixel, one ray runs from the near to the far plane through the pixel's sample position
 * (its centre by default), as docs/design.md fixes it. A bounding volume hierarchy over all
 * tetrahedra yields candidates; each candidate is tested exactly, in a frame where the ray is
 * the z axis: the six edges of the tetrahedron are classified against the ray by the exact sign
 * of a 2x2 determinant of the transformed vertices (ties broken by Simulation of Simplicity),
 * which identifies its entry and exit faces. Because an edge's sign depends only on its two
 * vertices, every tetrahedron sharing an edge or a face agrees on it: rays through vertices,
 * along edges and inside face planes are neither lost nor counted twice. The entry and exit
 * points are computed from each face's three vertices in a canonical order (sorted point ids),
 * with an exact-arithmetic fallback for faces nearly parallel to the ray, so that two
 * tetrahedra sharing a face get bitwise the same crossing and their intervals meet exactly.
 * The intervals, clipped to the near plane and to the opaque depth, are sorted along the ray
 * and integrated exactly (vtkTetRayIntegrator), then composited front to back in exact optical
 * depth. This handles non-convex meshes, cavities, cracks, overlapping cells (composited in
 * order of entry), a camera inside the mesh and degenerate cells (zero volume: skipped).
 * Tetrahedra that overlap through a shared face (on the same side of it: a face of three
 * tetrahedra, a cell listed twice) follow the mesh builder's rule, written again here: all but
 * the first in input order on each side of the face are left out.
 *
 * Inputs are those of a volume mapper: a vtkDataSet (unstructured grids of tetrahedra are used
 * as they are; other 3D cells are split with vtkDataSetTriangleFilter; cells of lower dimension
 * are ignored), scalars chosen as VTK's mappers choose them (vtkAbstractMapper::GetScalars),
 * reduced to one scalar by the mapper's rule (vtkTetScalarSelection: the colour function's
 * VectorMode by default), a volume property (first component), a camera, the image size (aspect
 * ratio = width / height), the volume's matrix (lengths are measured in world coordinates, after
 * it) and an optional opaque depth buffer (window z in [0, 1] per pixel, 1 meaning no geometry).
 *
 * The output is a vtkImageData of width x height pixels (row 0 at the bottom) with a float
 * "RGBA" point array (double on request) holding premultiplied colour and opacity, and an int
 * "NumberOfTets" array counting the tetrahedra crossed by each ray over a positive length
 * (transparent ones included). CompositeOverBackground() and ConvertToUnsignedChar() turn it into
 * the image a window would show over a background colour; CompareImages() measures the difference
 * of two RGB images in 1/255 units.
 *
 * Scenes (docs/reference-renderer.md, "Scenes"): AddVolume() adds more volumes, each with its
 * own mesh, property, scalars and matrix (vtkTetReferenceVolume), rendered together with the
 * renderer's own input (when set): along each ray the tetrahedra of all of them are merged in
 * depth order, and where media overlap the volume rendering integral is that of the sum of
 * their attenuations with emission sum(tau_i c_i) (vtkTetRayIntegrator::IntegrateMixture;
 * docs/design.md, "Overlapping media"). AddTranslucentLayer() adds translucent geometry as
 * layers of one premultiplied RGBA fragment per pixel at a window depth: fragments are
 * composited in depth order with the volumes (a fragment inside a tetrahedron splits its
 * segment there) and, like volumes, end at the opaque depth. A render with one volume and no
 * layer is exactly the single-volume render.
 *
 * Rays run in parallel with vtkSMPTools; the mesh preparation (triangulation, orientation,
 * hierarchy) is cached until the input, the scalar selection or the volume matrix changes.
 *
 * @sa vtkTetRayIntegrator vtkTetReferenceVolume
 */

#ifndef vtkTetReferenceRenderer_h
#define vtkTetReferenceRenderer_h

#include "vtkObject.h"
#include "vtkTetReferenceVolume.h"          // For the inline forwarders to the own volume
#include "vtkTiledRayCastReferenceModule.h" // For export macro

class vtkCamera;
class vtkDataArray;
class vtkDataSet;
class vtkPlaneCollection;
class vtkFloatArray;
class vtkImageData;
class vtkLightCollection;
class vtkMatrix4x4;
class vtkTetRayIntegrator;
class vtkVolume;
class vtkVolumeProperty;

class VTKTILEDRAYCASTREFERENCE_EXPORT vtkTetReferenceRenderer : public vtkObject
{
public:
  static vtkTetReferenceRenderer* New();
  vtkTypeMacro(vtkTetReferenceRenderer, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * The latest of the renderer's own modification time and its own volume's (input, property,
   * matrix and scalar selection are set there).
   */
  vtkMTimeType GetMTime() override;

  ///@{
  /**
   * The mesh to render.
   */
  void SetInputData(vtkDataSet* input) { this->Own->SetInputData(input); }
  vtkDataSet* GetInput() { return this->Own->GetInput(); }
  ///@}

  /**
   * Which scalars to render and how a multi-component array becomes one scalar, as a mapper's
   * (vtkTetScalarSelection, held by the renderer's own volume): scalar mode
   * (VTK_SCALAR_MODE_DEFAULT, USE_POINT_DATA, USE_CELL_DATA, USE_POINT_FIELD_DATA,
   * USE_CELL_FIELD_DATA) and, for the field data modes, the array by index or by name;
   * VectorMode DEFAULT (the default) follows the colour transfer function's own VectorMode and
   * VectorComponent as VTK's unstructured mappers do, COMPONENT (component VectorComponent) or
   * MAGNITUDE override it. Components the property would blend or read as dependent are refused
   * with an error. A mapper's settings are taken in one call:
   * `reference->GetScalarSelection()->CopySettings(mapper->GetScalarSelection())`.
   */
  vtkTetScalarSelection* GetScalarSelection() { return this->Own->GetScalarSelection(); }

  ///@{
  /**
   * The volume property (its first component is rendered). When none is set, the property of
   * the volume given with SetVolume() is used.
   */
  void SetVolumeProperty(vtkVolumeProperty* property) { this->Own->SetVolumeProperty(property); }
  vtkVolumeProperty* GetVolumeProperty() { return this->Own->GetVolumeProperty(); }
  ///@}

  ///@{
  /**
   * The camera.
   */
  void SetCamera(vtkCamera* camera);
  vtkGetObjectMacro(Camera, vtkCamera);
  ///@}

  ///@{
  /**
   * The lights of shading (vtkVolumeProperty::ShadeOn, docs/design.md "Shading"), as a
   * renderer's (vtkRenderer::GetLights(); kept by reference), and whether lighting is two-sided
   * (vtkRenderer::GetTwoSidedLighting(), default on). Every light is directional; headlights
   * follow the camera and camera lights are placed by it, as the renderer places them. No
   * lights: a shaded volume gets the ambient term alone. Shading and gradient opacity (the
   * property's, scaling each tetrahedron's attenuation by its gradient's magnitude in scalar
   * units per world unit) apply to the composite blend mode of one volume; a scene
   * (AddVolume(), AddTranslucentLayer()) refuses a property with either.
   */
  void SetLights(vtkLightCollection* lights);
  vtkGetObjectMacro(Lights, vtkLightCollection);
  vtkSetMacro(TwoSidedLighting, vtkTypeBool);
  vtkGetMacro(TwoSidedLighting, vtkTypeBool);
  vtkBooleanMacro(TwoSidedLighting, vtkTypeBool);
  ///@}

  ///@{
  /**
   * Image size in pixels (default 256 x 256); the aspect ratio is width / height.
   */
  vtkSetVector2Macro(ImageSize, int);
  vtkGetVector2Macro(ImageSize, int);
  ///@}

  ///@{
  /**
   * The model-to-world matrix of the volume (copied; nullptr means identity, the default).
   * SetVolume() takes the matrix of a vtkVolume at each Render() instead, and wins over this.
   */
  void SetVolumeMatrix(vtkMatrix4x4* matrix) { this->Own->SetMatrix(matrix); }
  vtkMatrix4x4* GetVolumeMatrix() { return this->Own->GetMatrix(); }
  void SetVolume(vtkVolume* volume) { this->Own->SetVolume(volume); }
  vtkVolume* GetVolume() { return this->Own->GetVolume(); }
  ///@}

  ///@{
  /**
   * Blend mode (vtkVolumeMapper's values: composite, the default; maximum, minimum and average
   * intensity; additive) and the scalar range averaged, as vtkTiledRayCastVolumeMapper defines
   * them (vtkTetReferenceBlending computes them from the property's own functions).
   */
  vtkSetMacro(BlendMode, int);
  vtkGetMacro(BlendMode, int);
  vtkSetVector2Macro(AverageIPScalarRange, double);
  vtkGetVectorMacro(AverageIPScalarRange, double, 2);
  ///@}

  ///@{
  /**
   * Optional clipping planes in world coordinates, as a mapper's (vtkAbstractMapper): each
   * keeps the half-space its normal points into, and every ray is cut exactly to the
   * intersection of the kept half-spaces. Any number of planes.
   */
  void SetClippingPlanes(vtkPlaneCollection* planes);
  vtkGetObjectMacro(ClippingPlanes, vtkPlaneCollection);
  ///@}

  ///@{
  /**
   * Optional opaque geometry: width x height window z values in [0, 1] (as read from VTK's depth
   * buffer, row 0 at the bottom); each ray ends at its pixel's depth, and 1 means no geometry.
   */
  void SetOpaqueDepth(vtkFloatArray* depth);
  vtkGetObjectMacro(OpaqueDepth, vtkFloatArray);
  ///@}

  ///@{
  /**
   * Where each pixel is sampled, in pixels from its lower left corner: (0.5, 0.5), the centre,
   * is the project's convention and the default. (0, 0) samples pixel corners, as VTK's Bunyk
   * ray caster does; only comparisons with such renderers should change it.
   */
  vtkSetVector2Macro(SampleOffset, double);
  vtkGetVector2Macro(SampleOffset, double);
  ///@}

  ///@{
  /**
   * Store "RGBA" as doubles instead of floats (default off). The integration is done in double
   * precision either way; tests that assert bounds tighter than float rounding (6e-8) use this.
   */
  vtkSetMacro(DoublePrecisionOutput, vtkTypeBool);
  vtkGetMacro(DoublePrecisionOutput, vtkTypeBool);
  vtkBooleanMacro(DoublePrecisionOutput, vtkTypeBool);
  ///@}

  ///@{
  /**
   * More volumes in the scene, rendered with the renderer's own input (when it has one) in one
   * pass: each is a mesh with its own property, scalar selection and matrix
   * (vtkTetReferenceVolume). AddVolume(input, property, matrix) makes one (the matrix copied,
   * nullptr for identity) and returns it, for further settings; AddVolume(volume) adds a given
   * one (kept by reference: later changes to it are seen at the next Render()). Volumes are
   * numbered in the order they render their errors: 0 is the renderer's own input when set,
   * then the added ones. Only the composite blend mode renders several volumes.
   */
  vtkTetReferenceVolume* AddVolume(
    vtkDataSet* input, vtkVolumeProperty* property, vtkMatrix4x4* matrix = nullptr);
  void AddVolume(vtkTetReferenceVolume* volume);
  void RemoveAllVolumes();
  int GetNumberOfAddedVolumes();
  vtkTetReferenceVolume* GetAddedVolume(int i);
  ///@}

  ///@{
  /**
   * Translucent geometry: a layer holds at most one fragment per pixel, @a rgba (4 components,
   * premultiplied, alpha in [0, 1]; width x height tuples, row 0 at the bottom) at window depth
   * @a depth (width x height values in [0, 1], as a depth buffer; 1 means no fragment). Any
   * number of layers (a depth-peeled surface is one layer per peel); fragments at the same
   * depth composite in the order their layers were added. Fragments behind the opaque depth
   * (not strictly in front of it) are hidden; clipping planes do not cut them. The arrays are
   * kept by reference and checked at Render().
   */
  void AddTranslucentLayer(vtkDataArray* rgba, vtkFloatArray* depth);
  void RemoveAllTranslucentLayers();
  int GetNumberOfTranslucentLayers();
  ///@}

  /**
   * Render. Returns 1 on success; 0 with an error message on bad input (no input, no
   * tetrahedra, no scalars, no property, no camera, a bad image size or depth buffer; in a
   * scene, the same of any added volume, a layer of the wrong size or with values out of range,
   * a blend mode other than composite). On failure the output is an empty image.
   */
  int Render();

  /**
   * The image of the last Render().
   */
  vtkImageData* GetOutput();

  /**
   * The integrator of the renderer's own input (initialised from the property at each Render()
   * where the property changed). Added volumes have integrators of their own.
   */
  vtkTetRayIntegrator* GetIntegrator();

  ///@{
  /**
   * Figures of the last Render(): tetrahedra rendered, zero-volume tetrahedra skipped,
   * overlapping tetrahedra left out (on the same side of a shared face as an earlier one: the
   * mesh builder's rule, docs/mesh-layout.md), seconds spent preparing the mesh (0 when cached)
   * and casting rays. In a scene, the sums over its volumes.
   */
  vtkGetMacro(NumberOfTetrahedra, vtkIdType);
  vtkGetMacro(NumberOfDegenerateTetrahedra, vtkIdType);
  vtkGetMacro(NumberOfOverlappingTetrahedra, vtkIdType);
  vtkGetMacro(LastPreparationTime, double);
  vtkGetMacro(LastRayCastTime, double);
  ///@}

  /**
   * Composite a premultiplied "RGBA" image (as GetOutput() gives) over a background colour:
   * @a output gets a float "RGB" point array = C + (1 - alpha) background.
   */
  static void CompositeOverBackground(
    vtkImageData* rgba, const double background[3], vtkImageData* output);

  /**
   * Composite over a background (as above) and convert to an unsigned char "RGB" array the way
   * a framebuffer stores colours (clamp to [0, 1], times 255, round to nearest).
   */
  static void ConvertToUnsignedChar(
    vtkImageData* rgba, const double background[3], vtkImageData* output);

  /**
   * For comparisons with vtkUnstructuredGridVolumeRayCastMapper (Bunyk): show a reference image
   * rendered with SampleOffset (0, 0) the way VTK's ray-cast image display helper shows that
   * mapper's image. The mapper casts its rays through pixel corners, stores floor(255 C) and
   * floor(255 alpha) in an 8-bit texture and draws it over the viewport with texel centres 0 and
   * W-1 on the viewport's edges, bilinearly, blended premultiplied over the background: screen
   * pixel i shows the corner image at (i + 1/2)(W - 1)/W. @a output gets an unsigned char "RGB"
   * array. What then remains between the two images is the integration itself.
   */
  static void EmulateRayCastImageDisplay(
    vtkImageData* rgba, const double background[3], vtkImageData* output);

  /**
   * Difference of two images of the same size in their first three components, in 1/255
   * units (unsigned char arrays as they are, other types times 255): @a stats gets the root
   * mean square, the 99.9th percentile and the maximum of the per-channel absolute
   * differences. Returns 0 (with an error) when the images cannot be compared.
   */
  static int CompareImages(vtkImageData* a, vtkImageData* b, double stats[3]);

protected:
  vtkTetReferenceRenderer();
  ~vtkTetReferenceRenderer() override;

  // The renderer's own input, property, volume, matrix and scalar selection: volume 0 of a
  // scene, rendered by the same code as the added volumes.
  vtkTetReferenceVolume* Own;
  vtkCamera* Camera;
  int ImageSize[2];
  vtkFloatArray* OpaqueDepth;
  vtkPlaneCollection* ClippingPlanes = nullptr;
  vtkLightCollection* Lights = nullptr;
  vtkTypeBool TwoSidedLighting = 1;
  int BlendMode = 0;
  double AverageIPScalarRange[2] = { -1.0e300, 1.0e300 };
  double SampleOffset[2];
  vtkTypeBool DoublePrecisionOutput;
  vtkImageData* Output;
  vtkTetRayIntegrator* Integrator;

  vtkIdType NumberOfTetrahedra;
  vtkIdType NumberOfDegenerateTetrahedra;
  vtkIdType NumberOfOverlappingTetrahedra = 0;
  double LastPreparationTime;
  double LastRayCastTime;

private:
  vtkTetReferenceRenderer(const vtkTetReferenceRenderer&) = delete;
  void operator=(const vtkTetReferenceRenderer&) = delete;

  // The steps of Render() before the rays are cast (see vtkTetReferenceRenderer.cxx for the
  // private classes that do the work).
  bool CheckInputs(vtkVolumeProperty* property, const float*& depth);
  bool CheckView(const float*& depth);
  bool PrepareMesh(vtkVolumeProperty* property);
  bool InitializeIntegrator(vtkVolumeProperty* property);
  // Render() of a scene: several volumes or translucent layers.
  int RenderScene(vtkVolumeProperty* property);
  void StoreOutput(vtkDataArray* rgba, vtkDataArray* counts);

  class vtkInternals;
  vtkInternals* Internals;
};

#endif
