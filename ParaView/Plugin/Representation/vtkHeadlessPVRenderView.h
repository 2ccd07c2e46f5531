/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkHeadlessPVRenderView.h

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
/**
 * @class   vtkHeadlessPVRenderView
 * @brief   ParaView's render view, able to render on the plugin's EGL window without X
 *
 * Debian's ParaView 5.11 is built for GLX only: pvbatch and pvserver abort without an X server.
 * With the plugin loaded, the module TiledRayCast::RenderingHeadless makes a plain
 * vtkRenderWindow::New() give a vtkHeadlessEGLRenderWindow where no X display answers, so the
 * window of a pvbatch or pvserver process (vtkPVProcessWindow) is an EGL one: a GPU, or Mesa's
 * llvmpipe without one. Each view renders into a window of ParaView's own that shares that
 * process window's context; it initialises itself with GLEW, and Debian's GLEW (the GLX flavour)
 * refuses any context but a GLX one, so that window would report "GLEW could not be initialized"
 * at every render. This view, which the plugin's object factory gives for every
 * vtkPVRenderView::New(), initialises its window on the process window's EGL context instead,
 * once, before its first render (vtkHeadlessSharedWindowInitializer; nothing is done
 * when the process window is not an EGL one), and picks the EGL device of its rank first:
 *
 * 1. ParaView's `--displays` (one device index per rank, by rank, as ParaView assigns them);
 * 2. the environment variable VTK_DEFAULT_EGL_DEVICE_INDEX, for every rank of the process group
 *    (what VTK's EGL window reads too);
 * 3. otherwise the rank's local rank on its machine (Open MPI's OMPI_COMM_WORLD_LOCAL_RANK,
 *    MPICH's MPI_LOCALRANKID, Slurm's SLURM_LOCALID; the MPI rank without them) modulo the
 *    machine's GPUs: one rank per GPU, or several ranks sharing each.
 *
 * An index that names no GPU gives a warning and the automatic choice (the first GPU, else the
 * CPU). Each rank logs the device it renders on (at vtkLogger's INFO verbosity), and warns when
 * it renders on the CPU while the machine has GPUs.
 *
 * ParaView also decides per process whether it can render, by opening the X display: without
 * one it turns remote rendering off for every view, so that pvbatch prints "Some of the
 * representations in this view require remote rendering which, however, is not available" and
 * several ranks wait on each other for ever. InitializeProcess(), which the plugin calls when it
 * is loaded, tells ParaView that a server or batch process renders with EGL, as its option
 * `--disable-xdisplay-test` would.
 */

#ifndef vtkHeadlessPVRenderView_h
#define vtkHeadlessPVRenderView_h

#include "vtkPVRenderView.h"
#include "vtkParaViewTiledRayCastModule.h" // For export macro

#include <string> // For std::string

class VTKPARAVIEWTILEDRAYCAST_EXPORT vtkHeadlessPVRenderView : public vtkPVRenderView
{
public:
  static vtkHeadlessPVRenderView* New();
  vtkTypeMacro(vtkHeadlessPVRenderView, vtkPVRenderView);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * As vtkPVRenderView's, after the view's window is set up on an EGL process window (at the
   * first render, where ParaView's own first render would initialise it).
   */
  void StillRender() override;
  void InteractiveRender() override;
  ///@}

  /**
   * Called when the plugin is loaded (paraview_add_plugin's INITIALIZERS): in a pvbatch or
   * pvserver process that will render with EGL (no X display answers, or ParaView's
   * `--displays` names EGL devices), sets ParaView's `--disable-xdisplay-test`, so that
   * ParaView counts the process as able to render. Load the plugin before the first view is
   * created (PV_PLUGIN_PATH or `--plugins` for pvserver; LoadPlugin() first in a pvbatch script).
   */
  static void InitializeProcess();

  /**
   * The EGL device index this rank asked for (-1: the automatic choice), and how it came to it
   * ("--displays", "VTK_DEFAULT_EGL_DEVICE_INDEX", "local rank N of M GPUs", "automatic"), once
   * the window is set up on EGL; "" otherwise.
   */
  vtkGetMacro(RequestedDeviceIndex, int);
  const char* GetDeviceChoice() { return this->DeviceChoice.c_str(); }

protected:
  vtkHeadlessPVRenderView();
  ~vtkHeadlessPVRenderView() override;

private:
  vtkHeadlessPVRenderView(const vtkHeadlessPVRenderView&) = delete;
  void operator=(const vtkHeadlessPVRenderView&) = delete;

  // Sets up the view's window on the process window's EGL context (once).
  void SetUpHeadlessWindow();
  // Picks the rank's EGL device (see the class description) and tells the process window.
  void ChooseDevice(class vtkHeadlessEGLRenderWindow* processWindow);

  bool HeadlessWindowChecked = false;
  int RequestedDeviceIndex = -1;
  std::string DeviceChoice;
};

#endif
