# Shared by the bench scripts (sourced): the rank count and the build, with a record of what ran;
# -h/--help and SIGNORINI_NO_BUILD as in tools/ (tools/script_args.sh: help_only, build_first, mpi_launcher).
source "$(dirname "${BASH_SOURCE[0]}")/../tools/script_args.sh"

# Builds build/src/signorini (unless SIGNORINI_NO_BUILD=1; 0 or unset: build), sets mpirun (the launcher the build's
# tests use: CMake's MPIEXEC_* cache entries, e.g. Open MPI's mpiexec -n N --oversubscribe
# --allow-run-as-root) and says which code and how many ranks.
build_and_describe() {
  build_first
  [ -x build/src/signorini ] || { echo "no build/src/signorini: build first (bash tools/build.sh)" >&2; exit 2; }
  [ -f build/CMakeCache.txt ] || echo "note: no build/CMakeCache.txt: the launcher is mpiexec -n $np --oversubscribe --allow-run-as-root"
  mpi_launcher "$np"
  echo "benchmark in the working tree of $(git describe --always --dirty 2>/dev/null || echo 'an unknown commit')," \
    "build/src/signorini of $(date -r build/src/signorini '+%Y-%m-%d %H:%M'), $np rank(s), on $(nproc) core(s)," \
    "$(date '+%Y-%m-%d %H:%M')"
  local committed
  committed=$(git log -1 --format=%ct 2>/dev/null || echo 0)
  if [ "$(date -r build/src/signorini +%s)" -lt "$committed" ]; then
    echo "note: build/src/signorini is older than the last commit (SIGNORINI_NO_BUILD): it may not be that code"
  fi
}

# Sets np and repeats from "[-np N] [-r R]" (positive integers); anything else stops with $1.
parse_ranks_and_repeats() {
  local usage=$1
  shift
  np=1
  repeats=1
  while [ $# -gt 0 ]; do
    if [ $# -ge 2 ] && [ "$1" = "-np" ] && [[ "$2" =~ ^[1-9][0-9]*$ ]]; then
      np=$2
    elif [ $# -ge 2 ] && [ "$1" = "-r" ] && [[ "$2" =~ ^[1-9][0-9]*$ ]]; then
      repeats=$2
    else
      echo "$usage (got: $*)" >&2
      exit 2
    fi
    shift 2
  done
}

# Sets np from "[-np N]" (N a positive integer); anything else, -r too, stops with $1.
parse_ranks() {
  parse_ranks_and_repeats "$@"
  if [ "$repeats" -ne 1 ]; then
    echo "$1 (-r is for bench/run-adaptive-bench.sh)" >&2
    exit 2
  fi
}
