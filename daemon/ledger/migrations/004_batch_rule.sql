-- One batching rule for the spool and the ledger ([batch] window_s and max_pieces,
-- daemon/station/batching_policy.hpp): a computed job carries its pieces (molds x quantity), so a
-- batch is limited by pieces, as on one station, not by jobs.
ALTER TABLE jobs ADD COLUMN pieces integer NOT NULL DEFAULT 1 CHECK (pieces >= 0);
