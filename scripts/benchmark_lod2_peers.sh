#!/usr/bin/env bash
# The LOD2 pipeline and its peers in one run, on the same inputs (lod2_peer_benchmark.h):
# this package's lod2_building_reconstruction() (benchmark_lod2_buildings), CGAL's PolyFit
# (benchmark_polyfit, built when GLPK is found) and CGAL 6.0.1's Kinetic_surface_reconstruction_3
# (ksr/benchmark_ksr, built against the CGAL 6.0.1 headers that scripts/fetch_cgal6.sh unpacks),
# on CGAL's points_3/building.ply and building by building on a synthetic classified tile
# (synthetic_city.h; the same seed for all).
#   bash scripts/benchmark_lod2_peers.sh BUILD_DIR [--buildings N] [--seed S] [--time-limit T]
# N buildings (default 30), seed S (default 1), T the time limit of PolyFit per input (default
# 600 s). Run after scripts/quickstart.sh has installed the packages of the build; installs the
# optional packages of this benchmark when they are missing (libglpk-dev for PolyFit,
# gnuplot-nox for the plot; as root or through sudo) and goes on without them when it cannot.
# Configures BUILD_DIR with the benchmarks, builds the programs, runs them one after the other
# and writes into BUILD_DIR/lod2_peers/: the JSON lines of each run (METHOD_INPUT.jsonl, their
# standard error in .log), peers.md (the totals of each method on each input, then the time of
# each method on each building), peers.csv (one line per method and input or building) and,
# with gnuplot, peers.png (time and RMS distance per building). Prints peers.md.
set -euo pipefail
usage() { echo "usage: $0 BUILD_DIR [--buildings N] [--seed S] [--time-limit SECONDS]" >&2; exit 2; }
[ $# -ge 1 ] || usage
build="$(realpath -m "$1")"
shift
buildings=30 seed=1 time_limit=600
while [ $# -gt 0 ]; do
  case "$1" in
    --buildings) buildings="${2:?}"; shift 2 ;;
    --seed) seed="${2:?}"; shift 2 ;;
    --time-limit) time_limit="${2:?}"; shift 2 ;;
    *) usage ;;
  esac
done
cd "$(dirname "$0")/.."
root="$(pwd)"
out="$build/lod2_peers"
jobs="$(nproc 2>/dev/null || echo 2)"
benchmarks="$build/Polygon_partition_simplification/benchmark/Polygon_partition_simplification"

# The optional packages: PolyFit's solver and the plot.
install_optional_packages() {
  local missing=() p sudo_cmd=""
  for p in libglpk-dev gnuplot-nox; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
  done
  [ ${#missing[@]} -gt 0 ] || return 0
  echo "Installing: ${missing[*]}"
  [ "$(id -u)" -eq 0 ] || sudo_cmd="sudo"
  { $sudo_cmd apt-get update -q && DEBIAN_FRONTEND=noninteractive $sudo_cmd apt-get install -y -q --no-install-recommends \
      "${missing[@]}"; } > "$out/install.log" 2>&1 \
    || echo "benchmark_lod2_peers: could not install ${missing[*]} (see $out/install.log); going on without" >&2
}

# compile DIR TARGET: the compiler's output in build.log, its end on the terminal if it fails.
compile() {
  echo "building $2" >&2
  cmake --build "$1" -j"$jobs" --target "$2" >> "$out/build.log" 2>&1 || { tail -n 30 "$out/build.log" >&2; exit 1; }
}

# benchmark_lod2_buildings and, with GLPK, benchmark_polyfit; benchmark_ksr against CGAL 6.0.1
# (KSR is skipped when CGAL 6.0.1 cannot be had).
build_programs() {
  local launcher=() cgal6
  command -v ccache > /dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
  cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release -DURBAN_BUILD_BENCHMARKS=ON > "$out/configure.log"
  compile "$build" benchmark_lod2_buildings
  # grep without -q reads the whole list: with -q it can exit at the first match while the
  # build tool still writes, which then gets SIGPIPE, and pipefail fails the test although the
  # target is there
  if cmake --build "$build" --target help 2> /dev/null | grep "benchmark_polyfit" > /dev/null; then
    compile "$build" benchmark_polyfit
  else
    echo "benchmark_lod2_peers: GLPK not found, PolyFit skipped (apt-get install libglpk-dev)" >&2
  fi
  if cgal6="$(bash scripts/fetch_cgal6.sh)"; then
    cmake -S Polygon_partition_simplification/benchmark/Polygon_partition_simplification/ksr -B "$build/ksr" \
      -DCMAKE_BUILD_TYPE=Release -DCGAL_DIR="$cgal6" "${launcher[@]}" > "$out/configure_ksr.log"
    compile "$build/ksr" benchmark_ksr
  else
    echo "benchmark_lod2_peers: no CGAL 6.0.1, KSR skipped" >&2
  fi
}

# run NAME PROGRAM ARGUMENTS...: one program on one input, its JSON lines in NAME.jsonl.
run() {
  local name="$1" program="$2"
  shift 2
  [ -x "$program" ] || return 0
  runs+=("$name")
  echo "running $name" >&2
  "$program" "$@" > "$out/$name.jsonl" 2> "$out/$name.log" || true
}

run_all() {
  local data tile=(--synthetic-city "$buildings" --seed "$seed")
  data="$(sed -n 's/^URBAN_CGAL_DATA_DIR:PATH=//p' "$build/CMakeCache.txt")/points_3/building.ply"
  rm -f "$out"/*.jsonl "$out/peers.png"
  runs=()
  run ours_building "$benchmarks/benchmark_lod2_buildings" "$data"
  run polyfit_building "$benchmarks/benchmark_polyfit" "$data" --time-limit "$time_limit"
  run ksr_building "$build/ksr/benchmark_ksr" "$data"
  run ksr_box_outside_building "$build/ksr/benchmark_ksr" "$data" --box-outside
  run ours_tile "$benchmarks/benchmark_lod2_buildings" "${tile[@]}"
  run ours_true_planes_tile "$benchmarks/benchmark_lod2_buildings" "${tile[@]}" --true-planes
  run polyfit_tile "$benchmarks/benchmark_polyfit" "${tile[@]}" --time-limit "$time_limit"
  run polyfit_true_planes_tile "$benchmarks/benchmark_polyfit" "${tile[@]}" --true-planes --time-limit "$time_limit"
  run ksr_tile "$build/ksr/benchmark_ksr" "${tile[@]}"
  run ksr_box_outside_tile "$build/ksr/benchmark_ksr" "${tile[@]}" --box-outside
}

# peers.csv from the JSON lines (flat objects): method, input, building (-1 for a file, "total"
# for the totals of a tile), kind, points, time, faces, RMS (the mean over the buildings for a
# total), closed, valid (counts for a total), modelled, repairs, failure.
write_csv() {
  echo "method,input,building,kind,points,time_s,faces,rms_m,closed,valid,modelled,repairs,failed"
  local name
  for name in "${runs[@]}"; do cat "$out/$name.jsonl"; done | awk '
    function get(key, value) {
      if(!match($0, "\"" key "\":(\"[^\"]*\"|[^,}]*)")) return ""
      value = substr($0, RSTART + length(key) + 3, RLENGTH - length(key) - 3)
      gsub(/"/, "", value); gsub(/,/, ";", value)
      return value
    }
    /^\{"method"/ {
      total = get("total") == "true"
      building = total ? "total" : (get("building") == "" ? -1 : get("building"))
      rms = total ? get("rms_mean_m") : get("rms_m")
      printf "%s,%s,%s,%s,%s,%s,%s,%s,%s,%s,%s,%s,%s\n", get("method"), get("input"), building, get("kind"), get("points"),
             get("time_s"), get("faces"), rms, get("closed"), get("valid"), total ? get("modelled") : (get("failed") == "" ? 1 : 0),
             total ? get("repaired") : get("repairs"), get("failed")
    }'
}

# The names of the methods in the tables and the plot (an awk function).
labels='function label(m) {
  if(m == "ours_true_planes") return "ours, true planes"
  if(m == "polyfit") return "PolyFit"
  if(m == "polyfit_true_planes") return "PolyFit, true planes"
  if(m == "ksr") return "KSR"
  if(m == "ksr_box_outside") return "KSR, box outside"
  return m
}
'

# peers.md: the totals of each method on each input, then the time of each method on each
# building (seconds; "(not closed)", "(not valid)" or "(none)" when the model is not a valid solid).
write_markdown() {
  local csv="$out/peers.csv"
  echo "| method | input | time (s) | faces | RMS (m) | closed & valid |"
  echo "|--------|-------|---------:|------:|--------:|----------------|"
  awk -F, -v buildings="$buildings" "$labels"'NR > 1 && ($3 == -1 || $3 == "total") {
    $1 = label($1)
    if($13 != "") { printf "| %s | %s | %.3g | - | - | failed: %s |\n", $1, $2, $6, $13; next }
    if($3 == -1) {
      valid = $10 == "true" ? "yes" : $9 == "true" ? "closed, not valid" : "no"
      if($12 != "") valid = valid " (after repairs: " $12 ")"
    } else {
      valid = $10 " of " buildings " (" $11 " models"
      valid = valid ($12 > 0 ? ", " $12 " repaired)" : ")")
    }
    printf "| %s | %s | %.3g | %s | %s |\n", $1, $2, $6, ($11 > 0 ? $7 " | " sprintf("%.3g", $8) : "- | -"), valid
  }' "$csv"
  echo
  awk -F, "$labels"'NR > 1 && $3 != -1 && $3 != "total" {
    $1 = label($1)
    if(!($1 in seen)) { seen[$1] = 1; methods[++m] = $1 }
    kind[$3] = $4; last = $3 > last ? $3 : last
    cell[$1, $3] = sprintf("%.3g", $6) ($13 != "" ? " (none)" : $9 != "true" ? " (not closed)" : $10 != "true" ? " (not valid)" : "")
  }
  END {
    printf "| building | kind |"; for(i = 1; i <= m; ++i) printf " %s |", methods[i]; printf "\n|---|---|"
    for(i = 1; i <= m; ++i) printf "---:|"; printf "\n"
    for(b = 0; b <= last; ++b) {
      printf "| %d | %s |", b, kind[b]; for(i = 1; i <= m; ++i) printf " %s |", cell[methods[i], b]; printf "\n"
    }
  }' "$csv"
}

color() {
  case "$1" in
    ours) echo "#d62728" ;; ours_true_planes) echo "#8c564b" ;; polyfit) echo "#1f77b4" ;; polyfit_true_planes) echo "#17becf" ;;
    ksr) echo "#2ca02c" ;; ksr_box_outside) echo "#7f7f7f" ;; *) echo "#ff7f0e" ;;
  esac
}

# peers.png: the time and the RMS distance of each method on each building (filled: a closed,
# valid model; open: a model that is not; the methods side by side at each building), when
# gnuplot is there.
write_plot() {
  command -v gnuplot > /dev/null || { echo "benchmark_lod2_peers: no gnuplot, no plot (apt-get install gnuplot-nox)" >&2; return 0; }
  local methods method count i panel column label title plots filled=(7 5 9 11 13 15) open=(6 4 8 10 12 14)
  methods="$(awk -F, 'NR > 1 && $3 != -1 && $3 != "total" && $13 == "" && !seen[$1]++ { print $1 }' "$out/peers.csv")"
  count="$(echo "$methods" | wc -w)"
  {
    echo "set terminal pngcairo size 960,720 font 'DejaVu Sans,10' noenhanced; set output '$out/peers.png'"
    echo "set datafile separator ','; set multiplot layout 2,1; set logscale y; set grid; set lmargin 10; set rmargin at screen 0.78"
    echo "set xrange [-0.5:$buildings - 0.5]; set xtics 1 font ',8'; set xlabel 'building of the tile'"
    echo "set label 'filled: closed, valid' at screen 0.80, screen 0.70; set label 'open: not' at screen 0.80, screen 0.67"
    for panel in "6:time per building (s)" "8:RMS distance of its points to the model (m)"; do
      column="${panel%%:*}" label="${panel#*:}" plots=() i=0
      echo "set ylabel '$label'"
      [ "$column" = 6 ] && echo "set key at screen 0.99, screen 0.97 right top" || echo "unset key; unset label"
      for method in $methods; do
        title="$(awk "$labels"'BEGIN { print label("'"$method"'") }')"
        local x="(\$3 + ($i - ($count - 1) / 2.) * 0.6 / $count)" row="strcol(1) eq '$method' && strcol(3) ne 'total' && strcol(3) ne '-1'"
        plots+=("'$out/peers.csv' using ($row && strcol(10) eq 'true' ? $x : NaN):$column with points pt ${filled[i % 6]} lc rgb '$(color "$method")' title '$title'")
        plots+=("'' using ($row && strcol(10) ne 'true' ? $x : NaN):$column with points pt ${open[i % 6]} lc rgb '$(color "$method")' notitle")
        i=$((i + 1))
      done
      (IFS=,; echo "plot ${plots[*]}")
    done
    echo "unset multiplot"
  } | gnuplot
}

mkdir -p "$out"
: > "$out/build.log"
install_optional_packages
build_programs
{
  echo "# $(date -u +%Y-%m-%d), $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'), $jobs cores" \
       "(load average $(cut -d' ' -f1-3 /proc/loadavg) before the runs); building.ply and a tile of $buildings buildings," \
       "seed $seed; PolyFit stopped at $time_limit s"
} > "$out/machine.txt"
run_all
write_csv > "$out/peers.csv"
{ cat "$out/machine.txt"; echo; write_markdown; } > "$out/peers.md"
write_plot
cat "$out/peers.md"
echo "Results in $out: peers.md, peers.csv$( [ -f "$out/peers.png" ] && echo ", peers.png"), the JSON lines of each run"
