// Strict parsing of the command line's numbers (args.hpp).
#include "args.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <system_error>

#include <fmt/format.h>

#include "vibook/core/errors.hpp"

namespace vibook::cli {

// The whole text as one number (a leading '+' allowed); anything else names the argument.
double parse_number(const std::string& arg, const std::string& text) {
  const char* first = text.data();
  const char* last = text.data() + text.size();
  if (first != last && *first == '+') ++first;
  double v = 0;
  const auto [ptr, ec] = std::from_chars(first, last, v);
  require_argument(!text.empty(), arg, "expects a number, got an empty value");
  require_argument(ec != std::errc::result_out_of_range, arg,
                   fmt::format("'{}' is out of the range of double", text));
  require_argument(ec == std::errc() && ptr == last, arg,
                   fmt::format("'{}' is not a number", text));
  return v;
}

long long parse_integer(const std::string& arg, const std::string& text) {
  long long v = 0;
  const auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
  require_argument(!text.empty(), arg, "expects an integer, got an empty value");
  require_argument(ec != std::errc::result_out_of_range, arg,
                   fmt::format("'{}' is out of range", text));
  // Base 10, whole: "010" is ten (never octal), and "0x2", " 2", "+2", "2x" are refused.
  require_argument(
      ec == std::errc() && ptr == text.data() + text.size(), arg,
      fmt::format("'{}' is not an integer (digits in base 10, an optional leading '-')", text));
  return v;
}

std::vector<std::string> split_list(const std::string& arg, const std::string& text) {
  std::vector<std::string> out;
  std::size_t start = 0;
  for (int i = 1;; ++i) {
    const std::size_t comma = text.find(',', start);
    std::string item =
        text.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    require_argument(!item.empty(), arg,
                     fmt::format("'{}': number {} of the comma-separated list is empty", text, i));
    out.push_back(std::move(item));
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  return out;
}

std::vector<double> parse_list(const std::string& arg, const std::string& text) {
  std::vector<double> out;
  for (const auto& item : split_list(arg, text)) out.push_back(parse_number(arg, item));
  return out;
}

std::vector<double> parse_state(const std::string& arg, const std::string& text,
                                const std::vector<double>& dflt, const std::string& why) {
  std::vector<double> v = text.empty() ? dflt : parse_list(arg, text);
  require_argument(v.size() == dflt.size(), arg,
                   fmt::format("has {} components; {}", v.size(), why));
  for (double x : v) require_argument(std::isfinite(x), arg, "must be finite");
  return v;
}

std::vector<double> parse_step_list(const std::string& arg, const std::string& text, double t_end,
                                    int max_steps_log10) {
  std::vector<double> hs = parse_list(arg, text);
  require_argument(hs.size() >= 3, arg, "needs at least 3 step sizes");
  for (double h : hs)
    require_argument(h > 0 && h <= t_end && t_end / h <= std::pow(10.0, max_steps_log10), arg,
                     fmt::format("{} is not a step size in (T/1e{}, T]", h, max_steps_log10));
  std::vector<double> sorted = hs;
  std::sort(sorted.begin(), sorted.end());
  require_argument(std::adjacent_find(sorted.begin(), sorted.end()) == sorted.end(), arg,
                   "gives a step size twice; an order needs distinct steps");
  return hs;
}

}  // namespace vibook::cli
