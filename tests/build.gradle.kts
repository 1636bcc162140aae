// mirrors tests/pom.xml: black-box integration tests of the CLI and the simulated hospital
plugins {
    java
}

dependencies {
    testImplementation(project(":cli"))
    testImplementation(project(":models:hospital"))
    testImplementation(project(":sim"))
    testImplementation(project(":pddl4j"))
    testImplementation(project(":service"))
    // the service's pages in a real browser: Debian's chromium + chromium-driver (installed by .ci/run)
    testImplementation("org.seleniumhq.selenium:selenium-chrome-driver:4.25.0")
    testImplementation("org.seleniumhq.selenium:selenium-support:4.25.0")
}
