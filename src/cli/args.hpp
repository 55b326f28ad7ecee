// Strict parsing of the command line's numbers, shared by the subcommands: the whole text is
// one number or the ArgumentError names the argument.
#pragma once

#include <string>
#include <vector>

namespace vibook::cli {

/// The whole text as one double (a leading '+' allowed).
double parse_number(const std::string& arg, const std::string& text);
/// The whole text as one integer.
long long parse_integer(const std::string& arg, const std::string& text);
/// "1,0.5": comma-separated numbers, none of them empty.
std::vector<double> parse_list(const std::string& arg, const std::string& text);

}  // namespace vibook::cli
