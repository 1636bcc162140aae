// mirrors pddl4j/pom.xml: PDDL4J 3.8.3 repackaged into this jar without the log4j 2.11 it bundles (a
// current log4j is a dependency instead); the tests run against the jar, as Maven's failsafe does
plugins {
    `java-library`
}

val triadVersion: String by project
val pddl4j: Configuration by configurations.creating

dependencies {
    api("org.triad:triad-planner:$triadVersion")
    pddl4j("com.github.pellierd:pddl4j:3.8.3") { isTransitive = false }
    compileOnly(files(pddl4j))
    implementation("org.apache.logging.log4j:log4j-api:2.24.1")
    implementation("org.apache.logging.log4j:log4j-core:2.24.1")
    testImplementation(files(tasks.jar))
}

tasks.jar {
    dependsOn(pddl4j)
    from(pddl4j.elements.map { jars -> jars.map { zipTree(it.asFile) } }) {
        exclude("org/apache/logging/**", "org/junit/**", "junit/**", "org/hamcrest/**", "org/json/**", "log4j2.xml",
            "META-INF/org/apache/logging/**", "META-INF/versions/**", "META-INF/services/**", "META-INF/DEPENDENCIES", "Log4j-*",
            "META-INF/*.SF", "META-INF/*.DSA", "META-INF/*.RSA", "META-INF/MANIFEST.MF", "META-INF/maven/**")
    }
}

tasks.test {
    // the *IT classes are the tests (they need the repackaged jar); the rest are their helpers
    include("**/*IT.class")
    classpath = files(tasks.jar) + sourceSets.test.get().output + configurations.testRuntimeClasspath.get()
}
