#!/usr/bin/env bash
# Measures how much of MontiArc 7's own models Triad's architecture language reads, checks, generates,
# compiles and runs (generator/README.md, "MontiArc 7's own models"). MontiArc's files are read from a
# clone or mirror of github.com/MontiCore/montiarc given as $1 and copied to a temporary folder only.
#   generator/scripts/montiarc/measure.sh /path/to/montiarc [commit]
set -eu
repo=${1:?usage: measure.sh MONTIARC_GIT_DIR_OR_CLONE [COMMIT]}
commit=${2:-HEAD}
here=$(cd "$(dirname "$0")/../../.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# MEASURE_NO_BUILD=1 uses the classes of the last build
[ "${MEASURE_NO_BUILD:-}" = 1 ] || (cd "$here" && mvn -B -q -o -pl generator -am compile dependency:build-classpath -Dmdep.outputFile=target/cp.txt >/dev/null)
cp="$here/generator/target/classes:$here/dsl/target/classes:$here/runtime/target/classes:$here/planner/target/classes:$(cat "$here/generator/target/cp.txt")"
runtime="$here/runtime/target/classes"

export_models() { # $1 path in the repository, $2 target folder
  mkdir -p "$2"
  git -C "$repo" archive "$commit" "$1" | tar -x -C "$2"
}

generate() { # $1 models folder, $2 output; prints the generator's report
  java -cp "$cp" org.triad.generator.arc.ArcJavaGeneratorMain "$1" "$2" 2>&1 || true
}

printf '| models | .arc files | parse | check clean | generate | compile | behave |\n|---|---|---|---|---|---|---|\n'
for set in applications/bumperbot applications/elevator applications/factory applications/avionics libraries/montiarc-base; do
  dir="$work/$(basename "$set")"
  export_models "$set/main" "$dir"
  models="$dir/$set/main"
  total=$(find "$models" -name '*.arc' | wc -l)
  report=$(generate "$models" "$dir/out")
  syntax=$(grep -E '^[^ ]+\.arc:[0-9]+:[0-9]+: error syntax' <<<"$report" | cut -d: -f1 | sort -u | wc -l)
  errors=$(grep -E '^[^ ]+\.arc:[0-9]+:[0-9]+: error' <<<"$report" | cut -d: -f1 | sort -u | wc -l)
  # generate what checks clean: drop models with errors (and those that then miss them) until the rest generates
  for _ in 1 2 3 4 5 6 7 8; do
    bad=$(grep -E '^[^ ]+\.(arc|cd):[0-9]+:[0-9]+: error' <<<"$report" | cut -d: -f1 | sort -u || true)
    [ -z "$bad" ] && break
    while read -r f; do rm -f "$models/$f"; done <<<"$bad"
    report=$(generate "$models" "$dir/out")
  done
  generated=0
  compiled=0
  behave="-"
  if grep -q '^generated' <<<"$report"; then
    generated=$(find "$models" -name '*.arc' | wc -l)
    mkdir -p "$dir/classes"
    if javac -nowarn -d "$dir/classes" -cp "$runtime" $(find "$dir/out" -name '*.java') >"$dir/javac.log" 2>&1; then
      compiled=$generated
      if [ "$(basename "$set")" = montiarc-base ]; then
        behave="$(java -cp "$runtime:$dir/classes" "$here/generator/scripts/montiarc/Behaviour.java" | tail -1 | sed 's/behave //') gates"
      elif [ "$(basename "$set")" = elevator ]; then
        behave="$(java -cp "$runtime:$dir/classes" "$here/generator/scripts/montiarc/Behaviour.java" elevator | tail -1 | sed 's/behave //') FloorControl/Splitter rows"
      fi
    else
      head -5 "$dir/javac.log" >&2
    fi
  fi
  printf '| %s | %d | %d | %d | %d | %d | %s |\n' "$set" "$total" $((total - syntax)) $((total - errors)) "$generated" "$compiled" "$behave"
done
