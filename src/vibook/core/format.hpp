/// \file format.hpp
/// \brief Numbers in messages, for the header-only core (which must not need a formatting
/// library at link time). Each function gives what printf gives for the same conversion
/// (std::to_chars is correctly rounded, as glibc's printf is).
#pragma once

#include <charconv>
#include <string>

namespace vibook::text {

/// printf("%.{digits}g", x).
inline std::string g(double x, int digits) {
  char buf[64];
  const auto r = std::to_chars(buf, buf + sizeof buf, x, std::chars_format::general, digits);
  return std::string(buf, r.ptr);
}

/// printf("%.{digits}e", x).
inline std::string e(double x, int digits) {
  char buf[64];
  const auto r = std::to_chars(buf, buf + sizeof buf, x, std::chars_format::scientific, digits);
  return std::string(buf, r.ptr);
}

}  // namespace vibook::text
