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
/// The comma-separated items as text, none of them empty (parse_list's split).
std::vector<std::string> split_list(const std::string& arg, const std::string& text);
/// An initial state, --q0 or --p0: `text` as a list of `dflt.size()` finite numbers, or `dflt`
/// when it is empty; otherwise "ARG has K components; WHY" (`why`: "the system has 2 degrees of
/// freedom") or "ARG must be finite".
std::vector<double> parse_state(const std::string& arg, const std::string& text,
                                const std::vector<double>& dflt, const std::string& why);
/// The step sizes of an order study: at least 3, distinct, each in (T/10^max_steps_log10, T].
std::vector<double> parse_step_list(const std::string& arg, const std::string& text, double t_end,
                                    int max_steps_log10);

}  // namespace vibook::cli
