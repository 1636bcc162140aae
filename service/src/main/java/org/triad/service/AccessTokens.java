package org.triad.service;

import java.io.IOException;
import java.io.Reader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.security.MessageDigest;
import java.security.SecureRandom;
import java.util.Base64;
import java.util.Map;
import java.util.Optional;
import java.util.Properties;

import org.triad.service.store.TaskStore;

/**
 * Who may do what: the submit token lets staff and programs submit, follow and cancel tasks; the
 * operator token also lets the operator retry, re-assign, mark done and take robots offline. Each token
 * comes from the environment ({@value #SUBMIT_ENV}, {@value #OPERATOR_ENV}), else the config file
 * ({@code submit-token=}, {@code operator-token=}), else the database, else it is generated on first
 * start, stored in the database and printed once.
 */
public final class AccessTokens {
    public static final String SUBMIT_ENV = "TRIAD_SUBMIT_TOKEN";
    public static final String OPERATOR_ENV = "TRIAD_OPERATOR_TOKEN";

    public enum Role { SUBMIT, OPERATOR }

    private final String submit;
    private final String operator;
    private final boolean generated;

    private AccessTokens(String submit, String operator, boolean generated) {
        this.submit = submit;
        this.operator = operator;
        this.generated = generated;
    }

    public static AccessTokens load(Map<String, String> env, Path configFile, TaskStore store) {
        Properties config = new Properties();
        if (configFile != null) {
            if (!Files.isReadable(configFile)) {
                throw ServiceError.startup("config file " + configFile + " cannot be read");
            }
            try (Reader r = Files.newBufferedReader(configFile, StandardCharsets.UTF_8)) {
                config.load(r);
            } catch (IOException | IllegalArgumentException e) {
                throw ServiceError.startup("config file " + configFile + ": " + e.getMessage());
            }
        }
        boolean[] generated = { false };
        String submit = token(env.get(SUBMIT_ENV), config.getProperty("submit-token"), store, "submit-token", generated);
        String operator = token(env.get(OPERATOR_ENV), config.getProperty("operator-token"), store, "operator-token", generated);
        if (submit.equals(operator)) {
            throw ServiceError.startup("the submit and the operator token must differ");
        }
        return new AccessTokens(submit, operator, generated[0]);
    }

    private static String token(String fromEnv, String fromConfig, TaskStore store, String setting, boolean[] generated) {
        for (String t : new String[] { fromEnv, fromConfig }) {
            if (t != null && !t.isBlank()) {
                if (t.strip().length() < 8) {
                    throw ServiceError.startup(setting + " is too short: a token has at least 8 characters");
                }
                return t.strip();
            }
        }
        Optional<String> stored = store.setting(setting);
        if (stored.isPresent()) {
            return stored.get();
        }
        byte[] bytes = new byte[24];
        new SecureRandom().nextBytes(bytes);
        String t = Base64.getUrlEncoder().withoutPadding().encodeToString(bytes);
        store.putSetting(setting, t);
        generated[0] = true;
        return t;
    }

    /** The role a presented token grants, if any (compared in constant time). */
    public Optional<Role> roleOf(String presented) {
        if (presented == null) {
            return Optional.empty();
        }
        byte[] p = presented.getBytes(StandardCharsets.UTF_8);
        if (MessageDigest.isEqual(p, operator.getBytes(StandardCharsets.UTF_8))) {
            return Optional.of(Role.OPERATOR);
        }
        if (MessageDigest.isEqual(p, submit.getBytes(StandardCharsets.UTF_8))) {
            return Optional.of(Role.SUBMIT);
        }
        return Optional.empty();
    }

    public String submitToken() {
        return submit;
    }

    public String operatorToken() {
        return operator;
    }

    /** Whether a token was made up at this start (then the service prints them). */
    public boolean generated() {
        return generated;
    }
}
