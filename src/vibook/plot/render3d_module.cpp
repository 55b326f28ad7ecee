// The entry point of the renderer module (libvibook_render3d.so): the OSMesa or EGL backend
// lives in a module of its own, loaded by render3d_loader.cpp when the first 3-D figure is
// drawn, so that no other command loads Mesa and LLVM (about 45 MB of mappings) at start.
#include <exception>
#include <string>
#include <vector>

#include "vibook/plot/render3d.hpp"

extern "C" __attribute__((visibility("default"))) bool vibook_render3d_lines(
    const std::vector<vibook::plot::Polyline3D>* lines, const vibook::plot::View3D* view,
    vibook::plot::Image* out, std::string* error) {
  try {
    *out = vibook::plot::render_lines(*lines, *view);
    return true;
  } catch (const std::exception& e) {
    *error = e.what();
    return false;
  }
}
