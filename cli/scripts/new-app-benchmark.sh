#!/usr/bin/env bash
# A newcomer's first hour, timed: from a fresh clone of this checkout to a green test of a new application,
# following the README only, then the edit-and-test cycle of a model change. Prints a table.
#
#   cli/scripts/new-app-benchmark.sh [WORK_DIR] [MAVEN_REPO]
#
# WORK_DIR (default: a new temporary folder) receives the clone and the new project. MAVEN_REPO (default:
# WORK_DIR/m2, empty: downloads included) is the local Maven repository every step uses, so the machine's
# ~/.m2 is left alone; give a filled one to leave downloads out. Cycle: 3 model changes, each followed by
# `mvn -o -q verify` in the new project; the median is printed.
set -euo pipefail
here="$(cd "$(dirname "$0")/../.." && pwd)"
work="${1:-$(mktemp -d)}"
repo="${2:-$work/m2}"
mkdir -p "$work" "$repo"
repo="$(cd "$repo" && pwd)"
declare -a names=() secs=()

step() { # name, command...
  local name="$1"; shift
  local start end
  start=$(date +%s.%N)
  if ! "$@" >"$work/step.log" 2>&1; then
    echo "new-app-benchmark: '$name' failed:" >&2; tail -40 "$work/step.log" >&2; exit 1
  fi
  end=$(date +%s.%N)
  names+=("$name"); secs+=("$(awk -v a="$start" -v b="$end" 'BEGIN { printf "%.2f", b - a }')")
}

rm -rf "$work/triad" "$work/pharmacy"
step "git clone" git clone -q "$here" "$work/triad"
cd "$work/triad"
step "install Triad's artifacts (README)" mvn -B -q install -DskipTests -pl refarc,generator,archetype -am -Dmaven.repo.local="$repo"
export MAVEN_OPTS="-Dmaven.repo.local=$repo ${MAVEN_OPTS:-}"
step "./triad new (builds the CLI first)" ./triad new "$work/pharmacy" --name Pharmacy
cd "$work/pharmacy"
step "mvn verify of the new project" mvn -B -q verify -Dmaven.repo.local="$repo"
first=$(printf '%s\n' "${secs[@]}" | awk '{ s += $1 } END { printf "%.2f", s }')

cycles=()
for i in 1 2 3; do
  # a model change that changes the generated code: one more task
  printf '\ntask Fetch%s(Medicine m, Cabinet from) {\n  At(from);\n  Holding(m);\n}\n' "$i" >>src/main/models/Tasks.task
  start=$(date +%s.%N)
  mvn -B -o -q verify -Dmaven.repo.local="$repo" >"$work/step.log" 2>&1 || { tail -40 "$work/step.log" >&2; exit 1; }
  test -f "target/generated-sources/triad/generated/pharmacy/tasks/Fetch$i.java"
  end=$(date +%s.%N)
  cycles+=("$(awk -v a="$start" -v b="$end" 'BEGIN { printf "%.2f", b - a }')")
done
median=$(printf '%s\n' "${cycles[@]}" | sort -n | sed -n 2p)

printf '%-45s %10s\n' "step" "seconds"
for i in "${!names[@]}"; do printf '%-45s %10.1f\n' "${names[$i]}" "${secs[$i]}"; done
printf '%-45s %10.1f\n' "fresh clone to a green test (sum)" "$first"
printf '%-45s %10s\n' "edit-and-test cycle (mvn -o -q verify), 3 runs" "$(printf '%.1f ' "${cycles[@]}")"
printf '%-45s %10.1f\n' "edit-and-test cycle, median" "$median"
