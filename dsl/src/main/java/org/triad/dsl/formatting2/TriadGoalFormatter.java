package org.triad.dsl.formatting2;

/** Formats .goal models with the layout all Triad languages share. */
public class TriadGoalFormatter extends TriadCommonFormatter {
}
