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
}
