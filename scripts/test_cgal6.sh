#!/usr/bin/env bash
# Builds the examples, command-line programs and tests of the packages against CGAL 6.0.1
# (Debian 13's libcgal-dev, unpacked next to the system's CGAL 5.5.1 by scripts/fetch_cgal6.sh,
# which runs first when it is missing), fails on a compiler warning, then runs their tests with
# ctest; prints the CGAL version the build uses.
#   bash scripts/test_cgal6.sh BUILD_DIR [PACKAGE...] [-- CMAKE_OPTION...]
# The build is `all` of that configuration (both packages: tests, examples, programs); PACKAGE
# (Lex_optimal_chains, Polygon_partition_simplification; default both) and KINDS choose the tests
# that ctest runs. JOBS (default 2) jobs build and test; the compiler goes through ccache when present (CCACHE_DISABLE=1: not).
# KINDS (default "Tests Examples"): the tests of the test folders, of the example folders, or both;
# Demo: the headless tests of the plugins in CGAL Lab (configure with -DURBAN_BUILD_DEMO=ON;
# CGAL's Qt6 headers and Lab sources are then unpacked too: scripts/fetch_cgal6.sh --lab); Sweep:
# the data sweep (test/data_sweep, label sweep).
set -euo pipefail
cd "$(dirname "$0")/.."

fail() { echo "test_cgal6: $*" >&2; exit 1; }

[ $# -ge 1 ] || fail "usage: bash scripts/test_cgal6.sh BUILD_DIR [PACKAGE...] [-- CMAKE_OPTION...]"
build="$1"
shift
packages=()
while [ $# -gt 0 ] && [ "$1" != "--" ]; do
  case "$1" in
    Lex_optimal_chains|Polygon_partition_simplification) packages+=("$1") ;;
    *) fail "unknown package '$1' (Lex_optimal_chains or Polygon_partition_simplification)" ;;
  esac
  shift
done
[ $# -gt 0 ] && shift # the "--"
[ ${#packages[@]} -gt 0 ] || packages=(Lex_optimal_chains Polygon_partition_simplification)
jobs="${JOBS:-2}"

kinds=(${KINDS:-Tests Examples})
fetch_options=()
case " ${kinds[*]} " in *" Demo "*) fetch_options=(--lab) ;; esac
cgal_dir="$(bash scripts/fetch_cgal6.sh "${fetch_options[@]}")" || fail "no CGAL 6.0.1 (scripts/fetch_cgal6.sh failed)"
mkdir -p "$build"
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release -DBUILD_TESTING=ON -DCGAL_DIR="$cgal_dir" "$@" \
  | tee "$build/configure.log" || fail "cmake could not configure $build"
# the line of cmake/Urban_reconstruction_packages.cmake: "-- CGAL <version>: <include directory>"
cgal="$(sed -n 's/^-- CGAL \([0-9][0-9.]*\): /\1 /p' "$build/configure.log" | tail -n1)"
[ "${cgal%% *}" = "6.0.1" ] || fail "the build uses CGAL '${cgal:-?}', not 6.0.1 (CGAL_DIR=$cgal_dir)"

# the labels of the tests to run: the test and/or example folders of the packages, the demo
labels=""
for kind in "${kinds[@]}"; do
  case "$kind" in
    Tests|Examples) for package in "${packages[@]}"; do labels+="${package}_${kind}|"; done ;;
    Demo) labels+="demo|" ;;
    Sweep) labels+="sweep|" ;;
    *) fail "unknown kind '$kind' (Tests, Examples, Demo or Sweep)" ;;
  esac
done
labels="^(${labels%|})$"

# the tests, examples and programs of the packages (the examples left out with
# -DURBAN_BUILD_EXAMPLES=OFF; the demo added with -DURBAN_BUILD_DEMO=ON): `all` of this
# configuration, built in parallel (a list of targets would be built one after the other)
[ -n "$(cd "$build" && ctest -N -L "$labels" | grep -m1 'compilation')" ] || fail "no compilation test labelled $labels in $build"
cmake --build "$build" -j"$jobs" 2>&1 | tee "$build/build.log" \
  || fail "the build failed (see $build/build.log)"
if grep -q 'warning:' "$build/build.log"; then
  grep 'warning:' "$build/build.log" | sort -u >&2
  fail "the build has compiler warnings (see $build/build.log)"
fi

status=0
# with URBAN_SANITIZERS: UndefinedBehaviorSanitizer's reports with their call stacks
export UBSAN_OPTIONS="${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}"
(cd "$build" && ctest -j"$jobs" -L "$labels" --output-on-failure) || status=$?
echo "test_cgal6: ${packages[*]} built and tested with CGAL ${cgal%% *} (${cgal#* })"
exit $status
