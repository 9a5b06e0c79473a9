-- The job ledger shared by several lastcutd nodes (docs/multi-station.md).
-- A job is one scan, known by the SHA-256 of its bytes (unique: the same scan dropped on two nodes
-- is one job). A compute node claims a `ready` job with a lease, computes its molds into the shared
-- folder and marks it `computed`; jobs are nested into batches; the station that owns the batch's
-- cutter claims it, marks it `sending` before the first byte and `cut` when the machine is done.
-- A batch whose station vanished while `sending` is `held` for an operator, never sent again.

-- Machines running lastcutd; heartbeat_at is renewed with their leases.
CREATE TABLE nodes (
  name         text PRIMARY KEY,
  roles        text[] NOT NULL,
  started_at   timestamptz NOT NULL DEFAULT now(),
  heartbeat_at timestamptz NOT NULL DEFAULT now()
);

-- Each cutter is cabled to one station; only that station sends to it.
CREATE TABLE cutters (
  name       text PRIMARY KEY,
  station    text NOT NULL REFERENCES nodes (name),
  updated_at timestamptz NOT NULL DEFAULT now()
);

-- Leather hides and roll pieces (issue #13 fills them: outline, flaws, quality regions).
CREATE TABLE hides (
  id         bigserial PRIMARY KEY,
  name       text NOT NULL UNIQUE,
  material   text NOT NULL,
  state      text NOT NULL DEFAULT 'available' CHECK (state IN ('available', 'reserved', 'used')),
  outline    jsonb,
  created_at timestamptz NOT NULL DEFAULT now()
);

CREATE TABLE batches (
  id         bigserial PRIMARY KEY,
  cutter     text NOT NULL,
  material   text NOT NULL,
  state      text NOT NULL CHECK (state IN ('queued', 'claimed', 'sending', 'cut', 'held')),
  hide_id    bigint REFERENCES hides (id),
  reason     text,
  created_by text NOT NULL,
  created_at timestamptz NOT NULL DEFAULT now(),
  updated_at timestamptz NOT NULL DEFAULT now()
);
CREATE INDEX batches_queued ON batches (cutter, created_at, id) WHERE state = 'queued';

CREATE TABLE jobs (
  id          bigserial PRIMARY KEY,
  scan_sha256 text NOT NULL UNIQUE CHECK (scan_sha256 ~ '^[0-9a-f]{64}$'),
  scan_name   text NOT NULL,
  ticket      text NOT NULL DEFAULT '',
  material    text NOT NULL,
  cutter      text NOT NULL,
  state       text NOT NULL CHECK (state IN ('ready', 'computing', 'computed', 'batched', 'done', 'failed', 'held')),
  attempts    integer NOT NULL DEFAULT 0,
  batch_id    bigint REFERENCES batches (id),
  reason      text,
  origin      text NOT NULL,
  created_at  timestamptz NOT NULL DEFAULT now(),
  updated_at  timestamptz NOT NULL DEFAULT now()
);
CREATE INDEX jobs_ready ON jobs (created_at, id) WHERE state = 'ready';
CREATE INDEX jobs_computed ON jobs (cutter, material, created_at, id) WHERE state = 'computed';
CREATE INDEX jobs_batch ON jobs (batch_id);

-- One row per job or batch ever claimed; never deleted, so that the epoch only grows (a released
-- lease has no holder). Every state change checks holder and epoch in its own transaction (fencing).
CREATE TABLE leases (
  kind       text NOT NULL CHECK (kind IN ('job', 'batch')),
  object_id  bigint NOT NULL,
  holder     text,
  epoch      bigint NOT NULL,
  expires_at timestamptz,
  PRIMARY KEY (kind, object_id)
);
CREATE INDEX leases_expiring ON leases (expires_at) WHERE holder IS NOT NULL;

-- The story of every job: who did what when (the ledger's counterpart of the spool's state.json).
CREATE TABLE job_events (
  id     bigserial PRIMARY KEY,
  job_id bigint NOT NULL REFERENCES jobs (id),
  at     timestamptz NOT NULL DEFAULT now(),
  node   text NOT NULL,
  event  text NOT NULL,
  detail text NOT NULL DEFAULT ''
);
CREATE INDEX job_events_job ON job_events (job_id, id);
