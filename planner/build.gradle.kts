// mirrors planner/pom.xml: the PDDL planning engine, no dependencies
