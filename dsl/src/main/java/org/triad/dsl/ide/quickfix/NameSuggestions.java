package org.triad.dsl.ide.quickfix;

import java.util.Collection;
import java.util.Comparator;
import java.util.List;

/** "Did you mean": the known names closest to a misspelt one, by edit distance (case-insensitive). */
public final class NameSuggestions {
	/** How many suggestions a quick-fix list shows at most. */
	public static final int MAX = 3;

	private NameSuggestions() {
	}

	public static List<String> closest(String wrong, Collection<String> known) {
		return known.stream().distinct().filter(k -> !k.equals(wrong)).filter(k -> distance(wrong, k) <= tolerance(wrong, k))
				.sorted(Comparator.comparingInt((String k) -> distance(wrong, k)).thenComparing(Comparator.naturalOrder()))
				.limit(MAX).toList();
	}

	/** Roughly a third of the longer name wrong, or one prefix of the other (loc → location). */
	private static int tolerance(String a, String b) {
		if (a.length() >= 2 && (b.toLowerCase().startsWith(a.toLowerCase()) || a.toLowerCase().startsWith(b.toLowerCase()))) {
			return Integer.MAX_VALUE;
		}
		return Math.max(1, Math.max(a.length(), b.length()) / 3);
	}

	/** Edit distance counting a swap of neighbours as one edit (optimal string alignment), ignoring case. */
	static int distance(String a, String b) {
		String x = a.toLowerCase();
		String y = b.toLowerCase();
		int[][] d = new int[x.length() + 1][y.length() + 1];
		for (int i = 0; i <= x.length(); i++) {
			d[i][0] = i;
		}
		for (int j = 0; j <= y.length(); j++) {
			d[0][j] = j;
		}
		for (int i = 1; i <= x.length(); i++) {
			for (int j = 1; j <= y.length(); j++) {
				int cost = x.charAt(i - 1) == y.charAt(j - 1) ? 0 : 1;
				d[i][j] = Math.min(d[i - 1][j - 1] + cost, Math.min(d[i - 1][j] + 1, d[i][j - 1] + 1));
				if (i > 1 && j > 1 && x.charAt(i - 1) == y.charAt(j - 2) && x.charAt(i - 2) == y.charAt(j - 1)) {
					d[i][j] = Math.min(d[i][j], d[i - 2][j - 2] + 1);
				}
			}
		}
		return d[x.length()][y.length()];
	}
}
