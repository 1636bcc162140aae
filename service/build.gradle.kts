// mirrors service/pom.xml: ./triad serve (typed task API, persistent task queue, fleet dispatch, web pages)
plugins {
    `java-library`
}

val triadVersion: String by project

dependencies {
    api("org.triad:triad-dsl:$triadVersion")
    api("org.triad:triad-generator:$triadVersion")
    api("org.triad:triad-refarc:$triadVersion")
    api("org.triad:triad-building:$triadVersion")
    api("org.triad:triad-runtime:$triadVersion")
    api("io.javalin:javalin:6.3.0")
    api("com.fasterxml.jackson.core:jackson-databind:2.17.2")
    implementation("at.favre.lib:bcrypt:0.10.2") // users' secrets
    implementation("com.h2database:h2:2.2.224")
    implementation("org.xerial:sqlite-jdbc:3.47.1.0")
    implementation("org.postgresql:postgresql:42.7.4")
    implementation("org.flywaydb:flyway-core:10.17.3")
    implementation("org.flywaydb:flyway-database-postgresql:10.17.3")
    implementation("org.slf4j:slf4j-simple:2.0.16") // Javalin, Jetty and Flyway log through SLF4J: warnings and errors to stderr
    testImplementation("io.swagger.parser.v3:swagger-parser-v3:2.1.22") // checks /api/openapi.json
}
