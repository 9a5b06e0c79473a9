-- Which batch cut a job (issue 35): a job cut in parts, or split over hides, leaves each part's batch
-- when the part is cut (jobs.batch_id names only the batch of its current part), so the overview
-- counted such a batch's jobs as none. The job's 'cut' event now names its batch, and the overview
-- counts a cut batch's jobs from these events.
ALTER TABLE job_events ADD COLUMN batch_id bigint;
CREATE INDEX job_events_batch ON job_events (batch_id) WHERE batch_id IS NOT NULL;
