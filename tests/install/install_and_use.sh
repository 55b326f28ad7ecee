#!/usr/bin/env bash
# Installs vibook from this build tree into a temporary prefix and builds examples/ against it
# as a separate project would: with CMake's find_package(vibook), and with pkg-config.
# Usage: install_and_use.sh BUILD_DIR SOURCE_DIR [EXTRA_CXX_FLAGS]
set -euo pipefail
build=$1 src=$2 flags=${3:-}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
prefix=$tmp/prefix

cmake --install "$build" --prefix "$prefix" >"$tmp/install.log" || { cat "$tmp/install.log"; exit 1; }
# The library (headers of the numerics and the engine, the engine's archive, the CMake package
# and the pkg-config files) and the command; none of the reproduction code's headers.
for f in include/vibook/mechanics/del_solver.hpp include/vibook/modified/engine.hpp \
         include/vibook/core/precision.hpp include/vibook/verify/verify.hpp \
         lib/libvibook_modified.a lib/cmake/vibook/vibookConfig.cmake \
         lib/cmake/vibook/vibookConfigVersion.cmake lib/pkgconfig/vibook.pc \
         share/doc/vibook/README.md share/doc/vibook/08-verify.md \
         share/doc/vibook/examples/henon_heiles_simpson.cpp share/doc/vibook/examples/CMakeLists.txt; do
  [ -e "$prefix/$f" ] || { echo "FAIL: $f not installed"; exit 1; }
done
if find "$prefix/include" -name 'checks.hpp' -o -name 'check_*.hpp' -o -name '*_test.cpp' \
     -o -path '*/claims/*' -o -path '*/figures/*' | grep -q .; then
  echo "FAIL: reproduction code installed:"; find "$prefix/include" -name 'check*'; exit 1
fi

# 1. CMake: find_package(vibook) in a separate project.
cmake -S "$src/examples" -B "$tmp/build" -G Ninja -DCMAKE_BUILD_TYPE=Release \
      -DCMAKE_PREFIX_PATH="$prefix" -DCMAKE_CXX_FLAGS="$flags" >"$tmp/configure.log" \
  || { cat "$tmp/configure.log"; exit 1; }
cmake --build "$tmp/build" >"$tmp/build.log" || { cat "$tmp/build.log"; exit 1; }
"$tmp/build/henon_heiles_simpson" || { echo "FAIL: the example's checks failed"; exit 1; }

# 2. pkg-config: the header-only core needs no library at all.
cat >"$tmp/core_only.cpp" <<'CPP'
#include <cmath>

#include "vibook/epavi/mechanical.hpp"
#include "vibook/integrators/kernels.hpp"
#include "vibook/kepler/kepler.hpp"
#include "vibook/problems/problems.hpp"
#include "vibook/verify/verify.hpp"
int main() {
  // The closed-form EpAVI, header-only: 1000 steps on Kepler e = 0.5 keep the discrete energy.
  const auto orbit = vibook::KeplerOrbit::perihelion(0.5);
  vibook::MechanicalEpAVI<vibook::Kepler> ep{vibook::Kepler{}};
  auto st = ep.start(0.0, orbit.at(0.0).q, 1e-3, orbit.at(1e-3).q);
  const double E1 = st.E;
  for (int k = 0; k < 1000; ++k) ep.step(st);
  if (!(std::abs(st.E - E1) <= 1e-13)) return 2;
  vibook::StormerVerlet<vibook::Pendulum> sv;
  const vibook::verify::Step step = [&](Eigen::VectorXd& z, double h) {
    vibook::verify::step_qp<1>(sv, z, h);
  };
  Eigen::VectorXd z(2);
  z << 1.0, 0.0;
  const auto r = vibook::verify::reversibility_defect(step, {z}, 0.1, 1e-14);
  return r.passed ? 0 : 1;
}
CPP
export PKG_CONFIG_PATH=$prefix/lib/pkgconfig
# shellcheck disable=SC2046,SC2086
g++ -std=c++20 -O2 $flags $(pkg-config --cflags vibook) "$tmp/core_only.cpp" -o "$tmp/core_only" \
    $(pkg-config --libs vibook)
"$tmp/core_only" || { echo "FAIL: core-only program"; exit 1; }
pkg-config --exists --print-errors vibook-modified vibook-precision
# The README's line, in its order (the sources before the libraries, -O2), on the example with
# the engine: it must link.
# shellcheck disable=SC2046,SC2086
g++ -std=c++20 -O2 $flags "$prefix/share/doc/vibook/examples/henon_heiles_simpson.cpp" \
    $(pkg-config --cflags --libs vibook-modified) -o "$tmp/example_pc" ||
  { echo "FAIL: the README's pkg-config line does not build the example"; exit 1; }
"$tmp/example_pc" >/dev/null || { echo "FAIL: the example built by pkg-config"; exit 1; }
# `vibook modified` as a library call (command.hpp), whose printing uses fmt: a program linking
# vibook-modified alone must link (fmt among the archive's requirements) and print what the
# command prints.
cat >"$tmp/derive.cpp" <<'CPP'
#include <iostream>
#include "vibook/modified/command.hpp"
int main() {
  vibook::modified::Derivation d;  // Stormer-Verlet, a generic potential, order h^2
  std::cout << vibook::modified::derive(d);
}
CPP
# shellcheck disable=SC2046,SC2086
g++ -std=c++20 -O2 $flags "$tmp/derive.cpp" $(pkg-config --cflags --libs vibook-modified) \
    -o "$tmp/derive" || { echo "FAIL: modified::derive does not link from vibook-modified"; exit 1; }
"$tmp/derive" >"$tmp/derive.txt" && "$prefix/bin/vibook" modified --method sv --order 2 >"$tmp/cmd.txt" &&
  cmp -s "$tmp/derive.txt" "$tmp/cmd.txt" ||
  { echo "FAIL: modified::derive differs from vibook modified:"; diff "$tmp/cmd.txt" "$tmp/derive.txt" | head -5; exit 1; }

# 3. The installed command, with its scripts under the prefix: a verify report with its figure.
[ -x "$prefix/bin/vibook" ] && [ -f "$prefix/share/vibook/figures/verify-report.gp" ] ||
  { echo "FAIL: vibook or its figure scripts not installed"; exit 1; }
(cd "$tmp" && "$prefix/bin/vibook" verify --ld '(q1-q0)^2/(2*h) - h*V((q0+q1)/2)' --potential 'x^2/2' \
   --q0 1 --p0 0 --steps 2048 --report rep >/dev/null) || { echo "FAIL: installed vibook verify"; exit 1; }
[ -s "$tmp/rep/verify-report.svg" ] || { echo "FAIL: installed vibook drew no figure"; exit 1; }
echo "install and use: ok"
