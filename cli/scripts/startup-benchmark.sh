#!/usr/bin/env bash
# Start-up of ./triad: median wall and CPU (user+sys) time of N runs per command, the launcher before
# issue #11's start-up work against the current one (on the JDK it chooses and on the `java` of the
# PATH), runs alternating, in one table. Run from anywhere; the tool is built first if need be.
#   cli/scripts/startup-benchmark.sh [RUNS] [BEFORE_REV]
# RUNS defaults to 11; BEFORE_REV (a commit whose `triad` script is "before") to 3c3573f, the last
# commit before that work. "before" runs the old script on the current build (its entry TriadCli).
set -euo pipefail
runs="${1:-11}"
before_rev="${2:-3c3573f}"
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
cd "$root"

before="$root/.triad-before-$$"
git show "$before_rev:triad" >"$before"
# the launchers without their last step, exec java: what the bash script itself costs
before_script="$root/.triad-before-script-$$"
after_script="$root/.triad-after-script-$$"
# and the launcher printing the java command line it would exec (NUL-separated)
after_print="$root/.triad-after-print-$$"
sed 's|^exec .*|exit 0|' "$before" >"$before_script"
sed 's|^exec .*|exit 0|' "$root/triad" >"$after_script"
sed 's|^exec "\$java"|printf "%s\\0" "$java"|' "$root/triad" >"$after_print"
chmod +x "$before" "$before_script" "$after_script" "$after_print"
trap 'rm -f "$before" "$before_script" "$after_script" "$after_print"' EXIT

path_java="$(readlink -f "$(command -v java)")"
path_jdk="$(dirname "$(dirname "$path_java")")"
gripper=planner/src/test/resources/pddl/ipc/gripper
commands=(
  "solve $gripper/domain.pddl $gripper/prob01.pddl"
  "check models/hospital"
  "run models/hospital/src/main/models --state Morning.state --task GoTo(ward3)"
  "--help"
)
labels=("solve gripper prob01" "check models/hospital" "run a hospital task (GoTo(ward3))" "--help")
# launcher name, script, TRIAD_JAVA ("" = the launcher's own choice)
launchers=("before (java on PATH, AppCDS)" "$before" ""
           "after (JDK it chooses)" "$root/triad" ""
           "after (TRIAD_JAVA = java on PATH)" "$root/triad" "$path_jdk")

# one timed run: prints "wall cpu"
timed() {
  local script="$1" jdk="$2"; shift 2
  local t
  TIMEFORMAT="%3R %3U %3S"
  if [ -n "$jdk" ]; then
    t=$( { time TRIAD_JAVA="$jdk" "$script" "$@" >/dev/null 2>&1; } 2>&1 )
  else
    t=$( { time env -u TRIAD_JAVA "$script" "$@" >/dev/null 2>&1; } 2>&1 )
  fi
  local w u s
  read -r w u s <<<"$t"
  echo "$w $(awk -v u="$u" -v s="$s" 'BEGIN { printf "%.3f", u + s }')"
}

median() { sort -n | awk '{ v[NR] = $1 } END { printf "%.3f", (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }

# build, training runs and archives first (not measured)
"$root/triad" --help >/dev/null
for ((c = 0; c < ${#commands[@]}; c++)); do
  read -ra args <<<"${commands[c]}"
  for ((l = 0; l < ${#launchers[@]}; l += 3)); do
    timed "${launchers[l + 1]}" "${launchers[l + 2]}" "${args[@]}" >/dev/null
  done
done

chosen_jdk="$(env -u TRIAD_JAVA bash -c 'for h in "${JAVA_HOME:-}" /usr/lib/jvm/*; do [ -f "$h/release" ] && grep -h "^JAVA_VERSION=" "$h/release" | sed "s|^|$h |"; done' 2>/dev/null | sort -t'"' -k2 -V | tail -1)"
echo "Date: $(date -u '+%Y-%m-%d %H:%M UTC'); $(nproc) cores; load average at start: $(cut -d' ' -f1-3 /proc/loadavg)"
echo "java on PATH: $path_jdk ($(java -version 2>&1 | head -1)); newest JDK found: ${chosen_jdk:-none}"
echo "Median of $runs runs per cell (launchers alternating), wall and CPU = user+sys of the whole process tree, seconds."
echo
echo "| command | launcher | wall s | CPU s |"
echo "|---|---|---|---|"
for ((c = 0; c < ${#commands[@]}; c++)); do
  read -ra args <<<"${commands[c]}"
  declare -A walls=() cpus=()
  for ((i = 0; i < runs; i++)); do
    for ((l = 0; l < ${#launchers[@]}; l += 3)); do
      read -r w u <<<"$(timed "${launchers[l + 1]}" "${launchers[l + 2]}" "${args[@]}")"
      walls[$l]+="$w "
      cpus[$l]+="$u "
    done
  done
  for ((l = 0; l < ${#launchers[@]}; l += 3)); do
    printf '| %s | %s | %s | %s |\n' "${labels[c]}" "${launchers[l]}" \
      "$(tr ' ' '\n' <<<"${walls[$l]}" | grep . | median)" "$(tr ' ' '\n' <<<"${cpus[$l]}" | grep . | median)"
  done
  unset walls cpus
done

# Where the time of a small solve goes (after, on the JDK the launcher chooses): the bash script up to
# exec java, the JVM starting and stopping (-version, same flags, no archive), the JVM planning
# (the java command line the launcher execs), the whole.
read -ra solve_args <<<"${commands[0]}"
java_line=()
while IFS= read -r -d '' a; do java_line+=("$a"); done < <(env -u TRIAD_JAVA "$after_print" "${solve_args[@]}")
echo
echo "Where the time of \`triad ${commands[0]}\` goes (after, the JDK the launcher chooses):"
echo
echo "| step | wall s | CPU s |"
echo "|---|---|---|"
parts=("launcher script before, up to exec java" "$before_script"
       "launcher script after, up to exec java" "$after_script"
       "JVM start and exit (java -version, same JVM flags)" "${java_line[0]:-java}"
       "the JVM's solve (the command line the launcher execs)" "java-line"
       "the whole ./triad solve" "$root/triad")
for ((p = 0; p < ${#parts[@]}; p += 2)); do
  ws=""; cs=""
  for ((i = 0; i < runs; i++)); do
    case "${parts[p + 1]}" in
      java-line) t=$(TIMEFORMAT="%3R %3U %3S"; { time "${java_line[@]}" >/dev/null 2>&1; } 2>&1) ;;
      */java) t=$(TIMEFORMAT="%3R %3U %3S"; { time "${parts[p + 1]}" -XX:+UseSerialGC -XX:-UsePerfData -XX:TieredStopAtLevel=1 -version >/dev/null 2>&1; } 2>&1) ;;
      *) t=$(TIMEFORMAT="%3R %3U %3S"; { time env -u TRIAD_JAVA "${parts[p + 1]}" "${solve_args[@]}" >/dev/null 2>&1; } 2>&1) ;;
    esac
    read -r w u s <<<"$t"
    ws+="$w "; cs+="$(awk -v u="$u" -v s="$s" 'BEGIN { printf "%.3f", u + s }') "
  done
  printf '| %s | %s | %s |\n' "${parts[p]}" "$(tr ' ' '\n' <<<"$ws" | grep . | median)" "$(tr ' ' '\n' <<<"$cs" | grep . | median)"
done
echo
echo "load average at end: $(cut -d' ' -f1-3 /proc/loadavg)"
