-- Nesting on the ledger (lastcutd ledger nodes, docs/multi-station.md): a compute node groups
-- computed jobs into a batch in state `nesting` under its lease, nests them and writes the cut file
-- into the shared folder, then the batch is `queued` for its cutter's station with the file's name.
-- A nesting node that vanishes leaves the batch `dissolved`: its jobs are back in `computed`, to be
-- grouped anew. A job may end `held` for review right after its computation (reference check).
ALTER TABLE batches DROP CONSTRAINT batches_state_check;
ALTER TABLE batches ADD CONSTRAINT batches_state_check
  CHECK (state IN ('nesting', 'queued', 'claimed', 'sending', 'cut', 'held', 'dissolved'));
ALTER TABLE batches ADD COLUMN cut_file text NOT NULL DEFAULT '';
ALTER TABLE batches ADD COLUMN pieces integer NOT NULL DEFAULT 0;
