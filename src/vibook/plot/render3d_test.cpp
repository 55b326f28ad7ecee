// Doctest of the off-screen 3-D renderer (the backend this build links: OSMesa here).
#include <cmath>
#include <stdexcept>
#include <string>

#include <doctest/doctest.h>

#include "vibook/plot/render3d.hpp"

using namespace vibook::plot;

TEST_CASE("3-D render: a worldline-like helix is drawn, not blank, identical across two renders") {
  REQUIRE_MESSAGE(render_backend() != "none",
                  "no off-screen renderer built: ./build.sh installs libosmesa6-dev");
  Polyline3D helix;
  for (int i = 0; i <= 3000; ++i) {
    const double s = 0.01 * i;
    helix.points.push_back({0.4 * std::cos(s) - 0.3, std::sin(s), 0.05 * s});
  }
  const View3D view;
  const Image a = render_lines({helix}, view), b = render_lines({helix}, view);
  REQUIRE(a.width == view.width);
  REQUIRE(a.rgba.size() == std::size_t(view.width * view.height * 4));
  std::size_t blue = 0, white = 0;
  for (std::size_t i = 0; i < a.rgba.size(); i += 4) {
    blue += a.rgba[i + 2] > 120 && a.rgba[i] < 80;  // the line's colour
    white += a.rgba[i] == 255 && a.rgba[i + 1] == 255 && a.rgba[i + 2] == 255;
  }
  MESSAGE(render_backend(), ": ", blue, " line pixels, ", white, " background pixels");
  CHECK(blue > 2000);                    // the curve is there
  CHECK(white > a.rgba.size() / 4 / 2);  // on a white background
  CHECK(a.rgba == b.rgba);               // deterministic
}

TEST_CASE("write_png: a write that fails (a full device) is one exception naming the file") {
  Image img;
  img.width = img.height = 64;
  img.rgba.assign(std::size_t(64) * 64 * 4, 128);
  // /dev/full accepts the open and fails every write with ENOSPC, as a full disk does; the
  // error reaches the caller as one message (libpng's own handler printed a second line).
  try {
    write_png("/dev/full", img);
    FAIL("writing to /dev/full succeeded");
  } catch (const std::runtime_error& e) {
    const std::string what = e.what();
    CHECK(what.find("cannot write /dev/full") != std::string::npos);
    CHECK(what.find('\n') == std::string::npos);
  }
}
