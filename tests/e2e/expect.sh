# Shared by the command-line scripts (cli.sh, cli_output.sh), sourced after `viewer` and `src`
# are set: a scratch folder removed on exit, a failure flag, and `expect STATUS DESCRIPTION --
# command...`, which runs the command with its output in $tmp/out and $tmp/err and fails the
# script (not at once: every check runs) when the exit status differs.
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
fail=0
expect() {
  local want="$1" what="$2"; shift 3
  "$@" >"$tmp/out" 2>"$tmp/err"; local got=$?
  if [ "$got" != "$want" ]; then echo "FAIL: $what: exit $got, expected $want"; cat "$tmp/err"; fail=1; fi
}
