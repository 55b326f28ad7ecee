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
  Image img;
  img.width = view.width;
  img.height = view.height;
  std::vector<std::uint8_t> buf(std::size_t(view.width) * std::size_t(view.height) * 4);
  if (!OSMesaMakeCurrent(ctx, buf.data(), GL_UNSIGNED_BYTE, view.width, view.height)) {
    OSMesaDestroyContext(ctx);
    throw RenderError("OSMesa: could not make the context current");
  }
  internal::draw_scene(lines, view);
  OSMesaMakeCurrent(nullptr, nullptr, 0, 0, 0);  // unbind before destroying
  OSMesaDestroyContext(ctx);
  // OSMesa's rows run bottom-up; PNG's top-down.
  img.rgba.resize(buf.size());
  const std::size_t row = std::size_t(view.width) * 4;
  for (int y = 0; y < view.height; ++y) {
    std::copy_n(buf.data() + std::size_t(view.height - 1 - y) * row, row,
                img.rgba.data() + std::size_t(y) * row);
  }
  return img;
}

}  // namespace vibook::plot
