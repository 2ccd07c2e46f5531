/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkHeadlessObjectFactory.cxx

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "vtkHeadlessObjectFactory.h"

#include "vtkGenericRenderWindowInteractor.h"
#include "vtkHeadlessEGLRenderWindow.h"
#include "vtkVersion.h"

#if TILEDRAYCAST_HEADLESS_HAS_X
#include "vtkHeadlessXOpenGLRenderWindow.h"
#include "vtkXRenderWindowInteractor.h"
#include <X11/Xlib.h>
#endif

#include <algorithm>
#include <atomic>
#include <cctype>
#include <cstdlib>
#include <cstring>
#include <map>
#include <mutex>
#include <set>
#include <string>

namespace
{
enum class Backend
{
  Automatic,
  EGL,
  Surfaceless,
  X
};

std::atomic<int> RequestedBackend(static_cast<int>(Backend::Automatic));

const char* CanonicalName(Backend backend)
{
  switch (backend)
  {
    case Backend::EGL:
      return "EGL";
    case Backend::Surfaceless:
      return "surfaceless";
    case Backend::X:
      return "X";
    default:
      return "auto";
  }
}

// Names of VTK 9.2+ window classes and of ours, case-insensitively. Returns false for others.
bool ParseBackend(const char* name, Backend& backend)
{
  std::string key = name ? name : "";
  std::transform(key.begin(), key.end(), key.begin(),
    [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (key.empty() || key == "auto" || key == "automatic")
  {
    backend = Backend::Automatic;
  }
  else if (key == "egl" || key == "vtkeglrenderwindow" || key == "vtkheadlesseglrenderwindow")
  {
    backend = Backend::EGL;
  }
  else if (key == "surfaceless" || key == "osmesa" || key == "vtkosopenglrenderwindow" ||
    key == "vtkheadlessosmesarenderwindow")
  {
    // No OSMesa window (docs/headless.md says why): Mesa on the CPU through EGL instead.
    backend = Backend::Surfaceless;
  }
  else if (key == "x" || key == "x11" || key == "glx" || key == "vtkxopenglrenderwindow" ||
    key == "vtkheadlessxopenglrenderwindow")
  {
    backend = Backend::X;
  }
  else
  {
    return false;
  }
  return true;
}

void WarnOnce(const std::string& message)
{
  static std::mutex mutex;
  static std::set<std::string> said;
  {
    std::lock_guard<std::mutex> lock(mutex);
    if (!said.insert(message).second)
    {
      return;
    }
  }
  vtkGenericWarningMacro(<< message);
}

// The backend a window created now gets.
Backend ResolveBackend()
{
  Backend backend = static_cast<Backend>(RequestedBackend.load());
  std::string source = "vtkHeadlessObjectFactory::SetBackend()";
  if (backend == Backend::Automatic)
  {
    const char* environment = std::getenv("VTK_DEFAULT_OPENGL_WINDOW");
    if (environment && *environment)
    {
      source = std::string("VTK_DEFAULT_OPENGL_WINDOW=") + environment;
      if (!ParseBackend(environment, backend))
      {
        WarnOnce(source +
          " names no window this module knows (vtkEGLRenderWindow, vtkOSOpenGLRenderWindow, "
          "vtkXOpenGLRenderWindow): choosing automatically");
        backend = Backend::Automatic;
      }
    }
  }
  const bool display = vtkHeadlessObjectFactory::HasUsableDisplay();
  if (backend == Backend::Automatic)
  {
    return display ? Backend::X : Backend::EGL;
  }
  if (backend == Backend::X && !display)
  {
    const char* value = std::getenv("DISPLAY");
    WarnOnce(source + " asks for the X window, but no X display answers (DISPLAY=" +
      (value ? value : "") + "): using the EGL window");
    return Backend::EGL;
  }
  return backend;
}

vtkObject* CreateRenderWindow()
{
  switch (ResolveBackend())
  {
#if TILEDRAYCAST_HEADLESS_HAS_X
    case Backend::X:
      return vtkHeadlessXOpenGLRenderWindow::New();
#endif
    case Backend::Surfaceless:
    {
      vtkHeadlessEGLRenderWindow* window = vtkHeadlessEGLRenderWindow::New();
      window->SetPlatformToSurfaceless();
      return window;
    }
    default:
      return vtkHeadlessEGLRenderWindow::New();
  }
}

vtkObject* CreateInteractor()
{
#if TILEDRAYCAST_HEADLESS_HAS_X
  if (ResolveBackend() == Backend::X)
  {
    return vtkXRenderWindowInteractor::New();
  }
#endif
  // Talks to no window system: timers and events come from the application, and Start()
  // returns at once instead of running an X event loop.
  return vtkGenericRenderWindowInteractor::New();
}

std::once_flag InstallFlag;
std::atomic<bool> Installed(false);
}

//------------------------------------------------------------------------------
vtkStandardNewMacro(vtkHeadlessObjectFactory);

//------------------------------------------------------------------------------
vtkHeadlessObjectFactory::vtkHeadlessObjectFactory()
{
  this->RegisterOverride("vtkRenderWindow", "vtkHeadlessEGLRenderWindow",
    "EGL window without an X display, X window with one (TiledRayCast::RenderingHeadless)", 1,
    CreateRenderWindow);
  this->RegisterOverride("vtkRenderWindowInteractor", "vtkGenericRenderWindowInteractor",
    "Interactor that needs no X display when the EGL window is in use "
    "(TiledRayCast::RenderingHeadless)",
    1, CreateInteractor);
}

//------------------------------------------------------------------------------
const char* vtkHeadlessObjectFactory::GetVTKSourceVersion()
{
  return VTK_SOURCE_VERSION;
}

//------------------------------------------------------------------------------
const char* vtkHeadlessObjectFactory::GetDescription()
{
  return "TiledRayCast::RenderingHeadless: chooses the X or the EGL render window";
}

//------------------------------------------------------------------------------
void vtkHeadlessObjectFactory::Install()
{
  std::call_once(InstallFlag,
    []()
    {
      vtkHeadlessObjectFactory* factory = vtkHeadlessObjectFactory::New();
      vtkObjectFactory::RegisterFactory(factory);
      factory->Delete();
      // VTK's factories registered earlier answer first: silence their window and interactor
      // overrides so that this factory decides (it makes the X classes itself for X).
      vtkObjectFactory::SetAllEnableFlags(0, "vtkRenderWindow", "vtkXOpenGLRenderWindow");
      vtkObjectFactory::SetAllEnableFlags(
        0, "vtkRenderWindowInteractor", "vtkXRenderWindowInteractor");
      Installed = true;
    });
}

//------------------------------------------------------------------------------
bool vtkHeadlessObjectFactory::IsInstalled()
{
  return Installed;
}

//------------------------------------------------------------------------------
bool vtkHeadlessObjectFactory::SetBackend(const char* name)
{
  Backend backend = Backend::Automatic;
  if (!ParseBackend(name, backend))
  {
    vtkGenericWarningMacro(<< "vtkHeadlessObjectFactory::SetBackend: unknown backend '" << name
                           << "' (use auto, EGL, surfaceless, X or a window class name)");
    return false;
  }
#if !TILEDRAYCAST_HEADLESS_HAS_X
  if (backend == Backend::X)
  {
    vtkGenericWarningMacro(<< "vtkHeadlessObjectFactory::SetBackend: this VTK has no X window");
    return false;
  }
#endif
  RequestedBackend = static_cast<int>(backend);
  return true;
}

//------------------------------------------------------------------------------
const char* vtkHeadlessObjectFactory::GetBackend()
{
  return CanonicalName(static_cast<Backend>(RequestedBackend.load()));
}

//------------------------------------------------------------------------------
const char* vtkHeadlessObjectFactory::GetResolvedWindowClassName()
{
  return ResolveBackend() == Backend::X ? "vtkHeadlessXOpenGLRenderWindow"
                                        : "vtkHeadlessEGLRenderWindow";
}

//------------------------------------------------------------------------------
bool vtkHeadlessObjectFactory::HasUsableDisplay()
{
#if TILEDRAYCAST_HEADLESS_HAS_X
  const char* value = std::getenv("DISPLAY");
  // An X display name has a colon ([host]:display[.screen]). ParaView's --displays puts each
  // rank's entry in DISPLAY, and with EGL those are device indices ("0", "1"): Xlib would read
  // one as a host name and wait on a TCP connection to it for minutes.
  if (!value || !std::strchr(value, ':'))
  {
    return false;
  }
  // Opening a connection costs about a millisecond locally (more for a remote server that does
  // not answer): remember the answer for each DISPLAY value. The connection that answered stays
  // open: an X server that has no client left resets itself (Xvfb under xvfb-run does), and a
  // window connecting during that reset is refused, so closing the probe would make the X window
  // that follows it fail now and then.
  static std::mutex mutex;
  static std::string lastValue;
  static bool lastAnswer = false;
  static std::map<std::string, Display*>* openDisplays = new std::map<std::string, Display*>();
  std::lock_guard<std::mutex> lock(mutex);
  if (lastValue != value)
  {
    auto it = openDisplays->find(value);
    Display* display = (it != openDisplays->end()) ? it->second : XOpenDisplay(value);
    lastAnswer = (display != nullptr);
    if (display)
    {
      (*openDisplays)[value] = display;
    }
    lastValue = value;
  }
  return lastAnswer;
#else
  return false;
#endif
}

//------------------------------------------------------------------------------
void vtkHeadlessObjectFactory::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Backend: " << GetBackend() << "\n";
  os << indent << "ResolvedWindowClassName: " << GetResolvedWindowClassName() << "\n";
}

//------------------------------------------------------------------------------
// Called by VTK's autoinit (vtkAutoInit.h) in every program and Python module that initializes
// TiledRayCast::RenderingHeadless, which implements VTK::RenderingCore.
VTKRENDERINGHEADLESS_EXPORT void vtkRenderingHeadless_AutoInit_Construct();
void vtkRenderingHeadless_AutoInit_Construct()
{
  vtkHeadlessObjectFactory::Install();
}
