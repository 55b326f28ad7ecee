#!/usr/bin/env bash
# vibook build driver.
#   ./build.sh book [--gcc|--sanitize]  install missing Debian packages, build, regenerate
#                                       every figure and the claims report, build the HTML book
#   ./build.sh test [--gcc|--sanitize]  same set-up and book, then every test through ctest
#   ./build.sh bench                    build and run the Google Benchmark suite (tests/bench)
#   ./build.sh cli                      build only the library and the `vibook` command
# The build uses clang++ (about four fifths of g++'s compile time, the same outputs).
# --gcc builds with g++ instead (build tree build-gcc/); --sanitize uses the ASan+UBSan preset
# (g++, build tree build-sanitize/).
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")"

usage() { sed -n '2,10p' "$0" | sed 's/^# \{0,1\}//'; }

action=${1:-}
[ $# -gt 0 ] && shift
sanitize=0
gcc=0
for arg in "$@"; do
  case "$arg" in
    --sanitize) sanitize=1 ;;
    --gcc) gcc=1 ;;
    -h|--help) usage; exit 0 ;;
    *) echo "build.sh: unknown option '$arg' (see ./build.sh --help)" >&2; exit 2 ;;
  esac
done
case "$action" in
  book|test|bench|cli) ;;
  -h|--help|help) usage; exit 0 ;;
  "") usage >&2; exit 2 ;;
  *) echo "build.sh: unknown action '$action' (book, test, bench or cli)" >&2; exit 2 ;;
esac

# --- Debian 12 packages -------------------------------------------------------------------
packages=(g++ clang cmake ninja-build pkg-config libeigen3-dev doctest-dev libcli11-dev
  nlohmann-json3-dev libfmt-dev libboost-dev libbenchmark-dev gnuplot-nox doxygen
  libjs-mathjax fonts-mathjax python3 libpng-dev libosmesa6-dev libegl-dev libopengl-dev
  libqd-dev libmpfr-dev libgmp-dev libginac-dev python3-sympy)
if [ "$action" = test ]; then
  packages+=(chromium chromium-driver python3-selenium)
fi
missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${db:Status-Status}' "$p" 2>/dev/null | grep -qx installed; then
    missing+=("$p")
  fi
done
if [ ${#missing[@]} -gt 0 ]; then
  if [ "$(id -u)" -eq 0 ]; then
    echo "build.sh: installing missing Debian packages: ${missing[*]}" >&2
    export DEBIAN_FRONTEND=noninteractive
    apt-get update -qq
    apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
  else
    echo "build.sh: missing Debian packages. Install them with:" >&2
    echo "  sudo apt-get install --no-install-recommends ${missing[*]}" >&2
    exit 1
  fi
fi

# --- configure and build -----------------------------------------------------------------
preset=dev
bdir=build
if [ $sanitize -eq 1 ]; then
  preset=sanitize bdir=build-sanitize
elif [ $gcc -eq 1 ]; then
  preset=gcc bdir=build-gcc
fi
cmake --preset "$preset" >/dev/null
jobs=$(nproc 2>/dev/null || echo 2)

case "$action" in
  cli)
    cmake --build "$bdir" --target vibook -j "$jobs"
    echo "vibook: $PWD/$bdir/src/cli/vibook"
    ;;
  book)
    cmake --build "$bdir" -j "$jobs"
    # The book shows the benchmark table: build them (not part of the default build, which the
    # test build and CI use); the book target runs them (about four minutes).
    cmake --build "$bdir" --target vibook_bench -j "$jobs"
    VIBOOK_BOOK_BENCH=1 VIBOOK_LONG_STUDIES=1 cmake --build "$bdir" --target book
    echo "book: $PWD/$bdir/book/html/index.html"
    ;;
  test)
    # One build of everything and the book: the book starts as soon as the command is linked,
    # while the test units still compile (the machine's cores stay busy to the end). The tests
    # run one more than cores at a time: a test waiting on a child (a stepper's timeout, a
    # Python host, the browser) would otherwise leave a core idle. Measured on 2 cores: ctest
    # -j 2 used 85 % of the cores' time (592 CPU-s in 348 s), -j 3 93 % (321 s). The build does
    # not gain so: a fresh clone's build took 504 s at -j 3 and 472 s at -j 2.
    cmake --build "$bdir" -j "$jobs" --target all book
    ctest --test-dir "$bdir" --output-on-failure -j "$((jobs + 1))"
    ;;
  bench)
    cmake --build "$bdir" --target vibook_bench -j "$jobs"
    mkdir -p "$bdir/bench"
    "$bdir/tests/bench/vibook_bench" --benchmark_out="$bdir/bench/bench.json" \
      --benchmark_out_format=json --benchmark_repetitions=5 \
      --benchmark_report_aggregates_only=true
    python3 tests/bench/sympy_lmod.py --table "$bdir/bench/sympy.txt" --timeout 120
    python3 tests/bench/bench_table.py --sympy "$bdir/bench/sympy.txt" "$bdir/bench/bench.json" \
      > "$bdir/bench/bench.md"
    cat "$bdir/bench/bench.md"
    echo "table for the book: $PWD/$bdir/bench/bench.md (rebuild the book to include it)"
    ;;
esac
