// The off-screen renderer as the library sees it: the backend module is loaded with dlopen on
// the first render_lines() call (render3d_module.cpp says why). VIBOOK_RENDER_MODULE in the
// environment names another module file; the default is the one this build made.
#include <dlfcn.h>

#include <cstdlib>
#include <mutex>
#include <string>
#include <vector>

#include "vibook/plot/gnuplot.hpp"
#include "vibook/plot/render3d.hpp"

namespace vibook::plot {

namespace {
using RenderFn = bool (*)(const std::vector<Polyline3D>*, const View3D*, Image*, std::string*);

struct Module {
  RenderFn render = nullptr;
  std::string error;
};

const Module& module() {
  static const Module m = [] {
    Module r;
    const char* env = std::getenv("VIBOOK_RENDER_MODULE");
    std::string path = VIBOOK_RENDER_MODULE_PATH;
#ifdef VIBOOK_INSTALL_MODULE_REL
    if (auto p = plot::installed_path(VIBOOK_INSTALL_MODULE_REL); !p.empty()) path = p.string();
#endif
    if (env && *env) path = env;
    void* handle = ::dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!handle) {
      const char* why = ::dlerror();
      r.error = "cannot load the 3-D renderer module '" + path + "': " + (why ? why : "?");
      return r;
    }
    r.render = reinterpret_cast<RenderFn>(::dlsym(handle, "vibook_render3d_lines"));
    if (!r.render) r.error = "'" + path + "' is not a vibook renderer module";
    return r;  // the module stays loaded until the process ends
  }();
  return m;
}
}  // namespace

std::string render_backend() { return VIBOOK_RENDER_BACKEND_NAME; }

Image render_lines(const std::vector<Polyline3D>& lines, const View3D& view) {
  const Module& m = module();
  if (!m.render) throw RenderError(m.error);
  Image image;
  std::string error;
  if (!m.render(&lines, &view, &image, &error)) throw RenderError(error);
  return image;
}

}  // namespace vibook::plot
