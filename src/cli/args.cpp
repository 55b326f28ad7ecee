// Strict parsing of the command line's numbers (args.hpp).
#include "args.hpp"

#include <charconv>
#include <system_error>

#include <fmt/format.h>

#include "vibook/core/errors.hpp"

namespace vibook::cli {

namespace {
void require(bool ok, const std::string& arg, const std::string& msg) {
  if (!ok) throw ArgumentError(arg, msg);
}
}  // namespace

// The whole text as one number (a leading '+' allowed); anything else names the argument.
double parse_number(const std::string& arg, const std::string& text) {
  const char* first = text.data();
  const char* last = text.data() + text.size();
  if (first != last && *first == '+') ++first;
  double v = 0;
  const auto [ptr, ec] = std::from_chars(first, last, v);
  require(!text.empty(), arg, "expects a number, got an empty value");
  require(ec != std::errc::result_out_of_range, arg,
          fmt::format("'{}' is out of the range of double", text));
  require(ec == std::errc() && ptr == last, arg, fmt::format("'{}' is not a number", text));
  return v;
}

long long parse_integer(const std::string& arg, const std::string& text) {
  long long v = 0;
  const auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
  require(!text.empty(), arg, "expects an integer, got an empty value");
  require(ec != std::errc::result_out_of_range, arg, fmt::format("'{}' is out of range", text));
  // Base 10, whole: "010" is ten (never octal), and "0x2", " 2", "+2", "2x" are refused.
  require(ec == std::errc() && ptr == text.data() + text.size(), arg,
          fmt::format("'{}' is not an integer (digits in base 10, an optional leading '-')", text));
  return v;
}

std::vector<double> parse_list(const std::string& arg, const std::string& text) {
  std::vector<double> out;
  std::size_t start = 0;
  for (int i = 1;; ++i) {
    const std::size_t comma = text.find(',', start);
    const std::string item =
        text.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    require(!item.empty(), arg,
            fmt::format("'{}': number {} of the comma-separated list is empty", text, i));
    out.push_back(parse_number(arg, item));
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  return out;
}

}  // namespace vibook::cli
