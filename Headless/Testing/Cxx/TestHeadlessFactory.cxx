/*=========================================================================

  Program:   TiledRayCast
  Module:    TestHeadlessFactory.cxx

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// The choice behind vtkRenderWindow::New() without an X display (the X side is checked by
// TestHeadlessXWindow and TestHeadlessMixedWindows under xvfb-run):
// - DISPLAY unset, empty, or naming a server that does not answer: the EGL window;
// - VTK_DEFAULT_OPENGL_WINDOW: vtkEGLRenderWindow gives EGL, vtkOSOpenGLRenderWindow gives EGL on
//   Mesa's surfaceless platform, vtkXOpenGLRenderWindow gives EGL with a warning (no display), an
//   unknown name gives a warning and the automatic choice;
// - vtkHeadlessObjectFactory::SetBackend() overrides the environment and rejects unknown names;
// - the interactor: the test driver's own vtkTestingInteractor (no X) here, and this module's
//   override gives vtkGenericRenderWindowInteractor, which needs no X either.
#include "vtkCommand.h"
#include "vtkHeadlessEGLRenderWindow.h"
#include "vtkHeadlessObjectFactory.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkOutputWindow.h"
#include "vtkRenderWindow.h"
#include "vtkRenderWindowInteractor.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"

#include <cstdlib>
#include <cstring>
#include <iostream>
#include <string>

namespace
{
int Failures = 0;

void Expect(bool condition, const std::string& what)
{
  std::cout << (condition ? "ok   " : "FAIL ") << what << "\n";
  Failures += condition ? 0 : 1;
}

// The class vtkRenderWindow::New() makes now; the window also has to render.
std::string NewWindowClass(int* platform = nullptr)
{
  vtkSmartPointer<vtkRenderWindow> window =
    vtkSmartPointer<vtkRenderWindow>::Take(vtkRenderWindow::New());
  if (!window)
  {
    return "(null)";
  }
  if (auto* egl = vtkHeadlessEGLRenderWindow::SafeDownCast(window))
  {
    vtkNew<vtkRenderer> renderer;
    window->AddRenderer(renderer);
    window->SetSize(16, 16);
    window->Render();
    if (!egl->HasContext())
    {
      return "EGL window without a context";
    }
    if (platform)
    {
      *platform = egl->GetPlatform();
    }
  }
  return window->GetClassName();
}

// Counts the warnings that static code sends to the output window.
class WarningCounter : public vtkCommand
{
public:
  static WarningCounter* New() { return new WarningCounter; }
  void Execute(vtkObject*, unsigned long, void* data) override
  {
    ++this->Count;
    this->Last = data ? static_cast<const char*>(data) : "";
  }
  int Count = 0;
  std::string Last;
};
}

int TestHeadlessFactory(int, char*[])
{
  Expect(vtkHeadlessObjectFactory::IsInstalled(), "the module's autoinit installed the factory");
  vtkNew<WarningCounter> warnings;
  vtkOutputWindow::GetInstance()->AddObserver(vtkCommand::WarningEvent, warnings);
  unsetenv("VTK_DEFAULT_OPENGL_WINDOW");

  unsetenv("DISPLAY");
  Expect(!vtkHeadlessObjectFactory::HasUsableDisplay(), "DISPLAY unset: no usable display");
  Expect(NewWindowClass() == "vtkHeadlessEGLRenderWindow", "DISPLAY unset: EGL window");
  setenv("DISPLAY", "", 1);
  Expect(NewWindowClass() == "vtkHeadlessEGLRenderWindow", "DISPLAY empty: EGL window");
  setenv("DISPLAY", ":98765", 1);
  Expect(!vtkHeadlessObjectFactory::HasUsableDisplay() &&
      NewWindowClass() == "vtkHeadlessEGLRenderWindow",
    "DISPLAY=:98765 (no server): EGL window");
  // ParaView's --displays sets DISPLAY to an EGL device index: not an X display (no colon),
  // never a TCP connection attempt to a host named "0".
  setenv("DISPLAY", "0", 1);
  Expect(!vtkHeadlessObjectFactory::HasUsableDisplay() &&
      NewWindowClass() == "vtkHeadlessEGLRenderWindow",
    "DISPLAY=0 (ParaView's --displays, an EGL device): EGL window");
  setenv("DISPLAY", ":98765", 1);
  Expect(std::strcmp(vtkHeadlessObjectFactory::GetResolvedWindowClassName(),
           "vtkHeadlessEGLRenderWindow") == 0,
    "GetResolvedWindowClassName() agrees");

  int platform = -1;
  setenv("VTK_DEFAULT_OPENGL_WINDOW", "vtkEGLRenderWindow", 1);
  Expect(NewWindowClass(&platform) == "vtkHeadlessEGLRenderWindow" &&
      platform == vtkHeadlessEGLRenderWindow::PLATFORM_AUTOMATIC,
    "VTK_DEFAULT_OPENGL_WINDOW=vtkEGLRenderWindow: EGL window");
  setenv("VTK_DEFAULT_OPENGL_WINDOW", "vtkOSOpenGLRenderWindow", 1);
  Expect(NewWindowClass(&platform) == "vtkHeadlessEGLRenderWindow" &&
      platform == vtkHeadlessEGLRenderWindow::PLATFORM_SURFACELESS,
    "VTK_DEFAULT_OPENGL_WINDOW=vtkOSOpenGLRenderWindow: EGL window on the surfaceless platform");

  int before = warnings->Count;
  setenv("VTK_DEFAULT_OPENGL_WINDOW", "vtkXOpenGLRenderWindow", 1);
  Expect(NewWindowClass() == "vtkHeadlessEGLRenderWindow" && warnings->Count == before + 1 &&
      warnings->Last.find("no X display answers") != std::string::npos,
    "VTK_DEFAULT_OPENGL_WINDOW=vtkXOpenGLRenderWindow without a display: EGL and one warning");
  before = warnings->Count;
  setenv("VTK_DEFAULT_OPENGL_WINDOW", "vtkNoSuchRenderWindow", 1);
  Expect(NewWindowClass() == "vtkHeadlessEGLRenderWindow" && warnings->Count == before + 1 &&
      warnings->Last.find("names no window") != std::string::npos,
    "VTK_DEFAULT_OPENGL_WINDOW=vtkNoSuchRenderWindow: automatic choice and one warning");

  // The API wins over the environment.
  setenv("VTK_DEFAULT_OPENGL_WINDOW", "vtkEGLRenderWindow", 1);
  Expect(vtkHeadlessObjectFactory::SetBackend("surfaceless") &&
      std::strcmp(vtkHeadlessObjectFactory::GetBackend(), "surfaceless") == 0 &&
      NewWindowClass(&platform) == "vtkHeadlessEGLRenderWindow" &&
      platform == vtkHeadlessEGLRenderWindow::PLATFORM_SURFACELESS,
    "SetBackend(\"surfaceless\") overrides VTK_DEFAULT_OPENGL_WINDOW");
  before = warnings->Count;
  Expect(!vtkHeadlessObjectFactory::SetBackend("Direct3D") &&
      std::strcmp(vtkHeadlessObjectFactory::GetBackend(), "surfaceless") == 0 &&
      warnings->Count == before + 1,
    "SetBackend(\"Direct3D\") is refused and changes nothing");
  Expect(vtkHeadlessObjectFactory::SetBackend(nullptr) &&
      std::strcmp(vtkHeadlessObjectFactory::GetBackend(), "auto") == 0,
    "SetBackend(nullptr) returns to the automatic choice");
  unsetenv("VTK_DEFAULT_OPENGL_WINDOW");

  // Interactors. The test driver switched off every interactor override (ours included) and
  // registered vtkTestingInteractor, which needs no X.
  {
    vtkSmartPointer<vtkRenderWindowInteractor> interactor =
      vtkSmartPointer<vtkRenderWindowInteractor>::Take(vtkRenderWindowInteractor::New());
    Expect(interactor && !interactor->IsA("vtkXRenderWindowInteractor"),
      std::string("test driver interactor needs no X: ") +
        (interactor ? interactor->GetClassName() : "(null)"));
  }
  // With our override enabled again, a program without the test driver gets an interactor that
  // makes no X calls, and whose Start() returns.
  vtkObjectFactory::SetAllEnableFlags(
    1, "vtkRenderWindowInteractor", "vtkGenericRenderWindowInteractor");
  {
    vtkSmartPointer<vtkRenderWindowInteractor> interactor =
      vtkSmartPointer<vtkRenderWindowInteractor>::Take(vtkRenderWindowInteractor::New());
    vtkSmartPointer<vtkRenderWindow> window =
      vtkSmartPointer<vtkRenderWindow>::Take(vtkRenderWindow::New());
    vtkNew<vtkRenderer> renderer;
    window->AddRenderer(renderer);
    interactor->SetRenderWindow(window);
    interactor->Initialize();
    interactor->Start();
    Expect(interactor->IsA("vtkGenericRenderWindowInteractor"),
      std::string("module interactor without X: ") + interactor->GetClassName());
  }
  vtkObjectFactory::SetAllEnableFlags(
    0, "vtkRenderWindowInteractor", "vtkGenericRenderWindowInteractor");

  vtkOutputWindow::GetInstance()->RemoveObserver(warnings);
  return Failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
