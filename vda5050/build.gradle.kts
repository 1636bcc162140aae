// mirrors vda5050/pom.xml: VDA 5050 2.1 over MQTT (Eclipse Paho), every message validated against the official JSON schemas
plugins {
    `java-library`
}

val triadVersion: String by project

dependencies {
    api("org.triad:triad-runtime:$triadVersion")
    api("org.triad:triad-refarc:$triadVersion")
    api("org.triad:triad-building:$triadVersion") // traffic control: the reservation table behind orders with base and horizon
    api("org.eclipse.paho:org.eclipse.paho.client.mqttv3:1.2.5")
    implementation("org.bouncycastle:bcpkix-jdk18on:1.79") // the broker's certificates
    api("com.fasterxml.jackson.core:jackson-databind:2.17.2")
    api("com.networknt:json-schema-validator:1.5.6")
    runtimeOnly("org.slf4j:slf4j-nop:2.0.16") // the schema validator logs through SLF4J; Triad reports every problem itself
}
