/* E2: route GLEW's glXGetProcAddressARB to OSMesa while an OSMesa context is current (symbol
 * interposition from the executable), then share the process with a GLX context. */
#define _GNU_SOURCE
#include <GL/glew.h>
#include <GL/glx.h>
#ifndef GLAPI
#define GLAPI extern
#endif
#include <GL/osmesa.h>
#include <dlfcn.h>
#include <stdio.h>
#include <string.h>

typedef void (*Proc)(void);
Proc glXGetProcAddressARB(const GLubyte* name)
{
  if (OSMesaGetCurrentContext())
    return (Proc)OSMesaGetProcAddress((const char*)name);
  static Proc (*real)(const GLubyte*) = NULL;
  if (!real)
    real = (Proc(*)(const GLubyte*))dlsym(RTLD_NEXT, "glXGetProcAddressARB");
  return real(name);
}
Proc glXGetProcAddress(const GLubyte* name) { return glXGetProcAddressARB(name); }

static unsigned char osbuf[16 * 16 * 4];
static OSMesaContext osctx;
static void osmesa_current(void) { OSMesaMakeCurrent(osctx, osbuf, GL_UNSIGNED_BYTE, 16, 16); }
static void osmesa_clear_red(const char* when)
{
  const GLfloat red[4] = { 1, 0, 0, 1 };
  memset(osbuf, 0, sizeof(osbuf));
  glClearBufferfv(GL_COLOR, 0, red); /* a GL 3.0 entry point: called through GLEW's table */
  glFinish();
  printf("  [%s] OSMesa: glClearBufferfv=%p, pixel after clear to red = %u,%u,%u\n", when,
    (void*)glClearBufferfv, osbuf[0], osbuf[1], osbuf[2]);
}

int main(void)
{
  const int attribs[] = { OSMESA_FORMAT, OSMESA_RGBA, OSMESA_PROFILE, OSMESA_CORE_PROFILE,
    OSMESA_CONTEXT_MAJOR_VERSION, 3, OSMESA_CONTEXT_MINOR_VERSION, 2, 0 };
  osctx = OSMesaCreateContextAttribs(attribs, NULL);
  osmesa_current();
  GLenum r = glewInit();
  printf("1. OSMesa alone: glewInit -> %u (%s), GLEW_VERSION_3_2=%d\n", r, glewGetErrorString(r), GLEW_VERSION_3_2);
  osmesa_clear_red("OSMesa only");

  Display* dpy = XOpenDisplay(NULL);
  if (!dpy) { printf("no X display\n"); return 0; }
  int att[] = { GLX_RGBA, GLX_DOUBLEBUFFER, None };
  XVisualInfo* vi = glXChooseVisual(dpy, DefaultScreen(dpy), att);
  GLXContext gc = glXCreateContext(dpy, vi, NULL, True);
  Window w = XCreateSimpleWindow(dpy, RootWindow(dpy, 0), 0, 0, 16, 16, 0, 0, 0);
  OSMesaMakeCurrent(NULL, NULL, 0, 0, 0);
  printf("2. GLX after OSMesa, GLEW table still from OSMesa: glXMakeCurrent -> %d\n", glXMakeCurrent(dpy, w, gc));
  const GLfloat green[4] = { 0, 1, 0, 1 };
  unsigned char px[4] = { 0, 0, 0, 0 };
  glClearBufferfv(GL_COLOR, 0, green);
  glReadPixels(0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, px);
  printf("  [GLX] clear to green through the OSMesa-filled table: X pixel = %u,%u,%u\n", px[0], px[1], px[2]);
  r = glewInit();
  printf("3. glewInit again with GLX current -> %u (%s)\n", r, glewGetErrorString(r));
  glClearBufferfv(GL_COLOR, 0, green);
  glReadPixels(0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, px);
  printf("  [GLX] clear to green through the GLX-filled table: X pixel = %u,%u,%u\n", px[0], px[1], px[2]);
  glXMakeCurrent(dpy, None, NULL);
  osmesa_current();
  osmesa_clear_red("OSMesa after GLX re-initialised GLEW");
  return 0;
}
