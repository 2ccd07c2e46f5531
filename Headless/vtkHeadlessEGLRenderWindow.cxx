/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkHeadlessEGLRenderWindow.cxx

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// GLEW first: it refuses to follow another GL header.
#include "vtk_glew.h"

#include "vtkHeadlessEGLRenderWindow.h"

#include "vtkHeadlessContextSwitch.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLFramebufferObject.h"

// The window never talks to X: keep X11 types out of EGL's platform header.
#define EGL_NO_X11
#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <cstdlib>
#include <cstring>
#include <map>
#include <mutex>
#include <sstream>
#include <stack>
#include <vector>

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

std::string LastEGLError()
{
  std::ostringstream os;
  EGLint error = eglGetError();
  os << EGLErrorName(error) << " (0x" << std::hex << error << ")";
  return os.str();
}

bool HasExtension(const char* extensions, const char* name)
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

//------------------------------------------------------------------------------
// EGL extension entry points, looked up once. Client extensions are those of EGL_NO_DISPLAY.
struct EGLEntryPoints
{
  PFNEGLQUERYDEVICESEXTPROC QueryDevices = nullptr;
  PFNEGLQUERYDEVICESTRINGEXTPROC QueryDeviceString = nullptr;
  PFNEGLQUERYDEVICEATTRIBEXTPROC QueryDeviceAttrib = nullptr;
  PFNEGLGETPLATFORMDISPLAYEXTPROC GetPlatformDisplay = nullptr;
  bool PlatformDevice = false;
  bool PlatformSurfaceless = false;
  std::string ClientExtensions;

  static const EGLEntryPoints& Get()
  {
    static const EGLEntryPoints entryPoints;
    return entryPoints;
  }

private:
  EGLEntryPoints()
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
};

//------------------------------------------------------------------------------
struct DeviceInfo
{
  EGLDeviceEXT Handle = EGL_NO_DEVICE_EXT;
  std::string Extensions;
  bool Software = false;
  std::string DRMFile;
  EGLAttrib CUDADevice = -1;
};

std::vector<DeviceInfo> QueryDevices()
{
  std::vector<DeviceInfo> devices;
  const EGLEntryPoints& egl = EGLEntryPoints::Get();
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

// The environment's default device index (VTK_DEFAULT_EGL_DEVICE_INDEX), -1 when unset or not
// a non-negative integer.
int EnvironmentDeviceIndex()
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
}

//------------------------------------------------------------------------------
class vtkHeadlessEGLRenderWindow::vtkInternals
{
public:
  EGLDisplay Display = EGL_NO_DISPLAY;
  EGLContext Context = EGL_NO_CONTEXT;
  EGLSurface Surface = EGL_NO_SURFACE; // a 1x1 pbuffer, or none (EGL_KHR_surfaceless_context)

  bool Failed = false;
  std::string Error;
  std::string PlatformInUse;
  int DeviceIndexInUse = -1;
  std::string EGLVendor;
  std::string EGLVersion;
  std::string GLVendor;
  std::string GLRenderer;
  std::string GLVersion;
  std::string Capabilities;

  // What PushContext() found current, to be restored by PopContext().
  struct Saved
  {
    EGLDisplay Display;
    EGLSurface Draw;
    EGLSurface Read;
    EGLContext Context;
    vtkHeadlessContextSwitch::GLXBinding GLX;
  };
  std::stack<Saved> ContextStack;

  // Tries one display: initializes it and creates a context on it. On failure the display is
  // released again and `why` says what went wrong.
  bool PreferSurfaceless = false;

  bool TryDisplay(EGLDisplay display, std::string& why)
  {
    if (display == EGL_NO_DISPLAY)
    {
      why = "no EGL display: " + LastEGLError();
      return false;
    }
    EGLint major = 0;
    EGLint minor = 0;
    if (!DisplayUsers::Initialize(display, &major, &minor))
    {
      why = "eglInitialize failed: " + LastEGLError();
      return false;
    }
    if (major < 1 || (major == 1 && minor < 4))
    {
      why = "EGL 1.4 or later is needed for desktop OpenGL";
      DisplayUsers::Release(display);
      return false;
    }
    if (!eglBindAPI(EGL_OPENGL_API))
    {
      why = "this EGL display cannot do desktop OpenGL (eglBindAPI: " + LastEGLError() + ")";
      DisplayUsers::Release(display);
      return false;
    }
    const char* displayExtensions = eglQueryString(display, EGL_EXTENSIONS);
    const bool surfacelessContext = HasExtension(displayExtensions, "EGL_KHR_surfaceless_context");

    // VTK draws into its own framebuffer objects, so the default framebuffer is never drawn to.
    // It is still given a 1x1 pbuffer, as VTK's own EGL window has one: VTK binds framebuffer 0
    // at the end of a frame, and a complete one keeps that harmless on every driver. Without a
    // pbuffer config, EGL_KHR_surfaceless_context allows no surface at all. (EGL_SURFACE_TYPE
    // must be given: its default, EGL_WINDOW_BIT, matches no config on these platforms.)
    EGLConfig config = nullptr;
    EGLint numberOfConfigs = 0;
    bool pbuffer = true;
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
    if (numberOfConfigs < 1)
    {
      why = "no EGL config for an OpenGL context: " + LastEGLError();
      DisplayUsers::Release(display);
      return false;
    }

    // The highest core profile: drivers refuse versions they do not have.
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
    if (context == EGL_NO_CONTEXT)
    {
      why = "no OpenGL 3.2 (or later) core profile context: " + LastEGLError();
      DisplayUsers::Release(display);
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
      why = "no pbuffer surface (and no EGL_KHR_surfaceless_context): " + LastEGLError();
      eglDestroyContext(display, context);
      DisplayUsers::Release(display);
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

  bool TryDevice(const std::vector<DeviceInfo>& devices, int index, std::string& why)
  {
    const EGLEntryPoints& egl = EGLEntryPoints::Get();
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

  bool TrySurfaceless(std::string& why)
  {
    const EGLEntryPoints& egl = EGLEntryPoints::Get();
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

  // Chooses and creates display and context. Returns false with `error` set; `warnings`
  // collects what the caller should tell the user even on success.
  bool Create(int platform, int requestedIndex, std::string& error, std::string& warnings)
  {
    const EGLEntryPoints& egl = EGLEntryPoints::Get();
    std::string why;
    if (platform == PLATFORM_SURFACELESS)
    {
      if (!this->TrySurfaceless(why))
      {
        error = "Cannot use the surfaceless EGL platform: " + why;
        return false;
      }
      return true;
    }

    const std::vector<DeviceInfo> devices = QueryDevices();
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
    const int environmentIndex = EnvironmentDeviceIndex();
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
    if (platform == PLATFORM_DEVICE)
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

  void Destroy()
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
    DisplayUsers::Release(this->Display);
    this->Display = EGL_NO_DISPLAY;
    this->Context = EGL_NO_CONTEXT;
    this->Surface = EGL_NO_SURFACE;
    this->PlatformInUse.clear();
    this->DeviceIndexInUse = -1;
  }
};

//------------------------------------------------------------------------------
vtkStandardNewMacro(vtkHeadlessEGLRenderWindow);

//------------------------------------------------------------------------------
vtkHeadlessEGLRenderWindow::vtkHeadlessEGLRenderWindow()
  : Platform(PLATFORM_AUTOMATIC)
  , PreferSurfacelessContext(false)
  , Internals(new vtkInternals)
{
  this->DeviceIndex = -1;
  this->ShowWindow = false;
  this->OwnContext = 1;
  // Nothing is on a screen; this is what VTK's own EGL window reports.
  this->ScreenSize[0] = 1920;
  this->ScreenSize[1] = 1080;
  this->SetWindowName("Visualization Toolkit - EGL");
}

//------------------------------------------------------------------------------
vtkHeadlessEGLRenderWindow::~vtkHeadlessEGLRenderWindow()
{
  this->Finalize();
  delete this->Internals;
}

//------------------------------------------------------------------------------
void vtkHeadlessEGLRenderWindow::SetPlatform(int platform)
{
  platform = platform < PLATFORM_AUTOMATIC
    ? PLATFORM_AUTOMATIC
    : (platform > PLATFORM_SURFACELESS ? PLATFORM_SURFACELESS : platform);
  if (platform == this->Platform)
  {
    return;
  }
  this->Platform = platform;
  this->Internals->Failed = false; // a new choice deserves a new attempt
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkHeadlessEGLRenderWindow::SetPreferSurfacelessContext(bool prefer)
{
  if (prefer == this->PreferSurfacelessContext)
  {
    return;
  }
  this->PreferSurfacelessContext = prefer;
  this->Internals->Failed = false;
  this->Modified();
}

//------------------------------------------------------------------------------
bool vtkHeadlessEGLRenderWindow::GetContextIsSurfaceless()
{
  return this->HasContext() && this->Internals->Surface == EGL_NO_SURFACE;
}

//------------------------------------------------------------------------------
void vtkHeadlessEGLRenderWindow::SetDeviceIndex(int index)
{
  index = index < -1 ? -1 : index;
  if (index == this->DeviceIndex)
  {
    return;
  }
  this->DeviceIndex = index;
  this->Internals->Failed = false;
  this->Modified();
}

//------------------------------------------------------------------------------
int vtkHeadlessEGLRenderWindow::GetNumberOfDevices()
{
  return static_cast<int>(QueryDevices().size());
}

//------------------------------------------------------------------------------
std::string vtkHeadlessEGLRenderWindow::GetDeviceDescriptions()
{
  const EGLEntryPoints& egl = EGLEntryPoints::Get();
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
bool vtkHeadlessEGLRenderWindow::HasContext()
{
  return this->Internals->Context != EGL_NO_CONTEXT;
}

//------------------------------------------------------------------------------
bool vtkHeadlessEGLRenderWindow::EnsureContext()
{
  vtkInternals* impl = this->Internals;
  if (impl->Context != EGL_NO_CONTEXT)
  {
    return true;
  }
  if (impl->Failed)
  {
    return false; // reported already; SetPlatform/SetDeviceIndex allow a new attempt
  }

  std::string error;
  std::string warnings;
  impl->PreferSurfaceless = this->PreferSurfacelessContext;
  if (!impl->Create(this->Platform, this->DeviceIndex, error, warnings))
  {
    impl->Failed = true;
    impl->Error = error;
    vtkErrorMacro(<< error);
    return false;
  }
  if (!warnings.empty())
  {
    vtkWarningMacro(<< warnings);
  }

  this->MakeCurrent();
  const auto glString = [](GLenum name)
  {
    const GLubyte* value = glGetString(name);
    return value ? std::string(reinterpret_cast<const char*>(value)) : std::string();
  };
  impl->GLVendor = glString(GL_VENDOR);
  impl->GLRenderer = glString(GL_RENDERER);
  impl->GLVersion = glString(GL_VERSION);

  this->Mapped = 0;
  this->OwnContext = 1;
  this->OpenGLInit();
  if (!this->Initialized)
  {
    // OpenGLInitContext() has said why; drop the useless context.
    impl->Failed = true;
    impl->Error =
      "OpenGL could not be initialized on " + impl->GLRenderer + " (" + impl->GLVersion + ")";
    impl->Destroy();
    return false;
  }
  impl->Error.clear();
  this->ContextCreationTime.Modified();
  vtkDebugMacro(<< "EGL context on the " << impl->PlatformInUse << " platform: " << impl->GLRenderer
                << ", " << impl->GLVersion);
  return true;
}

//------------------------------------------------------------------------------
void vtkHeadlessEGLRenderWindow::OpenGLInitContext()
{
  if (!this->Initialized)
  {
    // Debian's GLEW is the GLX flavour: glewInit() loads every GL entry point (as glvnd dispatch
    // stubs that follow the current EGL context) and then fails in glxewInit() for want of an X
    // display, returning GLEW_ERROR_NO_GLX_DISPLAY. VTK's own OpenGLInitContext() treats that as
    // fatal, so the GL part is checked here and the rest left to it.
    GLenum result = glewInit();
#ifdef GLEW_ERROR_NO_GLX_DISPLAY
    const bool usable = (result == GLEW_OK || result == GLEW_ERROR_NO_GLX_DISPLAY);
#else
    const bool usable = (result == GLEW_OK);
#endif
    if (!usable)
    {
      vtkErrorMacro("GLEW could not be initialized on the EGL context: "
        << reinterpret_cast<const char*>(glewGetErrorString(result)));
      return;
    }
    if (!GLEW_VERSION_3_2)
    {
      vtkErrorMacro("VTK needs OpenGL 3.2; the EGL context has "
        << this->Internals->GLVersion << " (" << this->Internals->GLRenderer << ")");
      return;
    }
    this->GlewInitValid = true;
    this->Initialized = true;
    GLfloat lineWidthRange[2] = { 1.0f, 1.0f };
    glGetFloatv(GL_ALIASED_LINE_WIDTH_RANGE, lineWidthRange);
    this->MaximumHardwareLineWidth = lineWidthRange[1];
  }
  this->Superclass::OpenGLInitContext();
}

//------------------------------------------------------------------------------
void vtkHeadlessEGLRenderWindow::CreateAWindow()
{
  this->EnsureContext();
}

//------------------------------------------------------------------------------
void vtkHeadlessEGLRenderWindow::DestroyWindow()
{
  vtkInternals* impl = this->Internals;
  if (impl->Context == EGL_NO_CONTEXT)
  {
    return;
  }
  // VTK's resources must be freed in their own context, whatever is current now.
  this->PushContext();
  this->ReleaseGraphicsResources(this);
  this->PopContext();
  impl->Destroy();
  this->Mapped = 0;
}

//------------------------------------------------------------------------------
void vtkHeadlessEGLRenderWindow::Initialize()
{
  this->EnsureContext();
}

//------------------------------------------------------------------------------
void vtkHeadlessEGLRenderWindow::Finalize()
{
  this->DestroyWindow();
}

//------------------------------------------------------------------------------
void vtkHeadlessEGLRenderWindow::Start()
{
  if (!this->EnsureContext())
  {
    return;
  }
  this->MakeCurrent();
  this->Superclass::Start();
}

//------------------------------------------------------------------------------
void vtkHeadlessEGLRenderWindow::Render()
{
  // Without a context every GL call of the renderers would go through null GLEW pointers.
  if (!this->EnsureContext())
  {
    return;
  }
  this->Superclass::Render();
}

//------------------------------------------------------------------------------
void vtkHeadlessEGLRenderWindow::Frame()
{
  if (!this->HasContext())
  {
    return;
  }
  this->MakeCurrent();
  this->Superclass::Frame();
}

//------------------------------------------------------------------------------
void vtkHeadlessEGLRenderWindow::BlitDisplayFramebuffersToHardware()
{
  // Nothing to show: pixels are read from VTK's display framebuffer.
}

//------------------------------------------------------------------------------
void vtkHeadlessEGLRenderWindow::WaitForCompletion()
{
  if (!this->HasContext())
  {
    return;
  }
  this->MakeCurrent();
  this->Superclass::WaitForCompletion();
}

//------------------------------------------------------------------------------
void vtkHeadlessEGLRenderWindow::MakeCurrent()
{
  vtkInternals* impl = this->Internals;
  if (impl->Context == EGL_NO_CONTEXT)
  {
    return;
  }
  eglBindAPI(EGL_OPENGL_API);
  if (eglGetCurrentContext() == impl->Context)
  {
    return;
  }
  // glvnd refuses an EGL context while a GLX one is current on this thread.
  vtkHeadlessContextSwitch::ReleaseGLX();
  if (!eglMakeCurrent(impl->Display, impl->Surface, impl->Surface, impl->Context))
  {
    vtkErrorMacro("eglMakeCurrent failed: " << LastEGLError());
  }
}

//------------------------------------------------------------------------------
void vtkHeadlessEGLRenderWindow::ReleaseCurrent()
{
  vtkInternals* impl = this->Internals;
  if (impl->Context != EGL_NO_CONTEXT && eglGetCurrentContext() == impl->Context)
  {
    eglMakeCurrent(impl->Display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  }
}

//------------------------------------------------------------------------------
bool vtkHeadlessEGLRenderWindow::IsCurrent()
{
  vtkInternals* impl = this->Internals;
  return impl->Context != EGL_NO_CONTEXT && eglGetCurrentContext() == impl->Context;
}

//------------------------------------------------------------------------------
void vtkHeadlessEGLRenderWindow::PushContext()
{
  vtkInternals* impl = this->Internals;
  vtkInternals::Saved saved;
  saved.Display = eglGetCurrentDisplay();
  saved.Draw = eglGetCurrentSurface(EGL_DRAW);
  saved.Read = eglGetCurrentSurface(EGL_READ);
  saved.Context = eglGetCurrentContext();
  if (saved.Context == EGL_NO_CONTEXT)
  {
    saved.GLX = vtkHeadlessContextSwitch::ReleaseGLX();
  }
  impl->ContextStack.push(saved);
  this->MakeCurrent();
}

//------------------------------------------------------------------------------
void vtkHeadlessEGLRenderWindow::PopContext()
{
  vtkInternals* impl = this->Internals;
  if (impl->ContextStack.empty())
  {
    return;
  }
  const vtkInternals::Saved saved = impl->ContextStack.top();
  impl->ContextStack.pop();
  if (saved.Context == eglGetCurrentContext())
  {
    return;
  }
  if (saved.Context != EGL_NO_CONTEXT)
  {
    eglMakeCurrent(saved.Display, saved.Draw, saved.Read, saved.Context);
    return;
  }
  this->ReleaseCurrent();
  vtkHeadlessContextSwitch::RestoreGLX(saved.GLX);
}

//------------------------------------------------------------------------------
vtkTypeBool vtkHeadlessEGLRenderWindow::IsDirect()
{
  return this->HasContext() ? 1 : 0;
}

//------------------------------------------------------------------------------
int vtkHeadlessEGLRenderWindow::SupportsOpenGL()
{
  if (!this->EnsureContext())
  {
    this->OpenGLSupportTested = true;
    this->OpenGLSupportResult = 0;
    this->OpenGLSupportMessage = this->Internals->Error;
    return 0;
  }
  // The base class would probe with a second, X-style window; this one already has a context
  // that passed OpenGLInitContext()'s checks.
  this->OpenGLSupportTested = true;
  this->OpenGLSupportResult = 1;
  this->OpenGLSupportMessage = "EGL context: " + this->Internals->GLVersion;
  return 1;
}

//------------------------------------------------------------------------------
const char* vtkHeadlessEGLRenderWindow::ReportCapabilities()
{
  if (!this->EnsureContext())
  {
    this->Internals->Capabilities = "No EGL context: " + this->Internals->Error + "\n";
    return this->Internals->Capabilities.c_str();
  }
  this->MakeCurrent();
  std::ostringstream os;
  os << "EGL platform:  " << this->Internals->PlatformInUse;
  if (this->Internals->DeviceIndexInUse >= 0)
  {
    os << " (device " << this->Internals->DeviceIndexInUse << ")";
  }
  os << "\nEGL surface:  "
     << (this->Internals->Surface != EGL_NO_SURFACE ? "1x1 pbuffer" : "none (surfaceless context)");
  os << "\nEGL vendor string:  " << this->Internals->EGLVendor
     << "\nEGL version string:  " << this->Internals->EGLVersion << "\n";
  os << this->Superclass::ReportCapabilities();
  this->Internals->Capabilities = os.str();
  return this->Internals->Capabilities.c_str();
}

//------------------------------------------------------------------------------
int* vtkHeadlessEGLRenderWindow::GetScreenSize()
{
  return this->ScreenSize;
}

//------------------------------------------------------------------------------
void* vtkHeadlessEGLRenderWindow::GetGenericDisplayId()
{
  return this->Internals->Display;
}

//------------------------------------------------------------------------------
void* vtkHeadlessEGLRenderWindow::GetGenericContext()
{
  return this->Internals->Context;
}

//------------------------------------------------------------------------------
void vtkHeadlessEGLRenderWindow::SetShowWindow(bool show)
{
  if (show)
  {
    vtkDebugMacro(<< "an EGL window is offscreen only; ShowWindow stays off");
  }
  this->Superclass::SetShowWindow(false);
}

//------------------------------------------------------------------------------
const char* vtkHeadlessEGLRenderWindow::GetInitializationError()
{
  return this->Internals->Error.c_str();
}

const char* vtkHeadlessEGLRenderWindow::GetPlatformInUse()
{
  return this->Internals->PlatformInUse.c_str();
}

int vtkHeadlessEGLRenderWindow::GetDeviceIndexInUse()
{
  return this->Internals->DeviceIndexInUse;
}

const char* vtkHeadlessEGLRenderWindow::GetEGLVendor()
{
  return this->Internals->EGLVendor.c_str();
}

const char* vtkHeadlessEGLRenderWindow::GetEGLVersion()
{
  return this->Internals->EGLVersion.c_str();
}

const char* vtkHeadlessEGLRenderWindow::GetGLVendor()
{
  return this->Internals->GLVendor.c_str();
}

const char* vtkHeadlessEGLRenderWindow::GetGLRenderer()
{
  return this->Internals->GLRenderer.c_str();
}

const char* vtkHeadlessEGLRenderWindow::GetGLVersion()
{
  return this->Internals->GLVersion.c_str();
}

//------------------------------------------------------------------------------
bool vtkHeadlessEGLRenderWindow::CanAccessPixels()
{
  return this->HasContext() && this->Initialized && this->RenderFramebuffer != nullptr;
}

int vtkHeadlessEGLRenderWindow::GetColorBufferSizes(int* rgba)
{
  if (!this->CanAccessPixels())
  {
    return 0;
  }
  return this->Superclass::GetColorBufferSizes(rgba);
}

int vtkHeadlessEGLRenderWindow::GetDepthBufferSize()
{
  if (!this->CanAccessPixels())
  {
    return 0;
  }
  return this->Superclass::GetDepthBufferSize();
}

int vtkHeadlessEGLRenderWindow::ReadPixels(
  const vtkRecti& rect, int front, int glFormat, int glType, void* data, int right)
{
  if (!this->CanAccessPixels())
  {
    return VTK_ERROR;
  }
  this->MakeCurrent();
  return this->Superclass::ReadPixels(rect, front, glFormat, glType, data, right);
}

int vtkHeadlessEGLRenderWindow::GetZbufferData(int x1, int y1, int x2, int y2, float* z)
{
  if (!this->CanAccessPixels())
  {
    return VTK_ERROR;
  }
  this->MakeCurrent();
  return this->Superclass::GetZbufferData(x1, y1, x2, y2, z);
}

int vtkHeadlessEGLRenderWindow::SetZbufferData(int x1, int y1, int x2, int y2, float* buffer)
{
  if (!this->CanAccessPixels())
  {
    return VTK_ERROR;
  }
  this->MakeCurrent();
  return this->Superclass::SetZbufferData(x1, y1, x2, y2, buffer);
}

int vtkHeadlessEGLRenderWindow::SetPixelData(
  int x, int y, int x2, int y2, unsigned char* data, int front, int right)
{
  if (!this->CanAccessPixels())
  {
    return VTK_ERROR;
  }
  this->MakeCurrent();
  return this->Superclass::SetPixelData(x, y, x2, y2, data, front, right);
}

int vtkHeadlessEGLRenderWindow::SetRGBAPixelData(
  int x, int y, int x2, int y2, float* data, int front, int blend, int right)
{
  if (!this->CanAccessPixels())
  {
    return VTK_ERROR;
  }
  this->MakeCurrent();
  return this->Superclass::SetRGBAPixelData(x, y, x2, y2, data, front, blend, right);
}

int vtkHeadlessEGLRenderWindow::SetRGBACharPixelData(
  int x, int y, int x2, int y2, unsigned char* data, int front, int blend, int right)
{
  if (!this->CanAccessPixels())
  {
    return VTK_ERROR;
  }
  this->MakeCurrent();
  return this->Superclass::SetRGBACharPixelData(x, y, x2, y2, data, front, blend, right);
}

void vtkHeadlessEGLRenderWindow::DrawPixels(
  int x1, int y1, int x2, int y2, int numComponents, int dataType, void* data)
{
  if (!this->CanAccessPixels())
  {
    return;
  }
  this->Superclass::DrawPixels(x1, y1, x2, y2, numComponents, dataType, data);
}

void vtkHeadlessEGLRenderWindow::DrawPixels(int dstXmin, int dstYmin, int dstXmax, int dstYmax,
  int srcXmin, int srcYmin, int srcXmax, int srcYmax, int srcWidth, int srcHeight,
  int numComponents, int dataType, void* data)
{
  if (!this->CanAccessPixels())
  {
    return;
  }
  this->Superclass::DrawPixels(dstXmin, dstYmin, dstXmax, dstYmax, srcXmin, srcYmin, srcXmax,
    srcYmax, srcWidth, srcHeight, numComponents, dataType, data);
}

void vtkHeadlessEGLRenderWindow::DrawPixels(
  int srcWidth, int srcHeight, int numComponents, int dataType, void* data)
{
  if (!this->CanAccessPixels())
  {
    return;
  }
  this->Superclass::DrawPixels(srcWidth, srcHeight, numComponents, dataType, data);
}

//------------------------------------------------------------------------------
void vtkHeadlessEGLRenderWindow::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  const char* platforms[] = { "automatic", "device", "surfaceless" };
  os << indent << "Platform: " << platforms[this->Platform] << "\n";
  os << indent << "PreferSurfacelessContext: " << (this->PreferSurfacelessContext ? "on" : "off")
     << "\n";
  os << indent << "HasContext: " << (this->HasContext() ? "yes" : "no") << "\n";
  os << indent << "PlatformInUse: " << this->Internals->PlatformInUse << "\n";
  os << indent << "DeviceIndexInUse: " << this->Internals->DeviceIndexInUse << "\n";
  os << indent << "GLRenderer: " << this->Internals->GLRenderer << "\n";
  os << indent << "GLVersion: " << this->Internals->GLVersion << "\n";
  os << indent << "InitializationError: " << this->Internals->Error << "\n";
}
