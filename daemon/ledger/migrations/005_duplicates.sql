-- [jobs] duplicate_policy on the ledger as on one station (docs/daemon.md): bytes already known
-- are skipped (no new job: the one job stays, as before), held for an operator, or processed
-- again as a job of their own. Such a job points to the first job of its bytes (duplicate_of);
-- the first job of each scan stays unique. A duplicate processed again computes into
-- jobs/<sha256>-<id>/ of the shared folder, since its sidecar (order, quantity) may differ.
ALTER TABLE jobs DROP CONSTRAINT jobs_scan_sha256_key;
ALTER TABLE jobs ADD COLUMN duplicate_of bigint REFERENCES jobs (id);
CREATE UNIQUE INDEX jobs_first_of_bytes ON jobs (scan_sha256) WHERE duplicate_of IS NULL;
