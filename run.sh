#!/usr/bin/env bash
# wheelrail: set up, build and run.
#   ./run.sh                    install missing packages, build (Release) into build/,
#                               run prm/default.prm on 2 MPI ranks and write its
#                               report page (results/default/plots/report.html)
#   ./run.sh test               same set-up, then the whole test suite (ctest)
#   ./run.sh test-portable      the same suite on a build for any x86-64 CPU
#                               (-DWHEELRAIL_NATIVE=OFF, in build-generic/): the
#                               references hold whatever CPU built and runs it
#   ./run.sh CASE.prm [-np N] [--resume]  same set-up, then run CASE.prm on N ranks
#                               (default 2); --resume continues from its checkpoint
#   ./run.sh bench [N ...]      same set-up, then the speed benchmarks prm/bench_paper.prm,
#                               bench_paper_single.prm, bench_profiles.prm and bench_block.prm on 1 and 2 ranks (or the rank
#                               counts N given); figures appended to bench/results.csv,
#                               after the machine's measured FMA peak and memory bandwidth
#                               and the element loop's family batch on cached data (build/
#                               element_kernel) and an exchange between 2 ranks (build/mpi_exchange);
#                               per case the element loop's share of the FMA peak and the triad,
#                               and the cases side by side
#   ./run.sh plot DIR [OTHER]   the paper's figures and report.html from a run's output
#                               directory (and the comparison with a second run) into DIR/plots,
#                               with the half-space solution of the patch's load and traction
#   ./run.sh sweep BASE.prm [options]  traction sweep over mu_n and friction laws with its
#                               plots and the creep curve against the half-space one
#                               (scripts/sweep.py --help)
#   ./run.sh creep-curve CASE.prm [options]  creep-force table (F_x/F_N, slip area,
#                               micro-slip against the creepage held) as CSV and HDF5
#                               with its plot beside the half-space curve
#                               (scripts/creep_curve.py --help)
#   ./run.sh build              set-up and build only
#   ./run.sh format             clang-format (.clang-format, deal.II's style) on every
#                               tracked C++ file (installs Debian's clang-format)
#   ./run.sh help               this text
set -euo pipefail
cd "$(dirname "$0")"
top=$(pwd)

packages=(cmake ninja-build g++ make perl libdeal.ii-dev libeigen3-dev numdiff openmpi-bin
          python3 python3-numpy python3-matplotlib python3-h5py)

install_missing_packages() {
  local missing=()
  for p in "${packages[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
  done
  [ ${#missing[@]} -eq 0 ] && return 0
  echo "run.sh: installing missing Debian packages: ${missing[*]}"
  local sudo=""
  [ "$(id -u)" -ne 0 ] && sudo="sudo"
  $sudo apt-get update
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y --no-install-recommends "${missing[@]}"
}

build() {
  install_missing_packages
  if [ ! -f build/CMakeCache.txt ]; then
    cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release
  fi
  cmake --build build -j "$(nproc)"
}

# The generic build: no -march=native, so x86-64's baseline (SSE2, no FMA).
build_generic() {
  install_missing_packages
  cmake -S . -B build-generic -G Ninja -DCMAKE_BUILD_TYPE=Release -DWHEELRAIL_NATIVE=OFF
  cmake --build build-generic -j "$(nproc)"
}

# Open MPI refuses root unless told otherwise (CI and containers run as root);
# allow more ranks than cores for the tests.
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
export OMPI_MCA_rmaps_base_oversubscribe=1

run_case() {
  local prm=$1 np=$2
  shift 2 # further arguments (--resume) go to wheelrail
  [ -f "$prm" ] || { echo "run.sh: no such parameter file: $prm" >&2; exit 1; }
  echo "run.sh: running $prm on $np MPI rank(s)"
  if [ "$np" -gt 1 ]; then
    mpirun -np "$np" "$top/build/wheelrail" "$prm" "$@"
  else
    "$top/build/wheelrail" "$prm" "$@"
  fi
  local dir
  dir=$(sed -n 's/^[[:space:]]*set[[:space:]]\+Output directory[[:space:]]*=[[:space:]]*\(.*[^[:space:]]\)[[:space:]]*$/\1/p' "$prm" | tail -1)
  run_dir=$(cd "${dir:-results}" && pwd)
  echo "run.sh: results are in $run_dir/ (open solution.pvd in ParaView; statistics; probe.csv; parameters.prm)"
}

# The report page of the run just made (run_dir), with the ParaView files
# beside it: the last thing the default case prints.
report_case() {
  echo "run.sh: writing the report page (scripts/plot.py $run_dir --hs-grid 48x33)"
  /usr/bin/python3 scripts/plot.py "$run_dir" --hs-grid 48x33
  echo "run.sh: ParaView: $run_dir/solution.pvd (the wheel and rail)"
  [ -f "$run_dir/patch_series.xdmf" ] &&
    echo "run.sh: ParaView: $run_dir/patch_series.xdmf (the contact patch as a movie)"
  echo "run.sh: report:   $run_dir/plots/report.html"
}

# The speed benchmarks: prm/bench_paper.prm, prm/bench_paper_single.prm (the
# same with single-precision element geometry), prm/bench_profiles.prm (S1002
# on 60E1, single) and prm/bench_block.prm on each
# rank count, each timing.csv row appended to bench/results.csv with the date,
# commit, CPU, the 2-core triad bandwidth, the bytes per element-step and the case.
run_bench() {
  local counts=("$@")
  [ ${#counts[@]} -eq 0 ] && counts=(1 2)
  mkdir -p bench
  local csv=bench/results.csv
  local header=date,commit,cpu,ranks,cells,dofs,steps,wall_s,ns_per_element_step,elements_s,contact_s,update_s,communication_s,energies_s,output_s,peak_memory_mb,projected_full_run_h,fastest_step_ms,median_step_ms,p95_step_ms,triad_2core_gb_s,bytes_per_element_step,case,element_gflop_s,fma_peak_percent,element_gb_s,triad_percent
  if [ ! -f "$csv" ]; then
    echo "$header" > "$csv"
  elif [ "$(head -1 "$csv")" != "$header" ]; then
    sed -i "1s/.*/$header/" "$csv" # older rows (the paper case) leave the new columns empty
  fi
  local commit cpu
  commit=$(git rev-parse --short HEAD 2>/dev/null || echo unknown)
  # the log itself does not count as a change to the code
  git diff --quiet -- . ':(exclude)bench/results.csv' 2>/dev/null || commit="$commit+changes"
  cpu=$(sed -n 's/^model name[[:space:]]*:[[:space:]]*//p' /proc/cpuinfo | head -1 | tr -d ',')
  # what the step is measured against: this machine's FMA peak and its
  # bandwidth on 2 cores, which turns ns per element-step into the bytes per
  # element-step that a host of that bandwidth moves in that time (the measure
  # that compares across hosts)
  local limits triad triad1 fma1 fma2 kernel flops
  limits=$("$top/build/machine_limits" 2)
  echo "$limits"
  triad=$(echo "$limits" | sed -n 's/.*STREAM triad.* on 1 core, \([0-9.]*\) on 2.*/\1/p')
  triad1=$(echo "$limits" | sed -n 's/.*STREAM triad[^:]*: \([0-9.]*\) GB.s on 1 core.*/\1/p')
  fma1=$(echo "$limits" | sed -n 's/.*FMA chains[^:]*: \([0-9.]*\) GFLOP.s on 1 core.*/\1/p')
  fma2=$(echo "$limits" | sed -n 's/.*FMA chains.* on 1 core, \([0-9.]*\) on 2.*/\1/p')
  # the element loop's floor on this host: its family batch on cached data,
  # and the kernel's operations per cell (damped and undamped, double and
  # single geometry)
  kernel=$("$top/build/element_kernel")
  echo "$kernel"
  flops=($(echo "$kernel" | sed -n 's/^Floating-point operations[^:]*://p' | grep -o '[0-9][0-9]*'))
  # one synchronisation's own cost, apart from the ranks waiting for each other
  mpirun -np 2 "$top/build/mpi_exchange"
  local case dir rows=0
  for case in paper paper_single profiles block; do
    dir=results/bench
    [ "$case" = paper_single ] && dir=results/bench_single
    [ "$case" = profiles ] && dir=results/bench_profiles
    [ "$case" = block ] && dir=results/bench_block
    for np in "${counts[@]}"; do
      echo "run.sh: benchmark prm/bench_$case.prm on $np rank(s)"
      local log
      log=$(mktemp)
      if [ "$np" -gt 1 ]; then
        mpirun -np "$np" "$top/build/wheelrail" "prm/bench_$case.prm" | grep -v '^step' | tee "$log"
      else
        "$top/build/wheelrail" "prm/bench_$case.prm" | grep -v '^step' | tee "$log"
      fi
      # the share of the batches' single-precision blocks that are distinct
      # (Element geometry sharing): the element data the loop streams
      local shared
      shared=$(sed -n 's/.*element data: \([0-9]*\) distinct blocks for \([0-9]*\) batches.*/\1 \2/p' "$log" |
        awk '{ printf "%.4f", $1 / $2 }')
      rm -f "$log"
      local row ns bytes loop
      row=$(grep -v '^#' "$dir/timing.csv" | tail -1)
      ns=$(echo "$row" | cut -d, -f6)
      bytes=$(awk -v ns="$ns" -v bw="$triad" 'BEGIN { printf "%.0f", ns * bw }')
      echo "run.sh: $ns ns per element-step x $triad GB/s (2-core triad) = $bytes bytes per element-step"
      loop=$(element_loop_rates "$dir/parameters.prm" "$np" "$row" "${shared:-1}")
      echo "run.sh: element loop of prm/bench_$case.prm on $np rank(s): $(echo "$loop" | cut -d, -f5-)"
      echo "$(date -u +%Y-%m-%dT%H:%M:%SZ),$commit,$cpu,$row,$triad,$bytes,$case,$(echo "$loop" | cut -d, -f1-4)" >> "$csv"
      rows=$((rows + 1))
    done
  done
  echo "run.sh: benchmark figures appended to $top/$csv"
  { head -1 "$csv"; tail -n "$rows" "$csv"; } | cut -d, -f4- | column -s, -t || true
  # the cases side by side: the paper mesh (refined, damped) and the block
  # (unrefined, undamped)
  echo "run.sh: the cases side by side (ns per element-step on all ranks; the element loop's share of the host's limits)"
  { echo "case,ranks,ns_per_element_step,elements_ns_per_cell_step_and_rank,element_gflop_s,fma_peak_percent,element_gb_s,triad_percent"
    tail -n "$rows" "$csv" | awk -F, '{ printf "%s,%s,%s,%.1f,%s,%s,%s,%s\n", $23, $4, $9, $10 / ($5 * $7) * 1e9, $24, $25, $26, $27 }' |
      sort -t, -k1,1 -k2,2n; } | column -s, -t || true
}

# The element loop of a benchmark row against the host's limits: the
# kernel's counted operations per cell (element_kernel: damped or not,
# double or single geometry, as the run's parameters.prm records
# Damping model, Damping form and Element geometry precision) times cells
# and steps over the slowest rank's element time, against the FMA peak of
# that many cores (1: the one-core figure; more: the 2-core figure per 2
# cores), and the bytes the loop must move per cell (its element data, 312 B
# double or 168 B single times the share of distinct blocks @p shared (the
# 4th argument; 1 unless Element geometry sharing finds copies: the shared
# blocks come from the caches), and per DoF u, v and the force read and written,
# 8 B each; undamped: no v; Damping form = nodal field: the undamped kernel
# on w, 24 B, plus the pass that forms w = u + beta v, 32 B) against the
# triad of as many cores. Prints
# "GFLOP/s,% of FMA peak,GB/s,% of triad,sentence". Uses flops, fma1,
# fma2, triad1, triad of run_bench().
element_loop_rates() {
  local prm=$1 np=$2 row=$3 shared=$4 damped=1 single=0 nodal=0
  grep -Eq '^ *set Damping model *= *none( |$)' "$prm" && damped=0
  grep -Eq '^ *set Element geometry precision *= *single( |$)' "$prm" && single=1
  # the nodal form runs the undamped kernel (on w = u + beta v)
  if [ "$damped" = 1 ] && grep -Eq '^ *set Damping form *= *nodal field( |$)' "$prm"; then
    nodal=1
  fi
  local f=${flops[$((2 * single + 1 - damped + nodal))]}
  echo "$row" | awk -F, -v f="$f" -v np="$np" -v damped="$damped" -v single="$single" -v nodal="$nodal" -v shared="$shared" \
    -v fma1="$fma1" -v fma2="$fma2" -v tr1="$triad1" -v tr2="$triad" '{
      cells = $2; dofs = $3; steps = $4; el = $7
      peak = (np == 1) ? fma1 : fma2 * np / 2; bw = (np == 1) ? tr1 : tr2 * np / 2
      gflops = f * cells * steps / el / 1e9
      bytes = (single ? 168 * shared : 312) + (nodal ? 56 : damped ? 32 : 24) * dofs / cells
      gbs = bytes * cells * steps / el / 1e9
      printf "%.1f,%.1f,%.1f,%.1f,", gflops, 100 * gflops / peak, gbs, 100 * gbs / bw
      printf "%d operations per cell (counted), %.1f GFLOP/s = %.0f %% of the FMA peak of %d core(s); %.0f bytes per cell, %.1f GB/s = %.0f %% of the triad\n",
        f, gflops, 100 * gflops / peak, np, bytes, gbs, 100 * gbs / bw }'
}

# The comment block at the top of this file, from its second line.
usage() {
  sed -n '2,/^[^#]/{/^#/p}' "$0" | sed 's/^# \{0,1\}//'
}

verb=${1:-default}
case "$verb" in
  default)
    build
    run_case prm/default.prm 2
    report_case
    ;;
  test)
    packages+=(chromium python3-vtk9) # the report page is rendered, the VTU files read back
    build
    ctest --test-dir build -j "$(nproc)" --output-on-failure
    ;;
  test-portable)
    packages+=(chromium python3-vtk9)
    build_generic
    ctest --test-dir build-generic -j "$(nproc)" --output-on-failure
    ;;
  build)
    build
    ;;
  format)
    packages=(clang-format)
    install_missing_packages
    git ls-files '*.cc' '*.h' | xargs clang-format -i
    ;;
  plot)
    shift
    install_missing_packages
    [ $# -ge 1 ] || { echo "run.sh: plot needs a run's output directory" >&2; exit 1; }
    /usr/bin/python3 scripts/plot.py "$@"
    ;;
  sweep)
    shift
    build
    /usr/bin/python3 scripts/sweep.py "$@"
    ;;
  creep-curve)
    shift
    build
    /usr/bin/python3 scripts/creep_curve.py "$@"
    ;;
  bench)
    shift
    build
    run_bench "$@"
    ;;
  help|-h|--help)
    usage
    ;;
  *.prm)
    np=2
    flags=()
    shift
    while [ $# -gt 0 ]; do
      case $1 in
        -np) np=${2:?"-np needs a number"}; shift 2 ;;
        --resume) flags+=(--resume); shift ;;
        *) echo "run.sh: unknown option '$1' after $verb (known: -np N, --resume)" >&2; exit 1 ;;
      esac
    done
    build
    run_case "$verb" "$np" "${flags[@]}"
    ;;
  *)
    echo "run.sh: unknown verb '$verb'" >&2
    usage >&2
    exit 1
    ;;
esac
