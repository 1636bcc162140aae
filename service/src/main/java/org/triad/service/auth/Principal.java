package org.triad.service.auth;

/** Who made a request: a named user (or one of the two shared tokens, named {@code staff-token}/{@code operator-token}) and the role. */
public record Principal(String name, Role role) {
    /** {@code alice (operator)}: how audit entries and task histories name the principal. */
    public String describe() {
        return name + " (" + role.label() + ")";
    }
}
