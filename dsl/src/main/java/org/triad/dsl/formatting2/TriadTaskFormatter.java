package org.triad.dsl.formatting2;

/** Formats .task models with the layout all Triad languages share. */
public class TriadTaskFormatter extends TriadCommonFormatter {
}
