// mirrors cli/pom.xml: the ./triad command (`gradle :cli:run --args="check models/hospital"`)
plugins {
    application
}

val triadVersion: String by project

dependencies {
    implementation("org.triad:triad-dsl:$triadVersion")
    implementation("org.triad:triad-generator:$triadVersion")
    implementation("org.triad:triad-refarc:$triadVersion")
    implementation(project(":pddl4j"))
    implementation(project(":models:hospital"))
    implementation("info.picocli:picocli:4.7.6")
}

application {
    mainClass.set("org.triad.cli.TriadMain")
}

tasks.named<JavaExec>("run") {
    workingDir = rootDir
    systemProperty("triad.home", rootDir.absolutePath)
}
