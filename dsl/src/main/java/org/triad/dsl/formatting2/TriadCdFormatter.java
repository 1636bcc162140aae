package org.triad.dsl.formatting2;

/** Formats .cd models with the layout all Triad languages share. */
public class TriadCdFormatter extends TriadCommonFormatter {
}
