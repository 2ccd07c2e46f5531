/* E1: an OSMesa core context and Debian's GLX-flavoured GLEW. */
#include <GL/glew.h>
#ifndef GLAPI
#define GLAPI extern
#endif
#include <GL/osmesa.h>
#include <stdio.h>
#include <stdlib.h>
int main(void)
{
  const int attribs[] = { OSMESA_FORMAT, OSMESA_RGBA, OSMESA_DEPTH_BITS, 24, OSMESA_PROFILE,
    OSMESA_CORE_PROFILE, OSMESA_CONTEXT_MAJOR_VERSION, 4, OSMESA_CONTEXT_MINOR_VERSION, 5, 0 };
  OSMesaContext ctx = OSMesaCreateContextAttribs(attribs, NULL);
  static unsigned char buf[64 * 64 * 4];
  printf("OSMesaCreateContextAttribs(core 4.5) -> %p\n", (void*)ctx);
  printf("OSMesaMakeCurrent -> %d\n", OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, 64, 64));
  typedef const GLubyte* (*GetStringFn)(GLenum);
  GetStringFn osmesaGetString = (GetStringFn)OSMesaGetProcAddress("glGetString");
  printf("OSMesaGetProcAddress(glGetString)(GL_VERSION) = %s\n", osmesaGetString(GL_VERSION));
  const GLubyte* v = glGetString(GL_VERSION);
  printf("glGetString(GL_VERSION) as linked = %s\n", v ? (const char*)v : "(null)");
  GLenum r = glewInit();
  printf("glewInit -> %u (%s)\n", r, glewGetErrorString(r));
  printf("GLEW_VERSION_3_2 = %d, glGenVertexArrays = %p\n", GLEW_VERSION_3_2, (void*)glGenVertexArrays);
  return 0;
}
