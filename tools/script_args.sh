# The arguments of the shell scripts in tools/, checked before a script does anything (installs,
# builds, runs or overwrites results). Sourced, not run: each script starts with
#   source "$(dirname "$0")/script_args.sh"
# and then calls one of:
#   no_arguments "$@"       -h/--help: the script's header comment on stdout, exit status 0; any other
#                           argument: '<script>: error: ...' and its usage line on stderr, exit status 2
#   help_only "$@"          -h/--help (anywhere) as above; every other argument is the script's to pass on
#   usage_error MESSAGE     '<script>: error: MESSAGE (Usage: ...)' on stderr, exit status 2
#   build_first             bash tools/build.sh (from the repository root) unless SIGNORINI_NO_BUILD=1;
#                           unset, empty or 0: build; another value: a usage error (nothing built or run)
#   mpi_launcher NP         sets the array mpirun to the launcher of the build's tests for NP ranks (CMake's
#                           MPIEXEC_* entries in build/CMakeCache.txt; without it Open MPI's
#                           mpiexec -n NP --oversubscribe --allow-run-as-root)
# The header comment is the comment block after the '#!' line; its 'Usage:' line is the usage.

script_help() {  # the header comment of the running script, without the '# '
  sed -n '2,/^[^#]/{/^#/{s/^# \{0,1\}//;p;};}' "$0"
}

script_usage() {  # the header's 'Usage:' line, or 'bash <folder>/<script>' (tools/, bench/)
  local line
  line=$(script_help | grep -m1 '^Usage:' || true)
  echo "${line:-Usage: bash $(basename "$(cd "$(dirname "$0")" && pwd)")/$(basename "$0")}"
}

help_only() {
  local a
  for a in "$@"; do
    case $a in
      -h | --help) script_help; exit 0 ;;
    esac
  done
}

usage_error() {
  echo "$(basename "$0"): error: $1 ($(script_usage))" >&2
  exit 2
}

no_arguments() {
  help_only "$@"
  [ $# -eq 0 ] || usage_error "unexpected argument '$1': the script takes none"
}

build_first() {
  case ${SIGNORINI_NO_BUILD:-0} in
    1) ;;
    0) bash tools/build.sh > /dev/null ;;
    *) usage_error "SIGNORINI_NO_BUILD='$SIGNORINI_NO_BUILD': 1 (use the existing build/src/signorini) or 0 (build first)" ;;
  esac
}

mpi_launcher() {
  local exe="" flag="" pre="--oversubscribe;--allow-run-as-root"
  if [ -f build/CMakeCache.txt ]; then
    cached() { sed -n "s/^$1:[A-Z]*=//p" build/CMakeCache.txt; }
    exe=$(cached MPIEXEC_EXECUTABLE)
    flag=$(cached MPIEXEC_NUMPROC_FLAG)
    pre=$(cached MPIEXEC_PREFLAGS)
  fi
  local preflags=()
  [ -z "$pre" ] || IFS=';' read -r -a preflags <<< "$pre"
  mpirun=("${exe:-mpiexec}" "${flag:--n}" "$1" "${preflags[@]}")
}
