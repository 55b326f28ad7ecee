// PNG output of the off-screen renderer (libpng).
#include <png.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>
#include <string>

#include "vibook/plot/render3d.hpp"

namespace vibook::plot {

Image internal::from_bottom_up(const std::vector<std::uint8_t>& buf, int width, int height) {
  Image img;
  img.width = width;
  img.height = height;
  img.rgba.resize(buf.size());
  const std::size_t row = std::size_t(width) * 4;
  for (int y = 0; y < height; ++y) {
    std::copy_n(buf.data() + std::size_t(height - 1 - y) * row, row,
                img.rgba.data() + std::size_t(y) * row);
  }
  return img;
}

namespace {

// libpng's default handlers print to standard error; ours keep the message for the exception
// (one line on the command line, not two) and drop warnings.
struct PngErrors {
  std::string message;
  int errno_value = 0;
};
extern "C" void png_error_to_message(png_structp png, png_const_charp msg) {
  if (auto* e = static_cast<PngErrors*>(png_get_error_ptr(png))) {
    e->errno_value = errno;
    e->message = msg ? msg : "unknown error";
  }
  png_longjmp(png, 1);
}
extern "C" void png_warning_dropped(png_structp, png_const_charp) {}

}  // namespace

void write_png(const std::filesystem::path& file, const Image& image) {
  std::unique_ptr<FILE, int (*)(FILE*)> f(std::fopen(file.c_str(), "wb"), &std::fclose);
  if (!f) throw std::runtime_error("cannot open " + file.string() + " for writing");
  PngErrors errors;
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &errors, png_error_to_message,
                                            png_warning_dropped);
  png_infop info = png ? png_create_info_struct(png) : nullptr;
  if (!png || !info) {
    png_destroy_write_struct(&png, &info);
    throw std::runtime_error("libpng: out of memory");
  }
  if (setjmp(png_jmpbuf(png))) {
    png_destroy_write_struct(&png, &info);
    throw std::runtime_error("cannot write " + file.string() + ": " + errors.message +
                             (errors.errno_value != 0
                                  ? std::string(" (") + std::strerror(errors.errno_value) + ")"
                                  : std::string()));
  }
  png_init_io(png, f.get());
  png_set_IHDR(png, info, image.width, image.height, 8, PNG_COLOR_TYPE_RGBA, PNG_INTERLACE_NONE,
               PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_write_info(png, info);
  for (int y = 0; y < image.height; ++y) {
    png_write_row(png, image.rgba.data() + std::size_t(y) * std::size_t(image.width) * 4);
  }
  png_write_end(png, nullptr);
  png_destroy_write_struct(&png, &info);
  // The last buffered bytes are written by fclose: its failure (a full disk) is an error too.
  errno = 0;
  if (std::fclose(f.release()) != 0)
    throw std::runtime_error("cannot write " + file.string() + ": " + std::strerror(errno));
}

}  // namespace vibook::plot
