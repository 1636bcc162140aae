-- Tasks as submitted, their state, their Status history, remote-operation requests and settings (tokens).
CREATE TABLE task (
  id BIGINT AUTO_INCREMENT PRIMARY KEY,
  name VARCHAR(200) NOT NULL,
  args VARCHAR(20000) NOT NULL,
  state VARCHAR(20) NOT NULL,
  robot VARCHAR(200),
  preferred_robot VARCHAR(200),
  reason VARCHAR(4000),
  submitted_at TIMESTAMP WITH TIME ZONE NOT NULL,
  updated_at TIMESTAMP WITH TIME ZONE NOT NULL
);
CREATE INDEX task_by_state ON task(state, id);

CREATE TABLE task_event (
  id BIGINT AUTO_INCREMENT PRIMARY KEY,
  task_id BIGINT NOT NULL REFERENCES task(id),
  at TIMESTAMP WITH TIME ZONE NOT NULL,
  kind VARCHAR(40) NOT NULL,
  robot VARCHAR(200),
  text VARCHAR(4000) NOT NULL
);
CREATE INDEX task_event_by_task ON task_event(task_id, id);

CREATE TABLE remote_request (
  id BIGINT AUTO_INCREMENT PRIMARY KEY,
  task_id BIGINT NOT NULL REFERENCES task(id),
  robot VARCHAR(200),
  goal VARCHAR(1000),
  reason VARCHAR(4000) NOT NULL,
  raised_at TIMESTAMP WITH TIME ZONE NOT NULL,
  resolved_at TIMESTAMP WITH TIME ZONE,
  resolution VARCHAR(40)
);
CREATE INDEX remote_request_open ON remote_request(resolved_at, id);

CREATE TABLE setting (
  name VARCHAR(100) PRIMARY KEY,
  val VARCHAR(1000) NOT NULL
);
