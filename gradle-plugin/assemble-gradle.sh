#!/usr/bin/env bash
# Assembles Gradle 8.10 from Maven Central artifacts alone into gradle-plugin/target/gradle-8.10
# (bin/gradle; Groovy build scripts only, builds run in the launching JVM, JUnit 5 tests run): what HospitalGradleBuildIT
# runs. `mvn verify` in gradle-plugin does the same in its pre-integration-test phase.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
cd "$here"
mvn -B -q dependency:copy@gradle-artifacts
java -cp target/gradle-artifacts/gradle-api-8.10.jar src/gradle-dist/AssembleGradle.java target/gradle-artifacts src/gradle-dist/shims target/gradle-8.10
echo "run: $here/target/gradle-8.10/bin/gradle --offline -p PROJECT TASK..."
