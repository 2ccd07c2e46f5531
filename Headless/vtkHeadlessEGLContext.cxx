/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkHeadlessEGLContext.cxx

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "vtkHeadlessEGLContext.h"

#include "vtkHeadlessEGLRenderWindow.h"

#include <sstream>

using DeviceInfo = vtkHeadlessEGLDevices::DeviceInfo;
using EntryPoints = vtkHeadlessEGLDevices::EntryPoints;

//------------------------------------------------------------------------------
// Tries one display: initializes it and creates a context on it. On failure the display is
// released again and `why` says what went wrong.
bool vtkHeadlessEGLContext::TryDisplay(EGLDisplay display, std::string& why)
{
  if (display == EGL_NO_DISPLAY)
  {
    why = "no EGL display: " + vtkHeadlessEGLDevices::LastError();
    return false;
  }
  EGLint major = 0;
  EGLint minor = 0;
  if (!vtkHeadlessEGLDevices::InitializeDisplay(display, &major, &minor))
  {
    why = "eglInitialize failed: " + vtkHeadlessEGLDevices::LastError();
    return false;
  }
  if (major < 1 || (major == 1 && minor < 4))
  {
    why = "EGL 1.4 or later is needed for desktop OpenGL";
    vtkHeadlessEGLDevices::ReleaseDisplay(display);
    return false;
  }
  if (!eglBindAPI(EGL_OPENGL_API))
  {
    why = "this EGL display cannot do desktop OpenGL (eglBindAPI: " +
      vtkHeadlessEGLDevices::LastError() + ")";
    vtkHeadlessEGLDevices::ReleaseDisplay(display);
    return false;
  }
  const char* displayExtensions = eglQueryString(display, EGL_EXTENSIONS);
  const bool surfacelessContext =
    vtkHeadlessEGLDevices::HasExtension(displayExtensions, "EGL_KHR_surfaceless_context");

  EGLConfig config = nullptr;
  bool pbuffer = true;
  if (!this->ChooseConfig(display, surfacelessContext, config, pbuffer))
  {
    why = "no EGL config for an OpenGL context: " + vtkHeadlessEGLDevices::LastError();
    vtkHeadlessEGLDevices::ReleaseDisplay(display);
    return false;
  }
  EGLContext context = CreateCoreContext(display, config);
  if (context == EGL_NO_CONTEXT)
  {
    why = "no OpenGL 3.2 (or later) core profile context: " + vtkHeadlessEGLDevices::LastError();
    vtkHeadlessEGLDevices::ReleaseDisplay(display);
    return false;
  }

  EGLSurface surface = EGL_NO_SURFACE;
  if (pbuffer)
  {
    const EGLint pbufferAttributes[] = { EGL_WIDTH, 1, EGL_HEIGHT, 1, EGL_NONE };
    surface = eglCreatePbufferSurface(display, config, pbufferAttributes);
  }
  if (surface == EGL_NO_SURFACE && !surfacelessContext)
  {
    why = "no pbuffer surface (and no EGL_KHR_surfaceless_context): " +
      vtkHeadlessEGLDevices::LastError();
    eglDestroyContext(display, context);
    vtkHeadlessEGLDevices::ReleaseDisplay(display);
    return false;
  }
  eglGetError();

  this->Display = display;
  this->Context = context;
  this->Surface = surface;
  const char* vendor = eglQueryString(display, EGL_VENDOR);
  const char* version = eglQueryString(display, EGL_VERSION);
  this->EGLVendor = vendor ? vendor : "";
  this->EGLVersion = version ? version : "";
  return true;
}

//------------------------------------------------------------------------------
bool vtkHeadlessEGLContext::TryDevice(
  const std::vector<DeviceInfo>& devices, int index, std::string& why)
{
  const EntryPoints& egl = EntryPoints::Get();
  EGLDisplay display = egl.GetPlatformDisplay(
    EGL_PLATFORM_DEVICE_EXT, devices[static_cast<size_t>(index)].Handle, nullptr);
  if (!this->TryDisplay(display, why))
  {
    return false;
  }
  this->PlatformInUse = "device";
  this->DeviceIndexInUse = index;
  return true;
}

//------------------------------------------------------------------------------
bool vtkHeadlessEGLContext::TrySurfaceless(std::string& why)
{
  const EntryPoints& egl = EntryPoints::Get();
  if (!egl.PlatformSurfaceless)
  {
    why = "Mesa's surfaceless EGL platform (EGL_MESA_platform_surfaceless) is not available";
    return false;
  }
  EGLDisplay display =
    egl.GetPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
  if (!this->TryDisplay(display, why))
  {
    return false;
  }
  this->PlatformInUse = "surfaceless";
  this->DeviceIndexInUse = -1;
  return true;
}

//------------------------------------------------------------------------------
bool vtkHeadlessEGLContext::Create(
  int platform, int requestedIndex, std::string& error, std::string& warnings)
{
  const EntryPoints& egl = EntryPoints::Get();
  std::string why;
  if (platform == vtkHeadlessEGLRenderWindow::PLATFORM_SURFACELESS)
  {
    if (!this->TrySurfaceless(why))
    {
      error = "Cannot use the surfaceless EGL platform: " + why;
      return false;
    }
    return true;
  }

  const std::vector<DeviceInfo> devices = vtkHeadlessEGLDevices::QueryDevices();
  const int count = static_cast<int>(devices.size());
  std::ostringstream errors;

  // An index set through the API is obeyed or fails.
  if (requestedIndex >= 0)
  {
    if (!egl.PlatformDevice)
    {
      error = "EGL device index " + std::to_string(requestedIndex) +
        " requested, but this EGL cannot enumerate devices (EGL_EXT_device_enumeration and "
        "EGL_EXT_platform_device are missing)";
      return false;
    }
    if (requestedIndex >= count)
    {
      error = "EGL device index " + std::to_string(requestedIndex) +
        " does not exist: " + std::to_string(count) + " EGL device(s) found";
      return false;
    }
    if (!this->TryDevice(devices, requestedIndex, why))
    {
      error = "EGL device " + std::to_string(requestedIndex) + " cannot be used: " + why;
      return false;
    }
    return true;
  }

  // The environment's index comes first, with a warning if it does not work.
  const int environmentIndex = vtkHeadlessEGLDevices::EnvironmentDeviceIndex();
  if (environmentIndex >= 0 && egl.PlatformDevice)
  {
    if (environmentIndex >= count)
    {
      warnings += "VTK_DEFAULT_EGL_DEVICE_INDEX=" + std::to_string(environmentIndex) +
        " ignored: " + std::to_string(count) + " EGL device(s) found. ";
    }
    else if (this->TryDevice(devices, environmentIndex, why))
    {
      return true;
    }
    else
    {
      warnings += "VTK_DEFAULT_EGL_DEVICE_INDEX=" + std::to_string(environmentIndex) +
        " ignored: " + why + ". ";
    }
  }

  // The first GPU that gives a context.
  for (int i = 0; egl.PlatformDevice && i < count; ++i)
  {
    if (devices[static_cast<size_t>(i)].Software || i == environmentIndex)
    {
      continue;
    }
    if (this->TryDevice(devices, i, why))
    {
      return true;
    }
    errors << "device " << i << ": " << why << "; ";
  }
  if (platform == vtkHeadlessEGLRenderWindow::PLATFORM_DEVICE)
  {
    std::string tried = errors.str();
    if (tried.size() > 2)
    {
      tried = ", failing: " + tried.substr(0, tried.size() - 2);
    }
    error = "No EGL GPU device could be used (" + std::to_string(count) + " EGL device(s) found" +
      (count ? ", software devices skipped" + tried : "") + ")";
    if (!egl.PlatformDevice)
    {
      error += "; this EGL cannot enumerate devices";
    }
    return false;
  }

  // No GPU: Mesa on the CPU, surfaceless first.
  if (this->TrySurfaceless(why))
  {
    return true;
  }
  errors << "surfaceless: " << why << "; ";
  for (int i = 0; egl.PlatformDevice && i < count; ++i)
  {
    if (!devices[static_cast<size_t>(i)].Software || i == environmentIndex)
    {
      continue;
    }
    if (this->TryDevice(devices, i, why))
    {
      return true;
    }
    errors << "device " << i << ": " << why << "; ";
  }
  if (this->TryDisplay(eglGetDisplay(EGL_DEFAULT_DISPLAY), why))
  {
    this->PlatformInUse = "default";
    this->DeviceIndexInUse = -1;
    return true;
  }
  errors << "default display: " << why;
  error = "No EGL display gives an OpenGL context (" + errors.str() + ")";
  return false;
}

//------------------------------------------------------------------------------
void vtkHeadlessEGLContext::Destroy()
{
  if (this->Display == EGL_NO_DISPLAY)
  {
    return;
  }
  if (eglGetCurrentContext() == this->Context)
  {
    eglMakeCurrent(this->Display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  }
  if (this->Context != EGL_NO_CONTEXT)
  {
    eglDestroyContext(this->Display, this->Context);
  }
  if (this->Surface != EGL_NO_SURFACE)
  {
    eglDestroySurface(this->Display, this->Surface);
  }
  vtkHeadlessEGLDevices::ReleaseDisplay(this->Display);
  this->Display = EGL_NO_DISPLAY;
  this->Context = EGL_NO_CONTEXT;
  this->Surface = EGL_NO_SURFACE;
  this->PlatformInUse.clear();
  this->DeviceIndexInUse = -1;
}

//------------------------------------------------------------------------------
// VTK draws into its own framebuffer objects, so the default framebuffer is never drawn to.
// It is still given a 1x1 pbuffer, as VTK's own EGL window has one: VTK binds framebuffer 0
// at the end of a frame, and a complete one keeps that harmless on every driver. Without a
// pbuffer config, EGL_KHR_surfaceless_context allows no surface at all. (EGL_SURFACE_TYPE
// must be given: its default, EGL_WINDOW_BIT, matches no config on these platforms.)
bool vtkHeadlessEGLContext::ChooseConfig(
  EGLDisplay display, bool surfacelessContext, EGLConfig& config, bool& pbuffer)
{
  EGLint numberOfConfigs = 0;
  pbuffer = true;
  const bool noSurface = this->PreferSurfaceless && surfacelessContext;
  for (EGLint surfaceType : { EGL_PBUFFER_BIT, EGL_DONT_CARE })
  {
    if (noSurface && surfaceType == EGL_PBUFFER_BIT)
    {
      continue;
    }
    const EGLint configAttributes[] = { EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_SURFACE_TYPE,
      surfaceType, EGL_RED_SIZE, 8, EGL_GREEN_SIZE, 8, EGL_BLUE_SIZE, 8, EGL_ALPHA_SIZE, 8,
      EGL_NONE };
    if (eglChooseConfig(display, configAttributes, &config, 1, &numberOfConfigs) &&
      numberOfConfigs > 0)
    {
      pbuffer = (surfaceType == EGL_PBUFFER_BIT);
      break;
    }
    if (!surfacelessContext)
    {
      break;
    }
  }
  return numberOfConfigs >= 1;
}

//------------------------------------------------------------------------------
// The highest core profile: drivers refuse versions they do not have.
EGLContext vtkHeadlessEGLContext::CreateCoreContext(EGLDisplay display, EGLConfig config)
{
  static const int versions[][2] = { { 4, 6 }, { 4, 5 }, { 4, 4 }, { 4, 3 }, { 4, 2 }, { 4, 1 },
    { 4, 0 }, { 3, 3 }, { 3, 2 } };
  EGLContext context = EGL_NO_CONTEXT;
  for (const auto& version : versions)
  {
    const EGLint contextAttributes[] = { EGL_CONTEXT_MAJOR_VERSION, version[0],
      EGL_CONTEXT_MINOR_VERSION, version[1], EGL_CONTEXT_OPENGL_PROFILE_MASK,
      EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE };
    context = eglCreateContext(display, config, EGL_NO_CONTEXT, contextAttributes);
    if (context != EGL_NO_CONTEXT)
    {
      break;
    }
  }
  return context;
}
