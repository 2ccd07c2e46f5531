/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkHeadlessEGLDevices.cxx

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "vtkHeadlessEGLDevices.h"

#include <cstdlib>
#include <cstring>
#include <map>
#include <mutex>
#include <sstream>

namespace
{
//------------------------------------------------------------------------------
const char* EGLErrorName(EGLint error)
{
  switch (error)
  {
    case EGL_SUCCESS:
      return "EGL_SUCCESS";
    case EGL_NOT_INITIALIZED:
      return "EGL_NOT_INITIALIZED";
    case EGL_BAD_ACCESS:
      return "EGL_BAD_ACCESS";
    case EGL_BAD_ALLOC:
      return "EGL_BAD_ALLOC";
    case EGL_BAD_ATTRIBUTE:
      return "EGL_BAD_ATTRIBUTE";
    case EGL_BAD_CONFIG:
      return "EGL_BAD_CONFIG";
    case EGL_BAD_CONTEXT:
      return "EGL_BAD_CONTEXT";
    case EGL_BAD_CURRENT_SURFACE:
      return "EGL_BAD_CURRENT_SURFACE";
    case EGL_BAD_DISPLAY:
      return "EGL_BAD_DISPLAY";
    case EGL_BAD_MATCH:
      return "EGL_BAD_MATCH";
    case EGL_BAD_NATIVE_PIXMAP:
      return "EGL_BAD_NATIVE_PIXMAP";
    case EGL_BAD_NATIVE_WINDOW:
      return "EGL_BAD_NATIVE_WINDOW";
    case EGL_BAD_PARAMETER:
      return "EGL_BAD_PARAMETER";
    case EGL_BAD_SURFACE:
      return "EGL_BAD_SURFACE";
    case EGL_CONTEXT_LOST:
      return "EGL_CONTEXT_LOST";
    default:
      return "unknown EGL error";
  }
}

//------------------------------------------------------------------------------
// Several windows share one EGLDisplay (EGL hands out the same handle for the same platform and
// device) and eglTerminate() would pull it from under the others: count the users per display.
// The map is never destroyed, because windows may be finalized during static destruction.
class DisplayUsers
{
public:
  static bool Initialize(EGLDisplay display, EGLint* major, EGLint* minor)
  {
    std::lock_guard<std::mutex> lock(Mutex());
    if (!eglInitialize(display, major, minor))
    {
      return false;
    }
    ++Counts()[display];
    return true;
  }

  static void Release(EGLDisplay display)
  {
    std::lock_guard<std::mutex> lock(Mutex());
    auto it = Counts().find(display);
    if (it == Counts().end())
    {
      return;
    }
    if (--it->second == 0)
    {
      Counts().erase(it);
      eglTerminate(display);
    }
  }

private:
  static std::map<EGLDisplay, int>& Counts()
  {
    static auto* counts = new std::map<EGLDisplay, int>();
    return *counts;
  }
  static std::mutex& Mutex()
  {
    static auto* mutex = new std::mutex();
    return *mutex;
  }
};
}

//------------------------------------------------------------------------------
const vtkHeadlessEGLDevices::EntryPoints& vtkHeadlessEGLDevices::EntryPoints::Get()
{
  static const EntryPoints entryPoints;
  return entryPoints;
}

//------------------------------------------------------------------------------
vtkHeadlessEGLDevices::EntryPoints::EntryPoints()
{
  const char* extensions = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
  if (!extensions)
  {
    // EGL 1.4 without EGL_EXT_client_extensions: nothing but eglGetDisplay.
    eglGetError();
    return;
  }
  this->ClientExtensions = extensions;
  if (HasExtension(extensions, "EGL_EXT_platform_base"))
  {
    this->GetPlatformDisplay = reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(
      eglGetProcAddress("eglGetPlatformDisplayEXT"));
  }
  if (HasExtension(extensions, "EGL_EXT_device_base") ||
    HasExtension(extensions, "EGL_EXT_device_enumeration"))
  {
    this->QueryDevices =
      reinterpret_cast<PFNEGLQUERYDEVICESEXTPROC>(eglGetProcAddress("eglQueryDevicesEXT"));
  }
  if (HasExtension(extensions, "EGL_EXT_device_base") ||
    HasExtension(extensions, "EGL_EXT_device_query"))
  {
    this->QueryDeviceString = reinterpret_cast<PFNEGLQUERYDEVICESTRINGEXTPROC>(
      eglGetProcAddress("eglQueryDeviceStringEXT"));
    this->QueryDeviceAttrib = reinterpret_cast<PFNEGLQUERYDEVICEATTRIBEXTPROC>(
      eglGetProcAddress("eglQueryDeviceAttribEXT"));
  }
  this->PlatformDevice = this->GetPlatformDisplay && this->QueryDevices &&
    HasExtension(extensions, "EGL_EXT_platform_device");
  this->PlatformSurfaceless =
    this->GetPlatformDisplay && HasExtension(extensions, "EGL_MESA_platform_surfaceless");
}

//------------------------------------------------------------------------------
std::vector<vtkHeadlessEGLDevices::DeviceInfo> vtkHeadlessEGLDevices::QueryDevices()
{
  std::vector<DeviceInfo> devices;
  const EntryPoints& egl = EntryPoints::Get();
  if (!egl.QueryDevices)
  {
    return devices;
  }
  EGLint count = 0;
  if (!egl.QueryDevices(0, nullptr, &count) || count <= 0)
  {
    eglGetError();
    return devices;
  }
  std::vector<EGLDeviceEXT> handles(static_cast<size_t>(count), EGL_NO_DEVICE_EXT);
  if (!egl.QueryDevices(count, handles.data(), &count))
  {
    eglGetError();
    return devices;
  }
  handles.resize(static_cast<size_t>(count));
  for (EGLDeviceEXT handle : handles)
  {
    DeviceInfo info;
    info.Handle = handle;
    if (egl.QueryDeviceString)
    {
      const char* extensions = egl.QueryDeviceString(handle, EGL_EXTENSIONS);
      info.Extensions = extensions ? extensions : "";
      if (HasExtension(extensions, "EGL_EXT_device_drm"))
      {
        const char* file = egl.QueryDeviceString(handle, EGL_DRM_DEVICE_FILE_EXT);
        info.DRMFile = file ? file : "";
      }
    }
    info.Software = HasExtension(info.Extensions.c_str(), "EGL_MESA_device_software");
    if (egl.QueryDeviceAttrib && HasExtension(info.Extensions.c_str(), "EGL_NV_device_cuda"))
    {
      EGLAttrib cuda = -1;
      if (egl.QueryDeviceAttrib(handle, EGL_CUDA_DEVICE_NV, &cuda))
      {
        info.CUDADevice = cuda;
      }
    }
    eglGetError();
    devices.push_back(info);
  }
  return devices;
}

//------------------------------------------------------------------------------
std::string vtkHeadlessEGLDevices::DescribeDevices()
{
  const EntryPoints& egl = EntryPoints::Get();
  std::ostringstream os;
  if (!egl.PlatformDevice)
  {
    os << "EGL cannot enumerate devices (no EGL_EXT_platform_device)\n";
  }
  const std::vector<DeviceInfo> devices = QueryDevices();
  for (size_t i = 0; i < devices.size(); ++i)
  {
    const DeviceInfo& device = devices[i];
    os << i << ": " << (device.Software ? "software" : "GPU");
    if (!device.DRMFile.empty())
    {
      os << ", " << device.DRMFile;
    }
    if (device.CUDADevice >= 0)
    {
      os << ", CUDA device " << device.CUDADevice;
    }
    os << ", extensions: " << (device.Extensions.empty() ? "(none)" : device.Extensions) << "\n";
  }
  os << "Mesa surfaceless platform: " << (egl.PlatformSurfaceless ? "available" : "not available")
     << "\n";
  return os.str();
}

//------------------------------------------------------------------------------
bool vtkHeadlessEGLDevices::InitializeDisplay(EGLDisplay display, EGLint* major, EGLint* minor)
{
  return DisplayUsers::Initialize(display, major, minor);
}

//------------------------------------------------------------------------------
void vtkHeadlessEGLDevices::ReleaseDisplay(EGLDisplay display)
{
  DisplayUsers::Release(display);
}

//------------------------------------------------------------------------------
int vtkHeadlessEGLDevices::EnvironmentDeviceIndex()
{
  const char* value = std::getenv("VTK_DEFAULT_EGL_DEVICE_INDEX");
  if (!value || !*value)
  {
    return -1;
  }
  char* end = nullptr;
  long index = std::strtol(value, &end, 10);
  if (*end != '\0' || index < 0 || index > 1000000)
  {
    return -1;
  }
  return static_cast<int>(index);
}

//------------------------------------------------------------------------------
std::string vtkHeadlessEGLDevices::LastError()
{
  std::ostringstream os;
  EGLint error = eglGetError();
  os << EGLErrorName(error) << " (0x" << std::hex << error << ")";
  return os.str();
}

//------------------------------------------------------------------------------
bool vtkHeadlessEGLDevices::HasExtension(const char* extensions, const char* name)
{
  if (!extensions || !name)
  {
    return false;
  }
  // Whole words only: EGL_EXT_platform_device must not match EGL_EXT_platform_device_foo.
  const size_t length = std::strlen(name);
  for (const char* p = std::strstr(extensions, name); p; p = std::strstr(p + 1, name))
  {
    const bool startsWord = (p == extensions || p[-1] == ' ');
    const bool endsWord = (p[length] == '\0' || p[length] == ' ');
    if (startsWord && endsWord)
    {
      return true;
    }
  }
  return false;
}
