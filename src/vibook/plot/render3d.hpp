/// \file render3d.hpp
/// \brief Off-screen 3-D line rendering to PNG. One backend per build: OSMesa (Debian
/// libosmesa6-dev, linked alone, never beside libGL) or, where OSMesa is not available
/// (it is gone from newer Mesa), EGL with a surfaceless Mesa display and a framebuffer
/// object. The scene is drawn by the same fixed-function OpenGL code in both.
#pragma once

#include <array>
#include <cstdint>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

namespace vibook::plot {

/// No off-screen renderer could be created (or none was built).
class RenderError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct Polyline3D {
  std::vector<std::array<double, 3>> points;
  std::array<float, 3> color{0.1f, 0.4f, 0.7f};
  float width = 2.0f;
};

struct View3D {
  int width = 900, height = 700;
  float elevation_deg = 22.0f;  ///< camera above the (x, y) plane
  float azimuth_deg = -55.0f;   ///< rotation about the vertical (third) axis
  bool box = true;              ///< draw the bounding box
};

/// An RGBA image, rows from top to bottom.
struct Image {
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgba;
};

/// Name of the backend compiled in: "OSMesa", "EGL-surfaceless" or "none".
std::string render_backend();

/// Render the polylines, scaled together into a unit box (the first two coordinates with a
/// common scale, the third stretched to the box height). Throws RenderError.
Image render_lines(const std::vector<Polyline3D>& lines, const View3D& view);

/// Write an RGBA image as PNG (libpng). Throws std::runtime_error on I/O failure.
void write_png(const std::filesystem::path& file, const Image& image);

namespace internal {
/// The fixed-function drawing shared by the backends (a current GL context is required).
void draw_scene(const std::vector<Polyline3D>& lines, const View3D& view);
/// An image from a bottom-up RGBA buffer as OpenGL reads it (rows reversed).
Image from_bottom_up(const std::vector<std::uint8_t>& buf, int width, int height);
}  // namespace internal

}  // namespace vibook::plot
