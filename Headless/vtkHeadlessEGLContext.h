/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkHeadlessEGLContext.h

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
/**
 * @class   vtkHeadlessEGLContext
 * @brief   private: the EGL display, context and surface of a vtkHeadlessEGLRenderWindow
 *
 * Create() chooses the display (the device the window or the environment names, else the first
 * GPU, else Mesa on the CPU: surfaceless, a software device, the default display) and creates
 * an OpenGL core-profile context on it, with a 1x1 pbuffer or no surface at all; Destroy()
 * releases them. What it got is recorded for the window to report. The window itself only
 * makes the context current and hands it to VTK.
 */

#ifndef vtkHeadlessEGLContext_h
#define vtkHeadlessEGLContext_h

#include "vtkHeadlessEGLDevices.h" // For EGL and vtkHeadlessEGLDevices::DeviceInfo

#include <string> // For std::string
#include <vector> // For std::vector

class vtkHeadlessEGLContext
{
public:
  EGLDisplay Display = EGL_NO_DISPLAY;
  EGLContext Context = EGL_NO_CONTEXT;
  EGLSurface Surface = EGL_NO_SURFACE; // a 1x1 pbuffer, or none (EGL_KHR_surfaceless_context)
  // Whether to go without a surface where the display allows it.
  bool PreferSurfaceless = false;

  // What Create() got.
  std::string PlatformInUse;
  int DeviceIndexInUse = -1;
  std::string EGLVendor;
  std::string EGLVersion;

  /**
   * Chooses and creates display and context for `platform` (a
   * vtkHeadlessEGLRenderWindow::PlatformType) and `requestedIndex` (-1: automatic). Returns
   * false with `error` set; `warnings` collects what the caller should tell the user even on
   * success.
   */
  bool Create(int platform, int requestedIndex, std::string& error, std::string& warnings);

  /**
   * Releases context, surface and display (the display only when no other window uses it).
   */
  void Destroy();

private:
  bool TryDisplay(EGLDisplay display, std::string& why);
  bool TryDevice(
    const std::vector<vtkHeadlessEGLDevices::DeviceInfo>& devices, int index, std::string& why);
  bool TrySurfaceless(std::string& why);
  bool ChooseConfig(EGLDisplay display, bool surfacelessContext, EGLConfig& config, bool& pbuffer);
  static EGLContext CreateCoreContext(EGLDisplay display, EGLConfig config);
};

#endif
// VTK-HeaderTest-Exclude: vtkHeadlessEGLContext.h
