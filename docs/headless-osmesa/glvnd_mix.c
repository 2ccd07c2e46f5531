#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <GL/glx.h>
#include <GL/gl.h>
#include <stdio.h>
int main(){
  Display* d = XOpenDisplay(NULL);
  int att[] = {GLX_RGBA, GLX_DOUBLEBUFFER, None};
  XVisualInfo* vi = glXChooseVisual(d, DefaultScreen(d), att);
  GLXContext gc = glXCreateContext(d, vi, NULL, True);
  Window w = XCreateSimpleWindow(d, RootWindow(d,0),0,0,10,10,0,0,0);
  printf("glXMakeCurrent: %d\n", glXMakeCurrent(d, w, gc));
  printf("GLX renderer %s\n", glGetString(GL_RENDERER));
  PFNEGLGETPLATFORMDISPLAYEXTPROC gpd = (void*)eglGetProcAddress("eglGetPlatformDisplayEXT");
  EGLDisplay ed = gpd(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, NULL);
  EGLint M,m; printf("eglInitialize %d\n", eglInitialize(ed,&M,&m));
  eglBindAPI(EGL_OPENGL_API);
  EGLint ca[]={EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE}; EGLConfig cfg; EGLint n;
  eglChooseConfig(ed, ca, &cfg, 1, &n);
  EGLContext ec = eglCreateContext(ed, cfg, EGL_NO_CONTEXT, NULL);
  printf("ctx %p\n", ec);
  EGLBoolean r = eglMakeCurrent(ed, EGL_NO_SURFACE, EGL_NO_SURFACE, ec);
  printf("eglMakeCurrent with GLX current: %d err 0x%x\n", r, eglGetError());
  glXMakeCurrent(d, None, NULL);
  r = eglMakeCurrent(ed, EGL_NO_SURFACE, EGL_NO_SURFACE, ec);
  printf("eglMakeCurrent after GLX release: %d err 0x%x, renderer %s\n", r, eglGetError(), glGetString(GL_RENDERER));
  Bool b = glXMakeCurrent(d, w, gc);
  printf("glXMakeCurrent with EGL current: %d\n", b);
  XSync(d, False);
  printf("glXGetCurrentContext %p\n", glXGetCurrentContext());
  eglMakeCurrent(ed, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  b = glXMakeCurrent(d, w, gc);
  printf("glXMakeCurrent after EGL release: %d renderer %s\n", b, glGetString(GL_RENDERER));
  return 0;
}
