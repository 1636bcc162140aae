#!/usr/bin/env bash
# Builds the VS Code extension: bundles the language server jar that Maven builds
# (editors/target/triad-language-server.jar), installs the npm packages pinned in
# package-lock.json, runs the Node tests and packages triad-models.vsix.
set -euo pipefail
cd "$(dirname "$0")"
jar=../target/triad-language-server.jar
if [ ! -f "$jar" ]; then
  echo "vscode: $jar is missing; build it first: mvn -B -pl editors -am package -DskipTests" >&2
  exit 2
fi
mkdir -p server
cp "$jar" server/triad-language-server.jar
npm ci --no-audit --no-fund
log="$(mktemp)"
status=0
node --test test/ 2>&1 | tee "$log" || status=$?
if [ "$status" -ne 0 ]; then
  rm -f "$log"
  echo "vscode: the extension's tests failed" >&2
  exit "$status"
fi
npx vsce package --skip-license --allow-missing-repository -o triad-models.vsix
# the Node test runner's summary last, where CI reads it
grep -E '^# (tests|pass|fail|cancelled|skipped)' "$log"
rm -f "$log"
