/*=========================================================================

  Program:   TiledRayCast
  Module:    vtkHeadlessObjectFactory.h

  Copyright (c) the TiledRayCast authors
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
/**
 * @class   vtkHeadlessObjectFactory
 * @brief   makes vtkRenderWindow::New() pick X or EGL, the way VTK 9.2 and later do
 *
 * This object factory is registered by the module's autoinit (C++ programs that name
 * TiledRayCast::RenderingHeadless in vtk_module_autoinit, VTK's test drivers, and Python after
 * `import tiledraycast`), or by Install(). From then on a plain vtkRenderWindow::New() (in Python,
 * `vtkRenderWindow()`) returns
 *
 * - a vtkHeadlessEGLRenderWindow when there is no usable X display (DISPLAY unset, empty, or
 *   naming a server that does not answer), so that programs and tests run on servers, CI machines
 *   and GPU nodes without X;
 * - a vtkHeadlessXOpenGLRenderWindow (VTK's X window) when there is one.
 *
 * The choice can be made explicit, in this order of precedence:
 *
 * 1. SetBackend() (C++ and Python);
 * 2. the environment variable VTK_DEFAULT_OPENGL_WINDOW, read at every vtkRenderWindow::New(),
 *    with the class names of later VTK versions: `vtkEGLRenderWindow` (or
 *    `vtkHeadlessEGLRenderWindow`) for EGL, `vtkXOpenGLRenderWindow` for X, and
 *    `vtkOSOpenGLRenderWindow`, which gives the EGL window on Mesa's surfaceless platform (the
 *    CPU path: this module has no OSMesa window, see docs/headless.md for why).
 *
 * Asking for X when no X display answers gives a warning and the EGL window, because VTK's X
 * window would abort the process.
 *
 * vtkRenderWindowInteractor::New() follows the same choice: VTK's X interactor with X, and
 * vtkGenericRenderWindowInteractor (no X calls; Start() returns at once) without. VTK's test
 * drivers replace the interactor by their own vtkTestingInteractor in any case.
 *
 * VTK's own OpenGL and UI factories are registered before this one and would answer first, so
 * their vtkRenderWindow and vtkRenderWindowInteractor overrides are switched off when this factory
 * is installed; this factory then creates the X classes itself when X is chosen.
 *
 * @sa vtkHeadlessEGLRenderWindow vtkHeadlessXOpenGLRenderWindow
 */

#ifndef vtkHeadlessObjectFactory_h
#define vtkHeadlessObjectFactory_h

#include "vtkObjectFactory.h"
#include "vtkRenderingHeadlessModule.h" // For export macro

class VTKRENDERINGHEADLESS_EXPORT vtkHeadlessObjectFactory : public vtkObjectFactory
{
public:
  static vtkHeadlessObjectFactory* New();
  vtkTypeMacro(vtkHeadlessObjectFactory, vtkObjectFactory);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  const char* GetVTKSourceVersion() override;
  const char* GetDescription() override;

  /**
   * Registers the factory (once; later calls do nothing). The module's autoinit calls it; a
   * program that does not use vtk_module_autoinit can call it before creating windows.
   */
  static void Install();

  /**
   * True once Install() has run.
   */
  static bool IsInstalled();

  /**
   * Chooses the window behind vtkRenderWindow::New(): "auto" (or nullptr or "", the default:
   * X when a display answers, else EGL), "EGL", "X", "surfaceless", or one of the class names
   * listed in the class description. Returns false, with an error, for a name it does not
   * know (the setting is then unchanged).
   */
  static bool SetBackend(const char* name);

  /**
   * The backend set with SetBackend(): "auto" or a canonical name ("EGL", "surfaceless", "X").
   */
  static const char* GetBackend();

  /**
   * The class a vtkRenderWindow::New() would create now, after SetBackend(), the environment
   * and the X display have had their say: "vtkHeadlessEGLRenderWindow" or
   * "vtkHeadlessXOpenGLRenderWindow".
   */
  static const char* GetResolvedWindowClassName();

  /**
   * True when DISPLAY names an X server that accepts a connection (the answer is cached per
   * value of DISPLAY).
   */
  static bool HasUsableDisplay();

protected:
  vtkHeadlessObjectFactory();
  ~vtkHeadlessObjectFactory() override = default;

private:
  vtkHeadlessObjectFactory(const vtkHeadlessObjectFactory&) = delete;
  void operator=(const vtkHeadlessObjectFactory&) = delete;
};

#endif
