// mirrors sim/pom.xml: the 2D dyn4j simulation
plugins {
    `java-library`
}

dependencies {
    api("org.dyn4j:dyn4j:5.0.2")
}

tasks.test {
    systemProperty("java.awt.headless", "true")
}
