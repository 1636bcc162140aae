package org.triad.dsl.formatting2;

/** Formats .actor models with the layout all Triad languages share. */
public class TriadActorFormatter extends TriadCommonFormatter {
}
