// OSMesa backend of the off-screen renderer: software rendering into a client buffer.
#include <GL/osmesa.h>

#include <algorithm>
#include <mutex>

#include "vibook/plot/render3d.hpp"

namespace vibook::plot {

std::string render_backend() { return "OSMesa"; }

Image render_lines(const std::vector<Polyline3D>& lines, const View3D& view) {
  static std::mutex mutex;  // one context at a time: OSMesa's current context is per thread,
  std::lock_guard<std::mutex> lock(mutex);  // but the figures may render concurrently
  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, nullptr);
  if (!ctx) throw RenderError("OSMesa: could not create a context");
  std::vector<std::uint8_t> buf(std::size_t(view.width) * std::size_t(view.height) * 4);
  if (!OSMesaMakeCurrent(ctx, buf.data(), GL_UNSIGNED_BYTE, view.width, view.height)) {
    OSMesaDestroyContext(ctx);
    throw RenderError("OSMesa: could not make the context current");
  }
  internal::draw_scene(lines, view);
  OSMesaMakeCurrent(nullptr, nullptr, 0, 0, 0);  // unbind before destroying
  OSMesaDestroyContext(ctx);
  return internal::from_bottom_up(buf, view.width, view.height);
}

}  // namespace vibook::plot
