-- Named users with a role and a bcrypt hash of their secret, and the audit log of who did what when
-- (issue 25). Portable SQL (H2, PostgreSQL, SQLite): no identity columns, the service numbers entries.
CREATE TABLE app_user (
  name VARCHAR(64) PRIMARY KEY,
  role VARCHAR(16) NOT NULL,
  secret_hash VARCHAR(100) NOT NULL,
  created_at TIMESTAMP NOT NULL,
  revoked_at TIMESTAMP
);

CREATE TABLE audit_entry (
  id BIGINT PRIMARY KEY,
  happened_at TIMESTAMP NOT NULL,
  who VARCHAR(100) NOT NULL,
  what VARCHAR(100) NOT NULL,
  detail VARCHAR(1000) NOT NULL
);
