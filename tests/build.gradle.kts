// mirrors tests/pom.xml: black-box integration tests of the CLI and the simulated hospital
plugins {
    java
}

val triadVersion: String by project

dependencies {
    // Maven passes cli's dependencies on to the tests; Gradle's implementation scope does not, so they are named
    testImplementation("org.triad:triad-dsl:$triadVersion")
    testImplementation("org.triad:triad-generator:$triadVersion")
    testImplementation(project(":cli"))
    testImplementation(project(":models:hospital"))
    testImplementation(project(":sim"))
    testImplementation(project(":pddl4j"))
    testImplementation(project(":service"))
    // the service's pages in a real browser: Debian's chromium + chromium-driver (installed by .ci/run)
    testImplementation("org.seleniumhq.selenium:selenium-chrome-driver:4.25.0")
    testImplementation("org.seleniumhq.selenium:selenium-support:4.25.0")
}
