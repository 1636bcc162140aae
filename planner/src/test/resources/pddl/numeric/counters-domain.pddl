; Counters (after the IPC 2023 numeric domain): values moved up or down by one until they are ordered.
(define (domain counters)
  (:requirements :strips :typing :numeric-fluents)
  (:types counter)
  (:functions (value ?c - counter) (max-int))
  (:action increment
    :parameters (?c - counter)
    :precondition (<= (+ (value ?c) 1) (max-int))
    :effect (increase (value ?c) 1))
  (:action decrement
    :parameters (?c - counter)
    :precondition (>= (value ?c) 1)
    :effect (decrease (value ?c) 1)))
