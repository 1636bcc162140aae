package org.triad.dsl.formatting2;

/** Formats .state models with the layout all Triad languages share. */
public class TriadStateFormatter extends TriadCommonFormatter {
}
