; A robot whose battery drains by the length of each road and recharges at a dock (Triad test domain).
(define (domain battery)
  (:requirements :strips :typing :numeric-fluents)
  (:types place robot)
  (:predicates (at ?r - robot ?p - place) (road ?a ?b - place) (dock ?p - place))
  (:functions (battery ?r - robot) (distance ?a ?b - place) (capacity ?r - robot) (travelled))
  (:action drive
    :parameters (?r - robot ?a ?b - place)
    :precondition (and (at ?r ?a) (road ?a ?b) (>= (battery ?r) (distance ?a ?b)))
    :effect (and (not (at ?r ?a)) (at ?r ?b) (decrease (battery ?r) (distance ?a ?b)) (increase (travelled) (distance ?a ?b))))
  (:action recharge
    :parameters (?r - robot ?p - place)
    :precondition (and (at ?r ?p) (dock ?p) (< (battery ?r) (capacity ?r)))
    :effect (and (assign (battery ?r) (capacity ?r)))))
