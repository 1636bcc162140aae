// mirrors fuzz/pom.xml: Jazzer fuzz tests of every input boundary; `gradle :fuzz:test` replays their regression
// corpus, JAZZER_FUZZ=1 fuzzes (see CONTRIBUTING.md)
plugins {
    java
}

val triadVersion: String by project

dependencies {
    testImplementation("org.triad:triad-dsl:$triadVersion")
    testImplementation("org.triad:triad-planner:$triadVersion")
    testImplementation("org.triad:triad-vda5050:$triadVersion")
    testImplementation("org.triad:triad-service:$triadVersion")
    testImplementation("com.code-intelligence:jazzer-junit:0.30.0")
}

tasks.test {
    // coverage feedback from Triad's code only (instrumenting Xtext and EMF too makes a fuzzing run slow to start)
    systemProperty("jazzer.instrumentation_includes", "org.triad.**")
}
