# The arguments of the shell scripts in tools/, checked before a script does anything (installs,
# builds, runs or overwrites results). Sourced, not run: each script starts with
#   source "$(dirname "$0")/script_args.sh"
# and then calls one of:
#   no_arguments "$@"       -h/--help: the script's header comment on stdout, exit status 0; any other
#                           argument: '<script>: error: ...' and its usage line on stderr, exit status 2
#   help_only "$@"          -h/--help (anywhere) as above; every other argument is the script's to pass on
#   usage_error MESSAGE     '<script>: error: MESSAGE (Usage: ...)' on stderr, exit status 2
# The header comment is the comment block after the '#!' line; its 'Usage:' line is the usage.

script_help() {  # the header comment of the running script, without the '# '
  sed -n '2,/^[^#]/{/^#/{s/^# \{0,1\}//;p;};}' "$0"
}

script_usage() {  # the header's 'Usage:' line, or 'bash tools/<script>'
  local line
  line=$(script_help | grep -m1 '^Usage:' || true)
  echo "${line:-Usage: bash tools/$(basename "$0")}"
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
