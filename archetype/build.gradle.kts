// mirrors archetype/pom.xml: the new-application archetype, a jar of templates (archetype-resources/)
plugins {
    `java-library`
}
