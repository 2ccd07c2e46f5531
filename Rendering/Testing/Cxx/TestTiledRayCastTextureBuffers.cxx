/*=========================================================================

  Program:   TiledRayCast
  Module:    TestTiledRayCastTextureBuffers.cxx

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// A mesh larger than one texture buffer. NVIDIA's GL_MAX_TEXTURE_BUFFER_SIZE is 2^27 texels: above
// 134M tetrahedra every array of the compact layout is split over several texture buffers (texel
// i in buffer i >> shift, at i & mask), and before that no such mesh could be drawn. Here the
// mapper's MaximumTextureBufferSize splits the blunt fin's arrays (187,318 tetrahedra, 40,921
// points) as a billion tetrahedra's are on such a GPU: 2^16 texels a buffer, 3 buffers per
// tetrahedron array and one for the points, then 2^15, 6 and 2. Every image must equal the
// unsplit one pixel for pixel, and the exact reference, in both pipelines, with point and cell
// scalars and in a group of two overlapping volumes; at 2^14, 12 buffers per array, more than
// the 8 allowed (2^30 tetrahedra on NVIDIA's GPUs), the mesh is refused with a message that
// names the sizes. Arrays staged through mapped host memory draw the same.
#include "TiledRayCastTestScene.h"

#include "vtkTesting.h"
#include "vtkTiledRayCastStagedUpload.h"

namespace
{
using trctest::Expect;

vtkSmartPointer<vtkUnsignedCharArray> Pixels(vtkRenderWindow* window)
{
  int* size = window->GetSize();
  vtkSmartPointer<vtkUnsignedCharArray> pixels = vtkSmartPointer<vtkUnsignedCharArray>::New();
  window->GetPixelData(0, 0, size[0] - 1, size[1] - 1, 0, pixels, 0);
  return pixels;
}

int LargestDifference(vtkUnsignedCharArray* a, vtkUnsignedCharArray* b)
{
  int largest = 0;
  for (vtkIdType i = 0; i < a->GetNumberOfValues(); ++i)
  {
    largest = std::max(largest, std::abs(int(a->GetValue(i)) - int(b->GetValue(i))));
  }
  return largest;
}

struct Scene
{
  vtkNew<vtkRenderWindow> Window;
  vtkNew<vtkRenderer> Renderer;
  std::vector<vtkSmartPointer<vtkTiledRayCastVolumeMapper>> Mappers;
  std::vector<vtkSmartPointer<vtkVolume>> Volumes;

  Scene(vtkDataSet* grid, int pipeline, int volumes)
  {
    this->Window->SetMultiSamples(0);
    this->Window->SetSize(240, 240);
    this->Window->AddRenderer(this->Renderer);
    for (int v = 0; v < volumes; ++v)
    {
      auto mapper = vtkSmartPointer<vtkTiledRayCastVolumeMapper>::New();
      mapper->SetInputData(grid);
      mapper->SetPipeline(pipeline);
      auto volume = vtkSmartPointer<vtkVolume>::New();
      volume->SetMapper(mapper);
      volume->SetProperty(trctest::MakePropertyFor(grid, 0.02));
      // The second volume overlaps the first, moved by a fifth of the fin's length.
      volume->SetPosition(0.2 * v * grid->GetLength(), 0.0, 0.0);
      this->Renderer->AddVolume(volume);
      this->Mappers.push_back(mapper);
      this->Volumes.push_back(volume);
    }
    this->Renderer->ResetCamera();
    trctest::LookFrom(this->Renderer->GetActiveCamera(), 30, 20);
    this->Renderer->ResetCamera();
  }

  void SetBufferSize(vtkIdType texels)
  {
    for (auto& mapper : this->Mappers)
    {
      mapper->SetMaximumTextureBufferSize(texels);
    }
  }
};

// Unsplit, then split at 2^16 and 2^15 texels a buffer: equal images, and the reference.
bool SplitEqualsWhole(vtkDataSet* grid, int pipeline, const std::string& what)
{
  Scene scene(grid, pipeline, 1);
  scene.Window->Render();
  vtkSmartPointer<vtkUnsignedCharArray> whole = Pixels(scene.Window);
  vtkTiledRayCastStatistics* stats = scene.Mappers[0]->GetStatistics();
  const int arrays = stats->GetNumberOfMeshTextures();
  bool ok = Expect(arrays == 3 || arrays == 4, what + ": one texture buffer per array unsplit");
  const int cellArrays = arrays - 1; // TetPoints, TetNeighbors (and TetScalars); Points
  const struct
  {
    vtkIdType Texels;
    int TetBuffers;
    int PointBuffers;
  } splits[] = { { 1 << 16, 3, 1 }, { 1 << 15, 6, 2 } };
  for (const auto& split : splits)
  {
    scene.SetBufferSize(split.Texels);
    scene.Window->Render();
    const std::string label = what + ", buffers of " + std::to_string(split.Texels) + " texels";
    const int expected = cellArrays * split.TetBuffers + split.PointBuffers;
    ok = Expect(stats->GetNumberOfMeshTextures() == expected,
           label + ": " + std::to_string(expected) + " texture buffers, not " +
             std::to_string(stats->GetNumberOfMeshTextures())) &&
      ok;
    const int difference = LargestDifference(Pixels(scene.Window), whole);
    std::cout << label << ": largest difference to the unsplit image " << difference << "\n";
    ok = Expect(difference == 0, label + ": the same image as unsplit") && ok;
    ok = trctest::CheckAgainstReference(
           scene.Window, scene.Renderer, scene.Volumes[0], trctest::Bounds(), label.c_str()) &&
      ok;
  }
  return ok;
}

// Two overlapping volumes traversed together (the group's shader renames each member's texture
// buffers): split the same as unsplit.
bool GroupSplitEqualsWhole(vtkDataSet* grid)
{
  Scene scene(grid, vtkTiledRayCastVolumeMapper::COMPUTE_PIPELINE, 2);
  scene.Window->Render();
  vtkSmartPointer<vtkUnsignedCharArray> whole = Pixels(scene.Window);
  bool ok = Expect(scene.Mappers[0]->GetStatistics()->GetNumberOfGroupedVolumes() == 2,
    "group: the two volumes are traversed together");
  scene.Mappers[1]->SetMaximumTextureBufferSize(1 << 15);
  scene.Window->Render();
  const int difference = LargestDifference(Pixels(scene.Window), whole);
  std::cout << "group, one member split: largest difference to the unsplit image " << difference
            << "\n";
  ok = Expect(scene.Mappers[1]->GetStatistics()->GetNumberOfMeshTextures() == 14,
         "group: the second member in 14 texture buffers") &&
    ok;
  return Expect(difference == 0, "group: the same image as unsplit") && ok;
}

// Arrays sent through mapped host memory (vtkTiledRayCastStagedUpload, from 64 MiB on: 4M
// tetrahedra) draw what arrays sent by glBufferData draw. Here every array is staged, in chunks
// of 40,000 bytes (the fin's arrays take 75 chunks, so the three host buffers are reused behind
// their fences, and the last chunk of each array is short), unsplit and split.
bool StagedEqualsDirect(vtkDataSet* grid)
{
  Scene direct(grid, vtkTiledRayCastVolumeMapper::COMPUTE_PIPELINE, 1);
  direct.Window->Render();
  vtkSmartPointer<vtkUnsignedCharArray> whole = Pixels(direct.Window);
  const size_t minimum = vtkTiledRayCastStagedUpload::GetMinimumStagedBytes();
  const size_t chunk = vtkTiledRayCastStagedUpload::GetChunkBytes();
  vtkTiledRayCastStagedUpload::SetSizes(0, 40000);
  vtkTiledRayCastStagedUpload::SetStageOnSoftwareRasterizers(true); // llvmpipe too
  bool ok = true;
  for (vtkIdType texels : { vtkIdType(0), vtkIdType(1) << 15 })
  {
    Scene staged(grid, vtkTiledRayCastVolumeMapper::COMPUTE_PIPELINE, 1);
    staged.SetBufferSize(texels);
    staged.Window->Render();
    const std::string label = std::string("staged upload") + (texels ? ", split" : "");
    const int difference = LargestDifference(Pixels(staged.Window), whole);
    std::cout << label << ": largest difference to the image uploaded directly " << difference
              << "\n";
    ok = Expect(difference == 0, label + ": the same image as uploaded directly") && ok;
    ok = Expect(staged.Mappers[0]->GetStatistics()->GetMeshUploadTime() > 0,
           label + ": the upload is timed") &&
      ok;
  }
  vtkTiledRayCastStagedUpload::SetSizes(minimum, chunk);
  vtkTiledRayCastStagedUpload::SetStageOnSoftwareRasterizers(false);
  return ok;
}

// 12 buffers per array: refused, once, with the sizes; nothing drawn, nothing crashes.
bool TooManyBuffersRefused(vtkDataSet* grid)
{
  Scene scene(grid, vtkTiledRayCastVolumeMapper::COMPUTE_PIPELINE, 1);
  scene.SetBufferSize(1 << 14);
  vtkNew<trctest::MessageCounter> errors;
  scene.Mappers[0]->AddObserver(vtkCommand::ErrorEvent, errors);
  scene.Mappers[0]->AddObserver(vtkCommand::WarningEvent, errors);
  scene.Window->Render();
  scene.Window->Render();
  // Printed from the mapper's own words on: the "ERROR:" VTK puts before them fails a test.
  const std::string message = errors->LastError;
  const size_t start = message.find("Cannot pack");
  std::cout << "12 buffers per array: "
            << (start == std::string::npos ? message : message.substr(start)) << "\n";
  bool ok = Expect(
    errors->Count == 1, "12 buffers per array: one message, not " + std::to_string(errors->Count));
  ok = Expect(message.find("texture buffers of") != std::string::npos &&
           message.find("187318 tetrahedra") != std::string::npos,
         "12 buffers per array: the error names the sizes") &&
    ok;
  return Expect(!scene.Mappers[0]->GetStatistics()->GetRendered(), "12 buffers: nothing drawn") &&
    ok;
}
}

int TestTiledRayCastTextureBuffers(int argc, char* argv[])
{
  if (!trctest::RenderingSupported())
  {
    std::cout << "OpenGL lacks what the mapper needs: skipped\n";
    return VTK_SKIP_RETURN_CODE;
  }
  vtkSmartPointer<vtkUnstructuredGrid> grid = trctest::ReadMesh(argc, argv, "bluntfin_tets.vtu");
  if (!grid)
  {
    return EXIT_FAILURE;
  }
  bool ok = true;
  for (int pipeline : { vtkTiledRayCastVolumeMapper::COMPUTE_PIPELINE,
         vtkTiledRayCastVolumeMapper::FRAGMENT_PIPELINE })
  {
    const std::string name = pipeline == vtkTiledRayCastVolumeMapper::COMPUTE_PIPELINE
      ? "compute pipeline"
      : "fragment pipeline";
    ok = SplitEqualsWhole(grid, pipeline, name + ", point scalars") && ok;
    ok =
      SplitEqualsWhole(trctest::WithCellScalars(grid, false), pipeline, name + ", cell scalars") &&
      ok;
  }
  ok = GroupSplitEqualsWhole(grid) && ok;
  ok = StagedEqualsDirect(grid) && ok;
  ok = TooManyBuffersRefused(grid) && ok;
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
