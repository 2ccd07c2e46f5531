/*=========================================================================

  Program:   TiledRayCast
  Module:    TestTiledRayCastDiscretized.cxx

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// A discretized colour map (vtkDiscretizableColorTransferFunction, 256 steps: ParaView's default
// colour map, in its diverging colour space) is piecewise constant. It used to go through the
// adaptive linearisation, which gave up at 4096 nodes with a warning on every table rebuild
// ("needs more than 4096 linear pieces"), and was approximate at every step. It must now be
// exact (a node pair per step), silent, and match the exact reference, which evaluates the map
// through VTK itself.
#include "TiledRayCastTestScene.h"

#include "vtkDiscretizableColorTransferFunction.h"
#include "vtkTiledRayCastTransferFunction.h"

#include <cmath>
#include <string>

namespace
{
using trctest::Expect;

// ParaView's default map ("Cool to Warm", diverging space, 256 steps) over [lo, hi], with a
// linear opacity ramp that has a node inside a step.
vtkSmartPointer<vtkVolumeProperty> MakeDiscretizedProperty(double lo, double hi, double unit)
{
  vtkNew<vtkDiscretizableColorTransferFunction> color;
  color->AddRGBPoint(lo, 0.231373, 0.298039, 0.752941);
  color->AddRGBPoint(0.5 * (lo + hi), 0.865003, 0.865003, 0.865003);
  color->AddRGBPoint(hi, 0.705882, 0.0156863, 0.14902);
  color->SetColorSpaceToDiverging();
  color->DiscretizeOn();
  color->SetNumberOfValues(256);
  vtkNew<vtkPiecewiseFunction> opacity;
  opacity->AddPoint(lo, 0.0);
  opacity->AddPoint(lo + 0.3001 * (hi - lo), 0.1);
  opacity->AddPoint(hi, 0.8);
  return trcscene::MakeVolumeProperty(color, opacity, unit);
}

// The node list against VTK's own evaluation of the map, away from the steps' edges.
bool CheckNodes(vtkVolumeProperty* property, const double range[2])
{
  vtkNew<vtkTiledRayCastTransferFunction> tf;
  vtkNew<trctest::MessageCounter> warnings;
  tf->AddObserver(vtkCommand::WarningEvent, warnings);
  tf->Update(property, range);
  bool ok = Expect(tf->GetExact(), "a discretized map is represented exactly");
  ok = Expect(tf->GetNumberOfNodes() <= 2 * (257 + 3),
         "at most two nodes per step and opacity node, got " +
           std::to_string(tf->GetNumberOfNodes())) &&
    ok;
  ok = Expect(warnings->Count == 0, "no warning from the node list: " + warnings->Text) && ok;

  auto* color = property->GetRGBTransferFunction(0);
  vtkPiecewiseFunction* opacity = property->GetScalarOpacity(0);
  const double unit = property->GetScalarOpacityUnitDistance(0);
  const double width = range[1] - range[0];
  double worst = 0.0;
  // 997 samples per step width over the range and beyond it, none on a step's edge.
  const int samples = 997 * 256 / 10;
  for (int i = 0; i <= samples; ++i)
  {
    const double s = range[0] - 0.05 * width + 1.1 * width * (i + 0.5) / (samples + 1);
    const double position = (s - range[0]) / width * 256.0;
    if (std::abs(position - std::round(position)) < 1e-6)
    {
      continue;
    }
    double expected[3], actual[3], attenuation;
    color->GetColor(s, expected);
    tf->Evaluate(s, actual, attenuation);
    for (int c = 0; c < 3; ++c)
    {
      worst = std::max(worst, std::abs(expected[c] - actual[c]));
    }
    const double tau = std::max(0.0, opacity->GetValue(s)) / unit;
    worst = std::max(worst, std::abs(tau - attenuation) * unit);
  }
  std::cout << "node list: " << tf->GetNumberOfNodes() << " nodes, largest difference to VTK "
            << worst << "\n";
  ok = Expect(worst < 1e-12, "the node list evaluates as VTK does") && ok;
  return ok;
}
}

int TestTiledRayCastDiscretized(int argc, char* argv[])
{
  vtkSmartPointer<vtkUnstructuredGrid> grid =
    trctest::ReadMesh(argc, argv, "aneurysm_dolfin_38k.vtu");
  if (!grid)
  {
    return EXIT_FAILURE;
  }
  double range[2];
  grid->GetPointData()->GetScalars()->GetRange(range);
  vtkSmartPointer<vtkVolumeProperty> property =
    MakeDiscretizedProperty(range[0], range[1], 0.05 * grid->GetLength());
  bool ok = CheckNodes(property, range);

  trctest::WatchedVolume scene(grid, property, 160);
  scene.Window->Render();
  ok = Expect(scene.Mapper->GetStatistics()->GetRendered(), "rendered") && ok;
  // Partial pre-integration is exact for a piecewise-linear node list: the default bounds.
  ok = trctest::CheckAgainstReference(
         scene.Window, scene.Renderer, scene.Volume, trctest::Bounds(), "discretized map") &&
    ok;
  // A second frame after a change of the map (a rebuild) must be silent too.
  auto* color =
    vtkDiscretizableColorTransferFunction::SafeDownCast(property->GetRGBTransferFunction(0));
  color->SetNumberOfValues(64);
  scene.Window->Render();
  ok =
    Expect(scene.Warnings->Count == 0, "no warning while rendering: " + scene.Warnings->Text) && ok;
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
