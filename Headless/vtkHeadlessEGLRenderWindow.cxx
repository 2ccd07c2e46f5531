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
#include "vtkHeadlessEGLContext.h" // EGL's headers come with it, kept free of X11
#include "vtkObjectFactory.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLState.h"

#include <sstream>
#include <stack>

// The window is thin: what EGL offers (vtkHeadlessEGLDevices) and the display and context made
// from it (vtkHeadlessEGLContext) are private classes of their own. What is left here is handing
// the context to VTK: making it current, the context stack, the capabilities report.

//------------------------------------------------------------------------------
class vtkHeadlessEGLRenderWindow::vtkInternals : public vtkHeadlessEGLContext
{
public:
  bool Failed = false;
  std::string Error;
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
  return static_cast<int>(vtkHeadlessEGLDevices::QueryDevices().size());
}

//------------------------------------------------------------------------------
int vtkHeadlessEGLRenderWindow::GetNumberOfGPUDevices()
{
  int count = 0;
  for (const auto& device : vtkHeadlessEGLDevices::QueryDevices())
  {
    count += device.Software ? 0 : 1;
  }
  return count;
}

//------------------------------------------------------------------------------
int vtkHeadlessEGLRenderWindow::GetGPUDeviceIndex(int ordinal)
{
  const std::vector<vtkHeadlessEGLDevices::DeviceInfo> devices =
    vtkHeadlessEGLDevices::QueryDevices();
  int gpu = 0;
  for (size_t index = 0; index < devices.size(); ++index)
  {
    if (!devices[index].Software && gpu++ == ordinal)
    {
      return static_cast<int>(index);
    }
  }
  return -1;
}

//------------------------------------------------------------------------------
std::string vtkHeadlessEGLRenderWindow::GetDeviceDescriptions()
{
  return vtkHeadlessEGLDevices::DescribeDevices();
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
    vtkErrorMacro("eglMakeCurrent failed: " << vtkHeadlessEGLDevices::LastError());
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
  // VTK queries the draw framebuffer bound now. Between frames that is the display framebuffer,
  // which has no depth attachment: the query is then GL_INVALID_OPERATION, left for the next GL
  // error check to find (vtkRenderer::ResetCameraClippingRange asks, from ResetCamera). The
  // depth that matters is the one the scene is rendered into.
  vtkOpenGLState* state = this->GetState();
  state->PushDrawFramebufferBinding();
  this->RenderFramebuffer->Bind(GL_DRAW_FRAMEBUFFER);
  int size = this->Superclass::GetDepthBufferSize();
  state->PopDrawFramebufferBinding();
  return size;
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
