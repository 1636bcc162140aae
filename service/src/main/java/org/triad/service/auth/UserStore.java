package org.triad.service.auth;

import java.nio.charset.StandardCharsets;
import java.security.MessageDigest;
import java.security.NoSuchAlgorithmException;
import java.security.SecureRandom;
import java.sql.PreparedStatement;
import java.sql.ResultSet;
import java.sql.Timestamp;
import java.time.Instant;
import java.util.ArrayList;
import java.util.Base64;
import java.util.HexFormat;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.concurrent.ConcurrentHashMap;
import java.util.regex.Pattern;

import org.triad.service.store.TaskStore;

import at.favre.lib.crypto.bcrypt.BCrypt;

/**
 * Named users with a role, in the service's database (table {@code app_user}). A user's token is
 * {@code NAME.SECRET}, SECRET 24 random bytes; only a bcrypt hash (cost {@value #COST}) of the secret is
 * stored, and the token is shown once, when the user is added. Checking a token costs one bcrypt
 * verification (constant time in the secret); a token that passed is remembered by its SHA-256 for
 * the life of the process, and forgotten when any user is revoked. Revoked users stay listed.
 */
public final class UserStore {
    /** bcrypt's work factor: about 50-100 ms per check on one core, once per token and process. */
    static final int COST = 10;
    private static final Pattern NAME = Pattern.compile("[a-z0-9][a-z0-9_-]{0,63}");
    private static final SecureRandom RANDOM = new SecureRandom();
    private static final int MAX_REMEMBERED = 10_000;

    /** A user as listed; times ISO-8601 UTC, {@code revoked} null while the user is active. */
    public record User(String name, String role, String created, String revoked) {
    }

    private final TaskStore store;
    private final Map<String, Principal> verified = new ConcurrentHashMap<>();

    public UserStore(TaskStore store) {
        this.store = store;
    }

    /**
     * Adds a user and returns its token (shown once).
     *
     * @throws IllegalArgumentException for a bad name or a name already used (revoked names stay used)
     */
    public String add(String name, Role role, Instant now) {
        if (name == null || !NAME.matcher(name).matches()) {
            throw new IllegalArgumentException("a user name is 1..64 lower-case letters, digits, '-' and '_', not '" + name + "'");
        }
        byte[] bytes = new byte[24];
        RANDOM.nextBytes(bytes);
        String secret = Base64.getUrlEncoder().withoutPadding().encodeToString(bytes);
        String hash = BCrypt.withDefaults().hashToString(COST, secret.toCharArray());
        boolean added = store.withConnection(c -> {
            try (PreparedStatement q = c.prepareStatement("SELECT 1 FROM app_user WHERE name = ?")) {
                q.setString(1, name);
                try (ResultSet r = q.executeQuery()) {
                    if (r.next()) {
                        return false;
                    }
                }
            }
            try (PreparedStatement s = c.prepareStatement("INSERT INTO app_user(name, role, secret_hash, created_at) VALUES (?, ?, ?, ?)")) {
                s.setString(1, name);
                s.setString(2, role.label());
                s.setString(3, hash);
                s.setTimestamp(4, Timestamp.from(now));
                s.executeUpdate();
            }
            return true;
        });
        if (!added) {
            throw new IllegalArgumentException("there is a user '" + name + "' already (revoked users keep their name); choose another name");
        }
        return name + "." + secret;
    }

    /** Every user, revoked ones included, by name. */
    public List<User> list() {
        return store.withConnection(c -> {
            List<User> users = new ArrayList<>();
            try (PreparedStatement s = c.prepareStatement("SELECT name, role, created_at, revoked_at FROM app_user ORDER BY name");
                    ResultSet r = s.executeQuery()) {
                while (r.next()) {
                    Timestamp revoked = r.getTimestamp(4);
                    users.add(new User(r.getString(1), r.getString(2), r.getTimestamp(3).toInstant().toString(),
                            revoked == null ? null : revoked.toInstant().toString()));
                }
            }
            return users;
        });
    }

    /**
     * Revokes a user: its token is refused from now on.
     *
     * @return false when there is no such user or it was revoked already
     */
    public boolean revoke(String name, Instant now) {
        boolean done = store.withConnection(c -> {
            try (PreparedStatement s = c.prepareStatement("UPDATE app_user SET revoked_at = ? WHERE name = ? AND revoked_at IS NULL")) {
                s.setTimestamp(1, Timestamp.from(now));
                s.setString(2, name);
                return s.executeUpdate() == 1;
            }
        });
        verified.clear();
        return done;
    }

    /** The user a token names, if the token is right and the user not revoked. */
    public Optional<Principal> authenticate(String token) {
        if (token == null) {
            return Optional.empty();
        }
        int dot = token.lastIndexOf('.');
        if (dot < 1 || dot == token.length() - 1 || token.length() > 200) {
            return Optional.empty();
        }
        String key = sha256(token);
        Principal known = verified.get(key);
        if (known != null) {
            return Optional.of(known);
        }
        String name = token.substring(0, dot);
        String secret = token.substring(dot + 1);
        Optional<String[]> row = store.withConnection(c -> {
            try (PreparedStatement s = c.prepareStatement("SELECT role, secret_hash FROM app_user WHERE name = ? AND revoked_at IS NULL")) {
                s.setString(1, name);
                try (ResultSet r = s.executeQuery()) {
                    return r.next() ? Optional.of(new String[] { r.getString(1), r.getString(2) }) : Optional.empty();
                }
            }
        });
        if (row.isEmpty() || !BCrypt.verifyer().verify(secret.toCharArray(), row.get()[1].toCharArray()).verified) {
            return Optional.empty();
        }
        Principal p = new Principal(name, Role.of(row.get()[0]));
        if (verified.size() >= MAX_REMEMBERED) {
            verified.clear();
        }
        verified.put(key, p);
        return Optional.of(p);
    }

    private static String sha256(String s) {
        try {
            return HexFormat.of().formatHex(MessageDigest.getInstance("SHA-256").digest(s.getBytes(StandardCharsets.UTF_8)));
        } catch (NoSuchAlgorithmException e) {
            throw new IllegalStateException(e);
        }
    }

    /** For start-up errors: the command that manages users on this database. */
    public static String command(java.nio.file.Path db) {
        return "./triad users --db " + db + " add|list|revoke";
    }
}
