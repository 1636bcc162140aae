// mirrors tests/pom.xml: black-box integration tests of the CLI and the simulated hospital
plugins {
    java
}

dependencies {
    testImplementation(project(":cli"))
    testImplementation(project(":models:hospital"))
    testImplementation(project(":sim"))
    testImplementation(project(":pddl4j"))
}
