// Precompiled once per target (top-level CMakeLists.txt, option VIBOOK_PCH): the heavy headers
// that nearly every translation unit of vibook_lib, the `vibook` command and the doctests
// parses (Eigen with AutoDiff, Boost.Multiprecision and libqd through precision.hpp, fmt,
// nlohmann-json). Measured on a 2-core machine: a typical doctest unit compiles in 19.6 s
// instead of 24.8 s. Nothing here may depend on a macro a source file defines first.
#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Dense>
#include <fmt/format.h>
#include <fmt/ranges.h>
#include <nlohmann/json.hpp>
#include <unsupported/Eigen/AutoDiff>

#include "vibook/core/precision.hpp"
