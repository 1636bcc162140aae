; A courier on roads of different lengths, picking up and dropping parcels; a move costs its length (Triad test domain).
(define (domain roads)
  (:requirements :strips :typing :action-costs)
  (:types place parcel)
  (:predicates (at ?p - place) (road ?a ?b - place) (parcel-at ?x - parcel ?p - place) (carries ?x - parcel))
  (:functions (length ?a ?b - place) (total-cost))
  (:action move
    :parameters (?a ?b - place)
    :precondition (and (at ?a) (road ?a ?b))
    :effect (and (not (at ?a)) (at ?b) (increase (total-cost) (length ?a ?b))))
  (:action pick
    :parameters (?x - parcel ?p - place)
    :precondition (and (at ?p) (parcel-at ?x ?p))
    :effect (and (not (parcel-at ?x ?p)) (carries ?x) (increase (total-cost) 1)))
  (:action drop
    :parameters (?x - parcel ?p - place)
    :precondition (and (at ?p) (carries ?x))
    :effect (and (not (carries ?x)) (parcel-at ?x ?p) (increase (total-cost) 1))))
