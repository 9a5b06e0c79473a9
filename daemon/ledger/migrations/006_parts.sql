-- A job whose pieces are of several materials is cut in parts, one material after another
-- (daemon/job/job_parts.hpp, docs/cutting-pieces.md): parts lists them in cutting order as
-- [{material, cutter, pieces}], part is the one nested or cut now, and the job's material, cutter
-- and pieces are that part's. When a part's batch is cut and another part follows, the job is
-- computed again with the next part (its batch_id cleared: the job's events keep which batch cut
-- which part); after the last part it is done. A job of one material has no parts.
ALTER TABLE jobs ADD COLUMN parts jsonb NOT NULL DEFAULT '[]'::jsonb CHECK (jsonb_typeof(parts) = 'array');
ALTER TABLE jobs ADD COLUMN part integer NOT NULL DEFAULT 0 CHECK (part >= 0);
