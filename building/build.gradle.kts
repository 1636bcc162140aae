// mirrors building/pom.xml: the building's map, the fleet's shared world state, reservations and dispatch
plugins {
    `java-library`
}

val triadVersion: String by project

dependencies {
    api("org.triad:triad-refarc:$triadVersion")
    testImplementation("org.triad:triad-dsl:$triadVersion") // the tests load the hospital's models
    testImplementation("org.triad:triad-generator:$triadVersion")
}
