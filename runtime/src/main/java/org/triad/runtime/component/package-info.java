/**
 * A small component runtime for C&amp;C architectures, in the spirit of MontiArc's Java runtime.
 *
 * <ul>
 * <li>{@link org.triad.runtime.component.AtomicComponent}s declare typed
 * {@link org.triad.runtime.component.InPort}s and {@link org.triad.runtime.component.OutPort}s,
 * register a handler per in port, and start long work as activities whose results come back as
 * messages.</li>
 * <li>{@link org.triad.runtime.component.ComposedComponent}s own subcomponents and connectors
 * (fan-out allowed, one sender per target, type-checked) and forward their own ports.</li>
 * <li>A {@link org.triad.runtime.component.Scheduler} runs a deployed root: deterministically on
 * one thread for tests, or concurrently with each component handling its messages serially.</li>
 * <li>Exceptions never kill a thread: they become {@link org.triad.runtime.component.ComponentFault}s,
 * routed to the nearest composed component that connects its {@code faults} port, else to the
 * scheduler's listener. A message at an in port without handler, or at a composed in port that is
 * not connected inside, is a fault too: nothing is silently dropped.</li>
 * </ul>
 */
package org.triad.runtime.component;
