#!/usr/bin/env bash
# Time and peak memory of `./triad check` against the size of the models: the small application of the
# rule tests (dsl/src/test/resources/rules/_base) plus goal files of the given total size (one goal of
# ~60 bytes after another, each file at most the size given). Prints a table; the numbers for
# cli/README.md ("Model size") come from it.
#
#   cli/scripts/check-size-benchmark.sh [WORK_DIR]          (ONLY=2MB,50MB-one-file for some rows)
#
# Needs /usr/bin/time (GNU time, for the peak resident set) and python3 (to write the models).
set -euo pipefail
here="$(cd "$(dirname "$0")/../.." && pwd)"
work="${1:-$(mktemp -d)}"
mkdir -p "$work"
"$here/triad" check "$here/dsl/src/test/resources/rules/_base" >/dev/null # builds on first use, outside the timings

# app NAME TOTAL_BYTES FILE_BYTES: the base application plus goals
app() {
  local dir="$work/$1"
  rm -rf "$dir"; mkdir -p "$dir"
  cp "$here"/dsl/src/test/resources/rules/_base/* "$dir"/
  python3 - "$dir" "$2" "$3" <<'PY'
import sys, os
d, total, per_file = sys.argv[1], int(sys.argv[2]), int(sys.argv[3])
n, written, f, size = 0, 0, None, 0
while written < total:
    if f is None or size >= per_file - 200:
        if f: f.close()
        f = open(os.path.join(d, "Pad%d.goal" % n), "w"); f.write("domain Shop;\n"); size = 13
    g = "goal G%d(Place p) {\n  Bot.loc() == p\n}\n" % n
    f.write(g); size += len(g); written += len(g); n += 1
f.close()
PY
}

echo "| models | files over the base | exit | first line | wall s | peak RSS MB |"
echo "|---|---|---|---|---|---|"
run() { # label total per_file; ONLY=LABEL,LABEL runs only those rows
  if [ -n "${ONLY:-}" ] && [[ ",$ONLY," != *",$1,"* ]]; then return; fi
  app "$1" "$2" "$3"
  local files; files=$(ls "$work/$1"/Pad*.goal | wc -l)
  local out="$work/$1.out" t="$work/$1.time" code=0
  /usr/bin/time -f '%e %M' -o "$t" timeout 600 "$here/triad" check "$work/$1" >"$out" 2>&1 || code=$?
  read -r wall rss < <(tail -1 "$t") || true
  printf '| %s | %s | %s | %s | %s | %s |\n' "$1" "$files" "$code" "$(head -c 90 "$out" | head -1)" "$wall" "$((rss / 1024))"
}
run "0.5MB" $((512 * 1024)) $((2 * 1024 * 1024))
run "1MB" $((1024 * 1024)) $((2 * 1024 * 1024))
run "2MB" $((2 * 1024 * 1024 - 300)) $((2 * 1024 * 1024))
run "5MB-in-3-files" $((5 * 1024 * 1024)) $((2 * 1024 * 1024))
run "5MB-one-file" $((5 * 1024 * 1024)) $((6 * 1024 * 1024))
run "50MB-one-file" $((50 * 1024 * 1024)) $((51 * 1024 * 1024))
