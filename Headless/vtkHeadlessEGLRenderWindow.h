/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkHeadlessEGLRenderWindow.h

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
/**
 * @class   vtkHeadlessEGLRenderWindow
 * @brief   an offscreen OpenGL render window on EGL: a GPU without X, or Mesa on the CPU
 *
 * Debian's VTK 9.1 has only the X11 window (vtkXOpenGLRenderWindow), which aborts when there is
 * no X server. This window needs none. It gets an EGL display on one of two platforms:
 *
 * - the **device** platform (EGL_EXT_platform_device): one GPU of the machine, picked by index
 *   among the devices that eglQueryDevicesEXT lists. Software devices (Mesa's llvmpipe device,
 *   EGL_MESA_device_software) are skipped unless asked for by index;
 * - Mesa's **surfaceless** platform (EGL_MESA_platform_surfaceless): llvmpipe on the CPU, for
 *   machines without a GPU.
 *
 * With PLATFORM_AUTOMATIC (the default) the window takes the first GPU that gives a context and
 * falls back to the surfaceless platform, then to a software device, then to
 * eglGetDisplay(EGL_DEFAULT_DISPLAY). SetDeviceIndex() (or the environment variable
 * VTK_DEFAULT_EGL_DEVICE_INDEX, as in later VTK versions) picks the device: an index set through
 * the API is obeyed or fails with an error; an index from the environment that does not work
 * gives a warning and the automatic choice.
 *
 * The context is the highest OpenGL core profile the display gives, from 4.6 down to 3.2. The
 * window is always offscreen: VTK 9.1 renders into its own framebuffer objects and reads pixels
 * from them, so the context's own surface is a 1x1 pbuffer (or none at all, through
 * EGL_KHR_surfaceless_context, where pbuffers are missing) whatever the window size. Resizing
 * therefore only resizes VTK's framebuffers. Several windows may live in one process; they share
 * the EGL display, which is terminated when the last window that initialized it is finalized.
 *
 * When no display or context can be had, the window reports it once with vtkErrorMacro (also
 * available from GetInitializationError()) and every later Render() or pixel read does nothing.
 * Changing the platform or the device index allows a new attempt.
 *
 * The window can share a thread with X windows: glvnd lets only one of GLX and EGL own the
 * current context of a thread, so MakeCurrent() first releases a current GLX context and
 * PushContext()/PopContext() restore it (see vtkHeadlessXOpenGLRenderWindow for the other way).
 *
 * Usually this class is not named at all: with TiledRayCast::RenderingHeadless loaded,
 * vtkRenderWindow::New() returns it when there is no usable X display (see
 * vtkHeadlessObjectFactory).
 *
 * @sa vtkHeadlessObjectFactory vtkHeadlessXOpenGLRenderWindow
 */

#ifndef vtkHeadlessEGLRenderWindow_h
#define vtkHeadlessEGLRenderWindow_h

#include "vtkOpenGLRenderWindow.h"
#include "vtkRenderingHeadlessModule.h" // For export macro

#include <string> // For std::string

class VTKRENDERINGHEADLESS_EXPORT vtkHeadlessEGLRenderWindow : public vtkOpenGLRenderWindow
{
public:
  static vtkHeadlessEGLRenderWindow* New();
  vtkTypeMacro(vtkHeadlessEGLRenderWindow, vtkOpenGLRenderWindow);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * Which EGL platform the display comes from.
   */
  enum PlatformType
  {
    PLATFORM_AUTOMATIC = 0,
    PLATFORM_DEVICE = 1,
    PLATFORM_SURFACELESS = 2
  };

  ///@{
  /**
   * The EGL platform to use (default PLATFORM_AUTOMATIC). PLATFORM_DEVICE insists on a device
   * (a GPU unless SetDeviceIndex() names a software device); PLATFORM_SURFACELESS insists on
   * Mesa's surfaceless platform. Takes effect when the context is next created (after
   * Finalize() if one exists).
   */
  virtual void SetPlatform(int platform);
  vtkGetMacro(Platform, int);
  void SetPlatformToAutomatic() { this->SetPlatform(PLATFORM_AUTOMATIC); }
  void SetPlatformToDevice() { this->SetPlatform(PLATFORM_DEVICE); }
  void SetPlatformToSurfaceless() { this->SetPlatform(PLATFORM_SURFACELESS); }
  ///@}

  ///@{
  /**
   * By default the context gets a 1x1 pbuffer surface (see the class description). With this on,
   * it gets no surface at all when the display supports EGL_KHR_surfaceless_context (VTK renders
   * the same either way). Takes effect when the context is next created.
   */
  virtual void SetPreferSurfacelessContext(bool prefer);
  vtkGetMacro(PreferSurfacelessContext, bool);
  vtkBooleanMacro(PreferSurfacelessContext, bool);
  ///@}

  /**
   * True when the context has no surface (EGL_KHR_surfaceless_context), false with its pbuffer.
   */
  bool GetContextIsSurfaceless();

  /**
   * The EGL device to render on: an index into the list of eglQueryDevicesEXT (see
   * GetDeviceDescriptions()), or -1 (the default) for the automatic choice, which the
   * environment variable VTK_DEFAULT_EGL_DEVICE_INDEX can steer. Takes effect when the context
   * is next created.
   */
  void SetDeviceIndex(int index) override;

  /**
   * Number of EGL devices (GPUs and software devices) that eglQueryDevicesEXT lists; 0 when the
   * EGL implementation cannot enumerate devices.
   */
  int GetNumberOfDevices() override;

  ///@{
  /**
   * The GPUs among the EGL devices (software devices left out): how many there are, and the
   * device index (for SetDeviceIndex()) of the one at `ordinal` (0 to that number - 1), or -1
   * for an ordinal out of range. A process of several on one machine (an MPI rank) spreads them
   * over the GPUs by its rank modulo their number.
   */
  static int GetNumberOfGPUDevices();
  static int GetGPUDeviceIndex(int ordinal);
  ///@}

  /**
   * One line per EGL device: its index, whether it is a GPU or a software device, and what EGL
   * tells about it (DRM node, CUDA device number, device extensions).
   */
  static std::string GetDeviceDescriptions();

  /**
   * Creates the EGL display and context now if there is none yet (Render() does it too).
   * Returns false, after reporting why with vtkErrorMacro, when that is impossible.
   */
  bool EnsureContext();

  /**
   * True when the window holds an EGL context.
   */
  bool HasContext();

  /**
   * Why the last attempt to create the context failed ("" when it did not fail).
   */
  const char* GetInitializationError();

  ///@{
  /**
   * What the window got, once it has a context: the platform ("device", "surfaceless" or
   * "default"; "" before), the device index (-1 when not on the device platform), the EGL
   * vendor and version strings, and OpenGL's GL_VENDOR, GL_RENDERER and GL_VERSION.
   */
  const char* GetPlatformInUse();
  int GetDeviceIndexInUse();
  const char* GetEGLVendor();
  const char* GetEGLVersion();
  const char* GetGLVendor();
  const char* GetGLRenderer();
  const char* GetGLVersion();
  ///@}

  ///@{
  /**
   * vtkRenderWindow and vtkOpenGLRenderWindow API, on EGL.
   */
  void Initialize() override;
  void Finalize() override;
  void Start() override;
  void Frame() override;
  void Render() override;
  void WaitForCompletion() override;
  void MakeCurrent() override;
  void ReleaseCurrent() override;
  bool IsCurrent() override;
  void PushContext() override;
  void PopContext() override;
  vtkTypeBool IsDirect() override;
  int SupportsOpenGL() override;
  const char* ReportCapabilities() override;
  void OpenGLInitContext() override;
  int* GetScreenSize() VTK_SIZEHINT(2) override;
  void* GetGenericDisplayId() override;
  void* GetGenericContext() override;
  int GetColorBufferSizes(int* rgba) override;
  int GetDepthBufferSize() override;
  ///@}

  /**
   * The window is never shown: requests to show it are ignored.
   */
  void SetShowWindow(bool show) override;

  ///@{
  /**
   * Pixel access, which does nothing (and returns VTK_ERROR) when the window has no context or
   * has not rendered yet.
   */
  using Superclass::GetZbufferData;
  int GetZbufferData(int x1, int y1, int x2, int y2, float* z) override;
  using Superclass::SetZbufferData;
  int SetZbufferData(int x1, int y1, int x2, int y2, float* buffer) override;
  using Superclass::SetPixelData;
  int SetPixelData(
    int x, int y, int x2, int y2, unsigned char* data, int front, int right) override;
  using Superclass::SetRGBAPixelData;
  int SetRGBAPixelData(
    int x, int y, int x2, int y2, float* data, int front, int blend = 0, int right = 0) override;
  using Superclass::SetRGBACharPixelData;
  int SetRGBACharPixelData(int x, int y, int x2, int y2, unsigned char* data, int front,
    int blend = 0, int right = 0) override;
  void DrawPixels(
    int x1, int y1, int x2, int y2, int numComponents, int dataType, void* data) override;
  void DrawPixels(int dstXmin, int dstYmin, int dstXmax, int dstYmax, int srcXmin, int srcYmin,
    int srcXmax, int srcYmax, int srcWidth, int srcHeight, int numComponents, int dataType,
    void* data) override;
  void DrawPixels(
    int srcWidth, int srcHeight, int numComponents, int dataType, void* data) override;
  ///@}

protected:
  vtkHeadlessEGLRenderWindow();
  ~vtkHeadlessEGLRenderWindow() override;

  void CreateAWindow() override;
  void DestroyWindow() override;

  // Nothing is shown, so the final blit to a default framebuffer (which a surfaceless context
  // does not have) is skipped.
  void BlitDisplayFramebuffersToHardware() override;

  int ReadPixels(
    const vtkRecti& rect, int front, int glFormat, int glType, void* data, int right) override;

  // True when there is a context and VTK's framebuffers exist (something was rendered).
  bool CanAccessPixels();

  int Platform;
  bool PreferSurfacelessContext;

private:
  vtkHeadlessEGLRenderWindow(const vtkHeadlessEGLRenderWindow&) = delete;
  void operator=(const vtkHeadlessEGLRenderWindow&) = delete;

  class vtkInternals;
  vtkInternals* Internals;
};

#endif
