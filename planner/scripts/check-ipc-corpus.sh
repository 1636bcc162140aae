#!/usr/bin/env bash
# Parses (and with --ground grounds) every problem of the IPC benchmark collection Fast Downward uses,
# from a LOCAL copy; downloads nothing. Get the copy once:
#   git clone https://github.com/aibasel/downward-benchmarks ../downward-benchmarks
# Usage (from anywhere):
#   planner/scripts/check-ipc-corpus.sh [--ground] CORPUS_DIR [SUITE|DOMAIN_FOLDER...]
# A SUITE is a name of the corpus's suites.py, e.g. satisficing_strips (the default) or satisficing_adl.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
ground=()
if [ "${1:-}" = "--ground" ]; then ground=(--ground); shift; fi
corpus="${1:?usage: check-ipc-corpus.sh [--ground] CORPUS_DIR [SUITE|DOMAIN_FOLDER...]}"; shift
[ -d "$corpus" ] || { echo "check-ipc-corpus: no such folder: $corpus" >&2; exit 2; }
[ $# -gt 0 ] || set -- satisficing_strips
folders=()
for a in "$@"; do
  if [ -d "$corpus/$a" ]; then folders+=("$a")
  else
    # a suite name: ask the corpus's own suites.py (python3, no network)
    mapfile -t more < <(cd "$corpus" && python3 suites.py "$a" | tr -d '[]" ' | tr ',' '\n')
    folders+=("${more[@]}")
  fi
done
(cd "$here" && mvn -B -q -o -pl planner test-compile)
exec java -Xss4m -Xmx2g -cp "$here/planner/target/classes:$here/planner/target/test-classes" \
  org.triad.planner.IpcCorpusCheck "${ground[@]}" "$corpus" "${folders[@]}"
