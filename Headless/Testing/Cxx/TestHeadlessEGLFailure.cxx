/*=========================================================================

  Program:   TiledRayCast
  Module:    TestHeadlessEGLFailure.cxx

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// Failure paths of the EGL window, none of which may crash:
// - an impossible device index set through the API gives one clear error and no context; then
//   Render(), pixel and depth reads, a window-to-image filter, SupportsOpenGL() and
//   ReportCapabilities() all do nothing harmful, and no second error is printed;
// - PLATFORM_DEVICE on a machine without a GPU fails the same way (skipped where there is one);
// - setting a valid choice again lets the window render;
// - an impossible index in VTK_DEFAULT_EGL_DEVICE_INDEX only gives a warning: the window falls
//   back to the automatic choice and renders.
#include "HeadlessTestScene.h"

#include "vtkCommand.h"
#include "vtkFloatArray.h"
#include "vtkHeadlessEGLRenderWindow.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkUnsignedCharArray.h"
#include "vtkWindowToImageFilter.h"

#include <cstdlib>
#include <cstring>
#include <iostream>
#include <string>
#include <vector>

namespace
{
// Collects error and warning messages instead of printing them (the test driver fails a test
// whose output holds "ERROR:").
class MessageCollector : public vtkCommand
{
public:
  static MessageCollector* New() { return new MessageCollector; }
  void Execute(vtkObject*, unsigned long event, void* data) override
  {
    const std::string text = data ? static_cast<const char*>(data) : "";
    (event == vtkCommand::ErrorEvent ? this->Errors : this->Warnings).push_back(text);
  }
  std::vector<std::string> Errors;
  std::vector<std::string> Warnings;
};

bool Contains(const std::vector<std::string>& messages, const char* text)
{
  for (const auto& message : messages)
  {
    if (message.find(text) != std::string::npos)
    {
      return true;
    }
  }
  return false;
}

bool RendersSomething(vtkRenderWindow* window)
{
  window->Render();
  vtkNew<vtkUnsignedCharArray> pixels;
  if (window->GetPixelData(0, 0, 299, 299, 0, pixels, 0) != VTK_OK)
  {
    return false;
  }
  // The red sphere covers thousands of pixels; the background has red 0.1.
  int red = 0;
  for (vtkIdType i = 0; i < 300 * 300; ++i)
  {
    red += pixels->GetValue(3 * i) > 150 ? 1 : 0;
  }
  return red > 1000;
}

// Everything a program or a test harness might call on a window without a context.
void UseWithoutContext(vtkHeadlessEGLRenderWindow* window)
{
  window->Render();
  window->Render();
  vtkNew<vtkUnsignedCharArray> pixels;
  window->GetPixelData(0, 0, 9, 9, 0, pixels, 0);
  delete[] window->GetPixelData(0, 0, 9, 9, 1, 0);
  vtkNew<vtkFloatArray> depth;
  window->GetZbufferData(0, 0, 9, 9, depth);
  delete[] window->GetRGBACharPixelData(0, 0, 9, 9, 0, 0);
  window->WaitForCompletion();
  window->MakeCurrent();
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  grab->Update();
}
}

int TestHeadlessEGLFailure(int, char*[])
{
  int failures = 0;
  unsetenv("VTK_DEFAULT_EGL_DEVICE_INDEX");

  // 1. An impossible device index.
  {
    vtkNew<vtkHeadlessEGLRenderWindow> window;
    vtkNew<MessageCollector> messages;
    window->AddObserver(vtkCommand::ErrorEvent, messages);
    window->AddObserver(vtkCommand::WarningEvent, messages);
    HeadlessTestScene::Add(window);
    window->SetDeviceIndex(999);
    UseWithoutContext(window);
    const bool supports = window->SupportsOpenGL() != 0;
    const std::string capabilities = window->ReportCapabilities();
    std::cout << "device 999: " << window->GetInitializationError() << "\n";
    if (window->HasContext() || supports || messages->Errors.size() != 1 ||
      !Contains(messages->Errors, "EGL device index 999 does not exist") ||
      capabilities.find("No EGL context") == std::string::npos ||
      std::strlen(window->GetInitializationError()) == 0)
    {
      std::cerr << "device 999: expected exactly one clear error and no context, got "
                << messages->Errors.size() << " error(s)\n";
      ++failures;
    }

    // 2. A valid choice again: the same window renders.
    window->SetDeviceIndex(-1);
    if (!RendersSomething(window) || !window->HasContext() ||
      std::strlen(window->GetInitializationError()) != 0)
    {
      std::cerr << "the window did not recover after SetDeviceIndex(-1)\n";
      ++failures;
    }
  }

  // 3. PLATFORM_DEVICE needs a GPU (only checked where there is none).
  {
    vtkNew<vtkHeadlessEGLRenderWindow> probe;
    probe->SetPlatformToDevice();
    vtkNew<MessageCollector> messages;
    probe->AddObserver(vtkCommand::ErrorEvent, messages);
    HeadlessTestScene::Add(probe);
    UseWithoutContext(probe);
    if (probe->HasContext())
    {
      std::cout << "PLATFORM_DEVICE found a GPU: " << probe->GetGLRenderer()
                << " (failure path not checked)\n";
    }
    else if (messages->Errors.size() != 1 || !Contains(messages->Errors, "No EGL GPU device"))
    {
      std::cerr << "PLATFORM_DEVICE without a GPU: expected one clear error\n";
      ++failures;
    }
    else
    {
      std::cout << "PLATFORM_DEVICE without a GPU: " << probe->GetInitializationError() << "\n";
    }
  }

  // 4. An impossible index in the environment is only a warning.
  {
    setenv("VTK_DEFAULT_EGL_DEVICE_INDEX", "999", 1);
    vtkNew<vtkHeadlessEGLRenderWindow> window;
    vtkNew<MessageCollector> messages;
    window->AddObserver(vtkCommand::ErrorEvent, messages);
    window->AddObserver(vtkCommand::WarningEvent, messages);
    HeadlessTestScene::Add(window);
    const bool rendered = RendersSomething(window);
    unsetenv("VTK_DEFAULT_EGL_DEVICE_INDEX");
    if (!rendered || !messages->Errors.empty() ||
      !Contains(messages->Warnings, "VTK_DEFAULT_EGL_DEVICE_INDEX=999 ignored"))
    {
      std::cerr << "VTK_DEFAULT_EGL_DEVICE_INDEX=999: expected a warning and a rendered image\n";
      ++failures;
    }
  }
  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
