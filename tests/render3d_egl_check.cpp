// The EGL-surfaceless fallback of the 3-D renderer, checked on its own: a helix renders to a
// non-blank image, twice identically, and is written as PNG. Prints a closing line.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "vibook/plot/render3d.hpp"

int main(int argc, char** argv) {
  using namespace vibook::plot;
  Polyline3D helix;
  for (int i = 0; i <= 2000; ++i) {
    const double s = 0.01 * i;
    helix.points.push_back({std::cos(s), std::sin(s), 0.1 * s});
  }
  int failed = 0;
  try {
    const Image a = render_lines({helix}, View3D{}), b = render_lines({helix}, View3D{});
    std::size_t ink = 0;
    for (std::size_t i = 0; i < a.rgba.size(); i += 4)
      ink += a.rgba[i] < 200 || a.rgba[i + 1] < 200;
    if (ink < 1000)
      ++failed, std::fprintf(stderr, "EGL fallback: image is blank (%zu dark pixels)\n", ink);
    if (a.rgba != b.rgba) ++failed, std::fprintf(stderr, "EGL fallback: two renders differ\n");
    if (argc > 1) write_png(argv[1], a);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "EGL fallback: %s\n", e.what());
    failed = 2;
  }
  std::printf("render3d_egl_fallback (%s): %d passed, %d failed\n", render_backend().c_str(),
              2 - std::min(failed, 2), std::min(failed, 2));
  return failed ? 1 : 0;
}
