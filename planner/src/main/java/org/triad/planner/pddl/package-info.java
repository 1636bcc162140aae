/**
 * PDDL as data: an AST for domains and problems ({@link org.triad.planner.pddl.Domain},
 * {@link org.triad.planner.pddl.Problem}), a parser that reports bad input as
 * {@link org.triad.planner.pddl.PddlParseException} with {@code line:col}, and a writer that prints
 * standard PDDL for any planner. No third-party dependencies.
 */
package org.triad.planner.pddl;
