#!/usr/bin/env bash
# Quick start of the two packages on a fresh Debian 12 machine.
#   bash scripts/quickstart.sh run    install what is missing, build in Release, reconstruct
#                                     kitten.xyz (closed) and b9_training.ply (open: aerial
#                                     LiDAR), real scans from libcgal-demo, and simplify the
#                                     kinetic partition of 25 synthetic building footprints, and
#                                     build the LOD2 model of building.ply (a scan from libcgal-demo)
#                                     and of the buildings of the labelled tile b9_training.ply
#   bash scripts/quickstart.sh test   same set-up plus Qt5 and Xvfb, then build and run all tests
#                                     with ctest, the headless tests of the demo plugins included,
#                                     against Debian's CGAL 5.5.1; then the tests of both packages
#                                     again against CGAL 6.0.1 (Debian 13's
#                                     libcgal-dev, unpacked into build/cgal6 by
#                                     scripts/fetch_cgal6.sh, never installed), in build-cgal6/
#                                     (URBAN_SANITIZE=1: in build-cgal6-sanitized/, built by Debian's clang with
#                                     AddressSanitizer and UndefinedBehaviorSanitizer, the data
#                                     sweep included; any report fails its test),
#                                     with the headless tests of the plugins in CGAL 6.0.1's
#                                     CGAL Lab (Qt6: Debian 12's Qt 6.4; the Lab's sources
#                                     from Debian 13's libcgal-demo, unpacked the same way);
#                                     then each fuzz harness of a reader and of the command
#                                     lines for 20 s (scripts/fuzz.sh: libFuzzer,
#                                     AddressSanitizer and UndefinedBehaviorSanitizer, Debian's
#                                     clang)
#   bash scripts/quickstart.sh demo   same set-up, builds CGAL's Polyhedron demo with the plugins
#                                     of both packages (build-demo/) and starts it on kitten.xyz
#                                     and the 25 footprints (with a display; without one, says
#                                     how to start it)
set -euo pipefail
mode="${1:-run}"
case "$mode" in run|test|demo) ;; *) echo "usage: $0 run|test|demo" >&2; exit 2 ;; esac
cd "$(dirname "$0")/.."

packages=(cmake g++ make ccache libcgal-dev libcgal-demo libeigen3-dev libtbb-dev libgmp-dev
          libmpfr-dev libboost-dev libboost-timer-dev libcli11-dev nlohmann-json3-dev doxygen)
# the tiles over MPI ranks (lex_reconstruct_mpi) and their test with 2 and 3 ranks
# and the keys of Debian 13 (trixie), whose CGAL 6.0.1 the tests also use
# and the fuzzers (clang's libFuzzer and sanitizer runtimes)
if [ "$mode" = test ]; then packages+=(libopenmpi-dev openmpi-bin debian-archive-keyring clang libclang-rt-14-dev); fi
# the Polyhedron demo (Qt5, QtScript, CGAL's Qt5 headers) and its headless run (Xvfb, Mesa)
if [ "$mode" != run ]; then
  packages+=(qtbase5-dev qtscript5-dev libqt5svg5-dev libqt5opengl5-dev libcgal-qt5-dev xvfb xauth libgl1-mesa-dri)
fi
# CGAL Lab, CGAL 6's demo (Qt6, its QJSEngine from Qt Declarative), for the CGAL 6.0.1 pass
if [ "$mode" = test ]; then
  packages+=(qt6-base-dev qt6-declarative-dev qt6-svg-dev qt6-tools-dev libqt6opengl6-dev qt6-qpa-plugins)
fi
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "Installing: ${missing[*]}"
  sudo_cmd=""
  [ "$(id -u)" -eq 0 ] || sudo_cmd="sudo"
  $sudo_cmd apt-get update -q
  DEBIAN_FRONTEND=noninteractive $sudo_cmd apt-get install -y -q --no-install-recommends "${missing[@]}"
fi

jobs="$(nproc 2>/dev/null || echo 2)"
if [ "$mode" = run ]; then
  cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
  cmake --build build -j"$jobs" --target lex_reconstruct simplify_partition lod2_reconstruct
  mkdir -p results
  ./build/examples/Lex_optimal_chains/lex_reconstruct closed \
    build/cgal-data/data/points_3/kitten.xyz results/kitten_closed.off --json
  ./build/examples/Lex_optimal_chains/lex_reconstruct open \
    build/cgal-data/data/points_3/b9_training.ply results/b9_training_open.off --auto-boundary --json
  ./build/examples/Polygon_partition_simplification/simplify_partition \
    examples/Polygon_partition_simplification/data/footprints_25.txt results/footprints_25_simplified.geojson \
    --svg results/footprints_25_simplified.svg --json
  ./build/examples/Polygon_partition_simplification/lod2_reconstruct \
    build/cgal-data/data/points_3/building.ply results/building_lod2.city.json --planes segment_index --json
  ./build/examples/Polygon_partition_simplification/lod2_reconstruct \
    build/cgal-data/data/points_3/building.ply results/building_lod2.off --planes segment_index
  ./build/examples/Polygon_partition_simplification/lod2_reconstruct \
    build/cgal-data/data/points_3/b9_training.ply results/b9_training_lod2.city.json --classes 0:2 --json
  echo "The reconstructed surfaces are in $(pwd)/results/: kitten_closed.off (closed surface)" \
       "and b9_training_open.off (terrain bounded by its footprint); the simplified partition of" \
       "25 synthetic footprints: footprints_25_simplified.geojson (cells) and .svg (before/after);" \
       "the LOD2 model of building.ply: building_lod2.city.json (CityJSON 1.1) and building_lod2.off;" \
       "the buildings of the labelled aerial tile b9_training.ply: b9_training_lod2.city.json (LoD 1.2 and 2.2)"
elif [ "$mode" = demo ]; then
  cmake -S demo -B build-demo -DCMAKE_BUILD_TYPE=Release
  cmake --build build-demo -j"$jobs" --target urban_demo
  demo_command=(build-demo/polyhedron/Polyhedron_3 build-demo/cgal-data/data/points_3/kitten.xyz
                examples/Polygon_partition_simplification/data/footprints_25.txt)
  if [ -n "${DISPLAY:-}${WAYLAND_DISPLAY:-}" ]; then
    exec "${demo_command[@]}"
  fi
  echo "The demo is built; no display here. On a display, start it with: ${demo_command[*]}" \
       "(Operations > Point Set Processing > Surface Reconstruction, Operations on Polylines > Polygon Partition)"
else
  cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DBUILD_TESTING=ON -DURBAN_BUILD_DEMO=ON
  cmake --build build -j"$jobs"
  (cd build && ctest --output-on-failure -j"$jobs")
  # the second pass, on CGAL 6.0.1: the tests of the test folders and of the demo, built with
  # what they run (the plugins in CGAL Lab, the command-line programs), not the examples nor
  # the MPI programs (the sources of lod2_reconstruct and lex_reconstruct once more), nor the
  # data sweep, whose programs are those of the first pass. With URBAN_SANITIZE=1: built by
  # Clang with AddressSanitizer and UndefinedBehaviorSanitizer, the data sweep included (about
  # 16 minutes more on 2 cores without ccache: 34 to build, 9 to test, against 27)
  cgal6_options=(-DURBAN_WITH_MPI=OFF -DURBAN_BUILD_DEMO=ON -DURBAN_BUILD_EXAMPLES=OFF)
  if [ "${URBAN_SANITIZE:-0}" = 1 ]; then
    KINDS="Tests Sweep Demo" JOBS="$jobs" bash scripts/test_cgal6.sh build-cgal6-sanitized -- "${cgal6_options[@]}" \
      -DURBAN_DATA_SWEEP=ON -DURBAN_SANITIZERS=ON -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++
  else
    KINDS="Tests Demo" JOBS="$jobs" bash scripts/test_cgal6.sh build-cgal6 -- "${cgal6_options[@]}" \
      -DURBAN_DATA_SWEEP=OFF -DURBAN_SANITIZERS=OFF
  fi
  # the readers and the command lines of the three programs under libFuzzer, from their seed
  # corpora (fuzz_kinetic_partition, at about 16 scenes a second, is run on its own; ctest
  # replays its corpus)
  bash scripts/fuzz.sh 20 fuzz_point_file fuzz_polyline_file fuzz_segments_file fuzz_footprints fuzz_command_line \
    fuzz_lod2_command_line fuzz_simplify_command_line
fi
