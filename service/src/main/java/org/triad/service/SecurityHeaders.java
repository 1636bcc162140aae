package org.triad.service;

import io.javalin.http.Context;

/**
 * The headers every answer carries so that a browser runs the pages' own scripts only, never shows them in
 * another site's frame, and never guesses content types. Cross-origin requests are not allowed (no CORS
 * headers are ever sent, so a browser refuses another site's scripts the answers).
 */
final class SecurityHeaders {
    /** The pages load their scripts, styles and data from the service itself; inline styles are used by the floor map. */
    static final String CSP = "default-src 'self'; script-src 'self'; style-src 'self' 'unsafe-inline'; img-src 'self' data:;"
            + " connect-src 'self'; object-src 'none'; base-uri 'none'; form-action 'self'; frame-ancestors 'none'";

    private SecurityHeaders() {
    }

    static void apply(Context ctx) {
        ctx.header("Content-Security-Policy", CSP);
        ctx.header("X-Frame-Options", "DENY");
        ctx.header("X-Content-Type-Options", "nosniff");
        ctx.header("Referrer-Policy", "no-referrer");
        ctx.header("Cache-Control", ctx.path().startsWith("/api/") ? "no-store" : "no-cache");
    }
}
