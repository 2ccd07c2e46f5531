/* E3: the same interposer, but inside a shared library that Python loads (RTLD_LOCAL, the way
 * Python loads extension modules such as the wrapped VTK modules). */
#define _GNU_SOURCE
#include <GL/glew.h>
#ifndef GLAPI
#define GLAPI extern
#endif
#include <GL/osmesa.h>
#include <dlfcn.h>
#include <stdio.h>
typedef void (*Proc)(void);
Proc glXGetProcAddressARB(const GLubyte* name)
{
  if (OSMesaGetCurrentContext())
    return (Proc)OSMesaGetProcAddress((const char*)name);
  Proc (*real)(const GLubyte*) = (Proc(*)(const GLubyte*))dlsym(RTLD_NEXT, "glXGetProcAddressARB");
  return real(name);
}
int probe(void)
{
  static unsigned char buf[16 * 16 * 4];
  const int attribs[] = { OSMESA_FORMAT, OSMESA_RGBA, OSMESA_PROFILE, OSMESA_CORE_PROFILE,
    OSMESA_CONTEXT_MAJOR_VERSION, 3, OSMESA_CONTEXT_MINOR_VERSION, 2, 0 };
  OSMesaContext ctx = OSMesaCreateContextAttribs(attribs, NULL);
  OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, 16, 16);
  GLenum r = glewInit();
  printf("in a library loaded by Python: glewInit -> %u (%s), GLEW_VERSION_3_2=%d\n", r,
    glewGetErrorString(r), GLEW_VERSION_3_2);
  fflush(stdout);
  return (int)r;
}
