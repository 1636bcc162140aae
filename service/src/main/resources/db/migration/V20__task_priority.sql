-- Task priority (issue #20): higher runs first, first come first served within a priority. Portable SQL
-- (H2, PostgreSQL, SQLite): a plain column with a default, no vendor types.
ALTER TABLE task ADD COLUMN priority INTEGER DEFAULT 0 NOT NULL;
