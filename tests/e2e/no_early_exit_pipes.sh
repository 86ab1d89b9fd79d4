#!/usr/bin/env bash
# No shell script of the project pipes a command into 'grep -q': under 'set -o pipefail' the
# producer can die of SIGPIPE after grep has found its match and quit, and the match then
# counts as a failure, at random and more often on a loaded machine. Capture, then match:
#   grep -q PATTERN <<<"$(command)"
# usage: no_early_exit_pipes.sh PROJECT_DIR
set -euo pipefail
cd "$1"
scripts=(.ci/run scripts/*.sh tests/e2e/*.sh)
found="$(grep -nE '(^|[^|])\|[[:space:]]*grep[[:space:]]+(-[a-zA-Z]*q|--quiet)' "${scripts[@]}" || true)"
if [ -n "$found" ]; then
  echo "$found"
  echo "FAIL: a command piped into 'grep -q' (see above): capture its output, then match"
  exit 1
fi
echo "no script pipes a command into grep -q (${#scripts[@]} scripts)"
