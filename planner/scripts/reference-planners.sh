#!/usr/bin/env bash
# Builds the reference tools of planner/'s numeric comparison (NumericPlannerComparison) outside the
# repository, as ../shared/notes/reference-planners.md says: VAL and Metric-FF 2.1 from their public
# sources (git checkouts the caller brought onto the machine: this script downloads nothing from
# GitHub), ENHSP from PyPI (the up-enhsp package ships its jar). None of them is a dependency of Triad.
#   planner/scripts/reference-planners.sh VAL_SRC METRIC_FF_SRC OUT_DIR
# VAL_SRC: KCL-Planning/VAL (3c7a1f3); METRIC_FF_SRC: Vidminas/metric-ff-crossplatform (12175ca).
# Needs (Debian): cmake g++ flex bison gcc make python3-venv. Prints the three paths the comparison takes.
set -euo pipefail
[ $# -eq 3 ] || { echo "usage: $0 VAL_SRC METRIC_FF_SRC OUT_DIR" >&2; exit 2; }
val_src=$(realpath "$1"); mff_src=$(realpath "$2"); out=$(realpath -m "$3")
mkdir -p "$out"

# VAL: the parser sources ship generated (flex/bison not needed)
rm -rf "$out/val" && cp -r "$val_src" "$out/val"
cmake -S "$out/val" -B "$out/val/build" -DCMAKE_BUILD_TYPE=Release > "$out/val-cmake.log"
cmake --build "$out/val/build" -j2 > "$out/val-build.log"

# Metric-FF 2.1: times.c redefines gettimeofday/times outside Windows, and two parser functions name
# a parameter errno (a macro on glibc); times.c ends without a newline, so the #endif gets its own line
rm -rf "$out/mff" && cp -r "$mff_src" "$out/mff"
cd "$out/mff/v2.1"
{ echo '#ifdef _WIN32'; cat times.c; printf '\n#endif\n'; } > times.c.new && mv times.c.new times.c
sed -i 's/int errno, char \*par/int err_no, char *par/; s/sact_err = errno;/sact_err = err_no;/' scan-fct_pddl.y scan-ops_pddl.y
make > "$out/mff-build.log" 2>&1
cd - > /dev/null

# ENHSP from PyPI
python3 -m venv "$out/enhsp-venv"
"$out/enhsp-venv/bin/pip" install -q up-enhsp
jar=$(find "$out/enhsp-venv" -name enhsp.jar | head -1)

echo "METRIC_FF=$out/mff/ff-v2.1" # the makefile writes the binary one level up
echo "VALIDATE=$out/val/build/bin/Validate"
echo "ENHSP_JAR=$jar"
