/**
 * Planning: the pluggable {@link org.triad.runtime.planning.Planner} interface and its results,
 * Triad's own engine {@link org.triad.runtime.planning.TriadPlanner} (grounding by relaxed
 * reachability over static facts, cached across goals by
 * {@link org.triad.runtime.planning.GroundedProblemCache}; exact graph search, exact A* over a token graph with compressed moves, A*, goal agenda and
 * LAMA-style lazy search with FF and landmark heuristics), {@link org.triad.runtime.planning.PlanValidator},
 * {@link org.triad.runtime.planning.ExternalPlanner} for planner executables, and the
 * {@link org.triad.runtime.planning.SolveCommand} entry point. Other planners (e.g. triad-pddl4j)
 * register through {@link java.util.ServiceLoader}.
 */
package org.triad.runtime.planning;
