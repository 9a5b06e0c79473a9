-- Leather hides on the ledger (docs/hides.md, docs/multi-station.md). A hide file dropped into a
-- node's hides folder (or named from stock with `lastcut hide load`) is copied into the shared
-- folder and entered here as `loaded`: it lies on `cutter`'s table. A compute node nests the
-- computed jobs of its material on it (state `nesting`, in a batch with hide_id set, under the
-- batch's lease); the batch then goes to the cutter's station like a strip batch. Jobs that did not
-- fit go back to `computed` with the reason and wait for the next hide. A hide on which nothing fitted
-- is `empty`; dropped again later, it is loaded again. A nesting node that vanished leaves the hide
-- `loaded` again and its batch dissolved.
ALTER TABLE hides DROP CONSTRAINT hides_state_check;
ALTER TABLE hides ADD CONSTRAINT hides_state_check
  CHECK (state IN ('available', 'loaded', 'nesting', 'used', 'empty'));
ALTER TABLE hides ADD COLUMN cutter text NOT NULL DEFAULT '';
ALTER TABLE hides ADD COLUMN hide_file text NOT NULL DEFAULT '';
ALTER TABLE hides ADD COLUMN area_m2 double precision NOT NULL DEFAULT 0;
ALTER TABLE hides ADD COLUMN reason text;
ALTER TABLE hides ADD COLUMN entered_by text NOT NULL DEFAULT '';
ALTER TABLE hides ADD COLUMN updated_at timestamptz NOT NULL DEFAULT now();
CREATE INDEX hides_loaded ON hides (updated_at, id) WHERE state = 'loaded';
ALTER TABLE batches ADD COLUMN utilisation double precision NOT NULL DEFAULT 0;
