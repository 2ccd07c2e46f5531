/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkHeadlessEGLDevices.h

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
/**
 * @class   vtkHeadlessEGLDevices
 * @brief   private: what vtkHeadlessEGLRenderWindow knows of EGL itself, apart from any window
 *
 * The EGL client extensions and entry points (looked up once), the EGL devices
 * (eglQueryDevicesEXT with what each tells about itself), the count of windows per EGLDisplay
 * (EGL hands the same display to every window of a platform and device, and eglTerminate would
 * pull it from under the others), the environment's default device, and EGL error names.
 * vtkHeadlessEGLContext builds the display and context on top of it.
 */

#ifndef vtkHeadlessEGLDevices_h
#define vtkHeadlessEGLDevices_h

// The window never talks to X: keep X11 types out of EGL's platform header.
#ifndef EGL_NO_X11
#define EGL_NO_X11
#endif
#include <EGL/egl.h>    // For EGLDisplay and friends
#include <EGL/eglext.h> // For the device and platform extensions

#include <string> // For std::string
#include <vector> // For std::vector

class vtkHeadlessEGLDevices
{
public:
  /**
   * EGL extension entry points, looked up once. Client extensions are those of EGL_NO_DISPLAY.
   */
  struct EntryPoints
  {
    PFNEGLQUERYDEVICESEXTPROC QueryDevices = nullptr;
    PFNEGLQUERYDEVICESTRINGEXTPROC QueryDeviceString = nullptr;
    PFNEGLQUERYDEVICEATTRIBEXTPROC QueryDeviceAttrib = nullptr;
    PFNEGLGETPLATFORMDISPLAYEXTPROC GetPlatformDisplay = nullptr;
    bool PlatformDevice = false;
    bool PlatformSurfaceless = false;
    std::string ClientExtensions;

    static const EntryPoints& Get();

  private:
    EntryPoints();
  };

  /**
   * One EGL device and what it tells about itself.
   */
  struct DeviceInfo
  {
    EGLDeviceEXT Handle = EGL_NO_DEVICE_EXT;
    std::string Extensions;
    bool Software = false;
    std::string DRMFile;
    EGLAttrib CUDADevice = -1;
  };

  /**
   * The devices eglQueryDevicesEXT lists (none when EGL cannot enumerate them).
   */
  static std::vector<DeviceInfo> QueryDevices();

  /**
   * One line per device, and whether Mesa's surfaceless platform is there (what
   * vtkHeadlessEGLRenderWindow::GetDeviceDescriptions() returns).
   */
  static std::string DescribeDevices();

  ///@{
  /**
   * eglInitialize and eglTerminate, counted per display: the display is terminated when its
   * last user releases it.
   */
  static bool InitializeDisplay(EGLDisplay display, EGLint* major, EGLint* minor);
  static void ReleaseDisplay(EGLDisplay display);
  ///@}

  /**
   * The environment's default device index (VTK_DEFAULT_EGL_DEVICE_INDEX), -1 when unset or not
   * a non-negative integer.
   */
  static int EnvironmentDeviceIndex();

  /**
   * The last EGL error, by name and number.
   */
  static std::string LastError();

  /**
   * Whether the space-separated `extensions` list `name` (whole words only).
   */
  static bool HasExtension(const char* extensions, const char* name);
};

#endif
// VTK-HeaderTest-Exclude: vtkHeadlessEGLDevices.h
