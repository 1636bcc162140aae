-- A client's Idempotency-Key: a submission repeated after a lost answer (the service crashed after the
-- commit, before the 201) finds the task it stored instead of making a second one.
ALTER TABLE task ADD COLUMN submission_key VARCHAR(200);
CREATE UNIQUE INDEX task_by_submission_key ON task(submission_key);
