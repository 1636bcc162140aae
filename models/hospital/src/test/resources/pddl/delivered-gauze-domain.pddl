; The hospital's goal Delivered(gauze, ward1) from the Morning situation, as ./triad pddl translates it since
; the courier has a battery drained by distance, a payload and moves costing their length (issue #22).
; Metric-FF 2.1 (-s 0) solves it in 0.00 s; Triad's engine (NumericSearch) finds no plan within 30 s.
(define (domain hospital)
  (:requirements :strips :typing :fluents :negative-preconditions)
  (:types waypoint - object room - waypoint thing - object item - thing person - object)
  (:predicates
    (courier-loc ?value - waypoint)
    (courier-carries ?i - item)
    (courier-handempty)
    (courier-following ?p - person)
    (building-adj ?a ?b - waypoint)
    (building-itemat ?i - item ?w - waypoint)
    (building-personat ?p - person ?value - waypoint)
    (building-dock ?w - waypoint))
  (:functions (courier-battery) (courier-drain) (courier-load) (courier-payload) (building-distance ?a ?b - waypoint) (building-weight ?i - item) (total-cost))
  (:action courier-move
    :parameters (?src ?dst - waypoint)
    :precondition (and (courier-loc ?src) (building-adj ?src ?dst) (>= (courier-battery) (* (building-distance ?src ?dst) (courier-drain))))
    :effect (and (not (courier-loc ?src)) (courier-loc ?dst) (decrease (courier-battery) (* (building-distance ?src ?dst) (courier-drain))) (increase (total-cost) (building-distance ?src ?dst))))
  (:action courier-recharge
    :parameters (?w - waypoint)
    :precondition (and (courier-loc ?w) (building-dock ?w) (< (courier-battery) 100))
    :effect (and (assign (courier-battery) 100) (increase (total-cost) 1)))
  (:action courier-pick
    :parameters (?i - item ?w - waypoint)
    :precondition (and (courier-loc ?w) (building-itemat ?i ?w) (courier-handempty) (<= (+ (courier-load) (building-weight ?i)) (courier-payload)))
    :effect (and (courier-carries ?i) (not (courier-handempty)) (not (building-itemat ?i ?w)) (increase (courier-load) (building-weight ?i))))
  (:action courier-drop
    :parameters (?i - item ?w - waypoint)
    :precondition (and (courier-loc ?w) (courier-carries ?i))
    :effect (and (building-itemat ?i ?w) (not (courier-carries ?i)) (courier-handempty) (decrease (courier-load) (building-weight ?i))))
  (:action courier-guide
    :parameters (?p - person ?src ?dst - waypoint)
    :precondition (and (courier-loc ?src) (building-personat ?p ?src) (building-adj ?src ?dst) (not (courier-following ?p)) (>= (courier-battery) (* (building-distance ?src ?dst) (courier-drain))))
    :effect (and (not (courier-loc ?src)) (courier-loc ?dst) (not (building-personat ?p ?src)) (building-personat ?p ?dst) (decrease (courier-battery) (* (building-distance ?src ?dst) (courier-drain))) (increase (total-cost) (building-distance ?src ?dst))))
  (:action courier-startfollowing
    :parameters (?p - person ?w - waypoint)
    :precondition (and (courier-loc ?w) (building-personat ?p ?w))
    :effect (and (courier-following ?p)))
  (:action building-walk
    :parameters (?p - person ?src ?dst - waypoint)
    :precondition (and (building-personat ?p ?src) (building-adj ?src ?dst) (courier-following ?p) (courier-loc ?src) (>= (courier-battery) (* (building-distance ?src ?dst) (courier-drain))))
    :effect (and (not (building-personat ?p ?src)) (building-personat ?p ?dst) (not (courier-loc ?src)) (courier-loc ?dst) (decrease (courier-battery) (* (building-distance ?src ?dst) (courier-drain))) (increase (total-cost) (building-distance ?src ?dst))))
)
