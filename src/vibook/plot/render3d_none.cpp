// Built when neither OSMesa nor EGL/OpenGL is available: every render is a clear error.
#include "vibook/plot/render3d.hpp"

namespace vibook::plot {
std::string render_backend() { return "none"; }
Image render_lines(const std::vector<Polyline3D>&, const View3D&) {
  throw RenderError(
      "no off-screen renderer was built: install libosmesa6-dev (or libegl-dev and libopengl-dev) "
      "and reconfigure");
}
}  // namespace vibook::plot
