// mirrors models/logistics/pom.xml: the paper's logistics example (Listings 1-3)
plugins {
    id("org.triad.models")
    `java-library`
}

val triadVersion: String by project

dependencies {
    api("org.triad:triad-runtime:$triadVersion")
    api("org.triad:triad-refarc:$triadVersion")
    testImplementation("org.triad:triad-generator:$triadVersion")
}

tasks.withType<JavaCompile>().configureEach {
    options.compilerArgs.addAll(listOf("-Xlint:all", "-Werror"))
}
