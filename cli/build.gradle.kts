// mirrors cli/pom.xml: the ./triad command (`gradle :cli:run --args="check models/hospital"`)
plugins {
    `java-library` // api: what depends on the CLI (tests/) gets its libraries, as Maven's compile scope passes them on
    application
}

val triadVersion: String by project

dependencies {
    api("org.triad:triad-dsl:$triadVersion")
    api("org.triad:triad-generator:$triadVersion")
    api("org.triad:triad-refarc:$triadVersion")
    api(project(":pddl4j"))
    api(project(":vda5050")) // ./triad run with VDA 5050 robots, ./triad broker
    api(project(":service")) // ./triad serve
    api(project(":archetype")) // ./triad new
    api("info.picocli:picocli:4.7.6")
}

application {
    mainClass.set("org.triad.cli.TriadMain")
}

tasks.named<JavaExec>("run") {
    workingDir = rootDir
    systemProperty("triad.home", rootDir.absolutePath)
}
