// mirrors runtime/pom.xml
dependencies {
    api(project(":triad-planner"))
}
