/**
 * Planning: the pluggable {@link org.triad.planner.PddlPlanner} interface and its results,
 * Triad's own engine {@link org.triad.planner.TriadEngine} (grounding by relaxed
 * reachability over static facts, cached across goals by
 * {@link org.triad.planner.GroundedProblemCache}; exact graph search, exact A* over a token graph with compressed moves, A*, goal agenda and
 * LAMA-style lazy search with FF and landmark heuristics), {@link org.triad.planner.PlanValidator},
 * {@link org.triad.planner.ExternalPlanner} for planner executables, and the
 * {@link org.triad.planner.SolveCommand} entry point. Other planners (e.g. triad-pddl4j)
 * register through {@link java.util.ServiceLoader}.
 */
package org.triad.planner;
