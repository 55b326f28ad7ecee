// The scene of the off-screen renderer, drawn with fixed-function OpenGL 1.x. The GL context
// comes from render3d_osmesa.cpp or render3d_egl.cpp.
#include <GL/gl.h>

#include <algorithm>
#include <limits>

#include "vibook/plot/render3d.hpp"

namespace vibook::plot {

namespace internal {

void draw_scene(const std::vector<Polyline3D>& lines, const View3D& view) {
  // Bounds: common scale for the first two coordinates, the third stretched to the box.
  double lo[3], hi[3];
  for (int k = 0; k < 3; ++k) {
    lo[k] = std::numeric_limits<double>::infinity();
    hi[k] = -lo[k];
  }
  for (const auto& l : lines) {
    for (const auto& p : l.points) {
      for (int k = 0; k < 3; ++k) {
        lo[k] = std::min(lo[k], p[k]);
        hi[k] = std::max(hi[k], p[k]);
      }
    }
  }
  const double span_xy = std::max({hi[0] - lo[0], hi[1] - lo[1], 1e-12});
  const double span_z = std::max(hi[2] - lo[2], 1e-12);
  const double c[3] = {0.5 * (lo[0] + hi[0]), 0.5 * (lo[1] + hi[1]), 0.5 * (lo[2] + hi[2])};
  auto map = [&](const std::array<double, 3>& p) {
    return std::array<float, 3>{float((p[0] - c[0]) / span_xy), float((p[1] - c[1]) / span_xy),
                                float(1.2 * (p[2] - c[2]) / span_z)};
  };

  glViewport(0, 0, view.width, view.height);
  glClearColor(1.0f, 1.0f, 1.0f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glDisable(GL_LIGHTING);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  const double aspect = double(view.width) / double(view.height);
  glOrtho(-1.05 * aspect, 1.05 * aspect, -1.05, 1.05, -10.0, 10.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  // Third coordinate up: tilt the scene so that z points up on the screen.
  glRotatef(-90.0f + view.elevation_deg, 1.0f, 0.0f, 0.0f);
  glRotatef(view.azimuth_deg, 0.0f, 0.0f, 1.0f);

  if (view.box) {
    const float bx = float(0.5 * (hi[0] - lo[0]) / span_xy),
                by = float(0.5 * (hi[1] - lo[1]) / span_xy);
    const float bz = 0.6f;
    glColor3f(0.75f, 0.75f, 0.75f);
    glLineWidth(1.0f);
    glBegin(GL_LINES);
    const float xs[2] = {-bx, bx}, ys[2] = {-by, by}, zs[2] = {-bz, bz};
    for (float y : ys)
      for (float z : zs) {
        glVertex3f(-bx, y, z);
        glVertex3f(bx, y, z);
      }
    for (float x : xs)
      for (float z : zs) {
        glVertex3f(x, -by, z);
        glVertex3f(x, by, z);
      }
    for (float x : xs)
      for (float y : ys) {
        glVertex3f(x, y, -bz);
        glVertex3f(x, y, bz);
      }
    glEnd();
  }
  for (const auto& l : lines) {
    glColor3f(l.color[0], l.color[1], l.color[2]);
    glLineWidth(l.width);
    glBegin(GL_LINE_STRIP);
    for (const auto& p : l.points) {
      const auto q = map(p);
      glVertex3f(q[0], q[1], q[2]);
    }
    glEnd();
  }
  glFinish();
}

}  // namespace internal

}  // namespace vibook::plot
