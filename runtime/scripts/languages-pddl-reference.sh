#!/usr/bin/env bash
# Hands the PDDL that the languages translate to (./triad pddl, exactly what the Planner component plans at run
# time) to Metric-FF 2.1 and checks its plans with VAL: the pharmacy case of issue #22 and the hospital.
# The tools are built outside the repository by planner/scripts/reference-planners.sh (its METRIC_FF and VALIDATE
# lines); CI has no copy of their sources, so this is a script whose result dsl/README.md ("Numbers") quotes, not a test.
#   runtime/scripts/languages-pddl-reference.sh METRIC_FF VALIDATE [OUT_DIR]
# Run from the repository root after ./triad --help has built the tool. Prints one line per goal:
# situation, goal, Metric-FF's verdict and plan length, VAL's verdict and the plan's metric value, and Triad's engine
# (./triad solve) on the same files with its plan checked by VAL.
set -uo pipefail
[ $# -ge 2 ] || { echo "usage: $0 METRIC_FF VALIDATE [OUT_DIR]" >&2; exit 2; }
ff=$(realpath "$1"); validate=$(realpath "$2"); out=$(realpath -m "${3:-target/languages-pddl}")
mkdir -p "$out"
pharmacy=generator/src/test/resources/apps/pharmacy
hospital=models/hospital/src/main/models
status=0

check() { # models situation goal
  local dir="$out/$(echo "$2-$3" | tr -c 'A-Za-z0-9\n' '-')"
  mkdir -p "$dir"
  if ! ./triad pddl "$1" --state "$2" --goal "$3" -o "$dir" > "$dir/triad.log" 2>&1; then
    echo "| $2 | $3 | ./triad pddl failed: $(tail -1 "$dir/triad.log") | | | |"; status=1; return
  fi
  timeout 60 "$ff" -o "$dir/domain.pddl" -f "$dir/problem.pddl" > "$dir/ff.log" 2>&1
  if ! grep -q "found legal plan" "$dir/ff.log"; then
    echo "| $2 | $3 | Metric-FF: $(grep -m1 -iE 'unsolvable|error|problem proven' "$dir/ff.log" || tail -1 "$dir/ff.log") | | | |"; status=1; return
  fi
  # Metric-FF's "step N: ACTION ARGS" lines as a plan VAL reads
  grep -E '^ *(step)? *[0-9]+: ' "$dir/ff.log" | sed -E 's/^ *(step)? *[0-9]+: *//' | awk '{ print "(" tolower($0) ")" }' > "$dir/ff.plan"
  local steps; steps=$(wc -l < "$dir/ff.plan")
  LD_LIBRARY_PATH="$(dirname "$validate")" "$validate" "$dir/domain.pddl" "$dir/problem.pddl" "$dir/ff.plan" > "$dir/val.log" 2>&1
  local verdict value
  verdict=$(grep -q "Plan valid" "$dir/val.log" && echo "Plan valid" || { status=1; echo "VAL: $(grep -m1 -iE 'fail|error|invalid' "$dir/val.log")"; })
  value=$(grep -m1 "Final value" "$dir/val.log" | sed 's/.*: *//')
  # Triad's engine on the same files, its plan checked by VAL too
  local triad
  if ./triad solve "$dir/domain.pddl" "$dir/problem.pddl" -o "$dir/triad.plan" --timeout 60 > "$dir/triad-solve.log" 2>&1; then
    LD_LIBRARY_PATH="$(dirname "$validate")" "$validate" "$dir/domain.pddl" "$dir/problem.pddl" "$dir/triad.plan" > "$dir/val-triad.log" 2>&1
    if grep -q "Plan valid" "$dir/val-triad.log"; then
      triad="$(grep -c "^(" "$dir/triad.plan") steps, $(grep -m1 "Final value" "$dir/val-triad.log" | sed 's/.*: *//')"
    else
      status=1; triad="VAL: $(grep -m1 -iE 'fail|error|invalid' "$dir/val-triad.log")"
    fi
  else
    status=1; triad="no plan: $(tail -1 "$dir/triad-solve.log")"
  fi
  echo "| $2 | $3 | solved, $steps steps | $verdict | ${value:-} | $triad |"
}

echo "| situation | goal | Metric-FF 2.1 | VAL | metric (total cost) | Triad (VAL-checked), metric |"
echo "|---|---|---|---|---|---|"
check "$pharmacy" Morning "At(wardB)"
check "$pharmacy" Morning "Delivered(morphine, wardA)"
check "$pharmacy" Morning "Delivered(saline, wardB)"
check "$pharmacy" Morning "Charged(100.0)"
check "$hospital" Morning "IsAt(ward3)"
check "$hospital" Morning "Delivered(gauze, ward1)"
check "$hospital" Morning "FollowedTo(bob, ward3)"
check "$hospital" Morning "PersonAt(alice, xray)"
check "$hospital" Evening "Charged(lobby)"
check "$hospital" Evening "Delivered(gauze, ward1)"
exit $status
