// EGL backend of the off-screen renderer: a surfaceless Mesa display
// (EGL_MESA_platform_surfaceless), a desktop-OpenGL compatibility context without any surface, and
// a framebuffer object. Used where OSMesa is not available; links libEGL and libOpenGL (GLVND),
// never libGL.
#define GL_GLEXT_PROTOTYPES 1
#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <GL/gl.h>
#include <GL/glext.h>

#include <algorithm>
#include <mutex>

#include "vibook/plot/render3d.hpp"

namespace vibook::plot {

std::string render_backend() { return "EGL-surfaceless"; }

Image render_lines(const std::vector<Polyline3D>& lines, const View3D& view) {
  static std::mutex mutex;
  std::lock_guard<std::mutex> lock(mutex);
  auto get_display = reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(
      eglGetProcAddress("eglGetPlatformDisplayEXT"));
  if (!get_display) throw RenderError("EGL: eglGetPlatformDisplayEXT is not available");
  EGLDisplay dpy = get_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
  if (dpy == EGL_NO_DISPLAY || !eglInitialize(dpy, nullptr, nullptr)) {
    throw RenderError("EGL: no surfaceless Mesa display");
  }
  if (!eglBindAPI(EGL_OPENGL_API)) {
    eglTerminate(dpy);
    throw RenderError("EGL: desktop OpenGL is not supported");
  }
  // A surfaceless context needs no framebuffer configuration (EGL_KHR_no_config_context);
  // take one if the display offers any, else none.
  const EGLint attribs[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE};
  EGLConfig config = EGL_NO_CONFIG_KHR;
  EGLint n = 0;
  if (!eglChooseConfig(dpy, attribs, &config, 1, &n) || n < 1) config = EGL_NO_CONFIG_KHR;
  EGLContext ctx = eglCreateContext(dpy, config, EGL_NO_CONTEXT, nullptr);
  if (ctx == EGL_NO_CONTEXT || !eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, ctx)) {
    eglTerminate(dpy);
    throw RenderError("EGL: could not make a surfaceless context current");
  }
  GLuint fbo = 0, color = 0, depth = 0;
  glGenFramebuffers(1, &fbo);
  glBindFramebuffer(GL_FRAMEBUFFER, fbo);
  glGenRenderbuffers(1, &color);
  glBindRenderbuffer(GL_RENDERBUFFER, color);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, view.width, view.height);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, color);
  glGenRenderbuffers(1, &depth);
  glBindRenderbuffer(GL_RENDERBUFFER, depth);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, view.width, view.height);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth);
  if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
    eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    eglDestroyContext(dpy, ctx);
    eglTerminate(dpy);
    throw RenderError("EGL: incomplete framebuffer object");
  }
  internal::draw_scene(lines, view);
  std::vector<std::uint8_t> buf(std::size_t(view.width) * std::size_t(view.height) * 4);
  glReadPixels(0, 0, view.width, view.height, GL_RGBA, GL_UNSIGNED_BYTE, buf.data());
  glDeleteRenderbuffers(1, &depth);
  glDeleteRenderbuffers(1, &color);
  glDeleteFramebuffers(1, &fbo);
  eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  eglDestroyContext(dpy, ctx);
  eglTerminate(dpy);
  return internal::from_bottom_up(buf, view.width, view.height);
}

}  // namespace vibook::plot
