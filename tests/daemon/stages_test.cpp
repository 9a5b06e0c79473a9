// Job and batch stages: every value round-trips through its one spelling, any other text is
// refused, and a state file with a missing or unknown stage reads as held with a one-line reason.
#include <gtest/gtest.h>

#include "daemon/job/job_state.hpp"
#include "daemon/job/stages.hpp"

namespace lastcut::daemon {
namespace {

TEST(Stages, EveryJobStageRoundTrips) {
  EXPECT_EQ(all_job_stages().size(), 8u);
  for (JobStage stage : all_job_stages()) {
    EXPECT_EQ(parse_job_stage(to_string(stage)), stage) << to_string(stage);
  }
}

TEST(Stages, EveryBatchStageRoundTrips) {
  EXPECT_EQ(all_batch_stages().size(), 7u);
  for (BatchStage stage : all_batch_stages()) {
    EXPECT_EQ(parse_batch_stage(to_string(stage)), stage) << to_string(stage);
  }
}

TEST(Stages, SpellingsOnDiskStayTheSame) {
  EXPECT_EQ(to_string(JobStage::Claimed), "claimed");
  EXPECT_EQ(to_string(JobStage::Skipped), "skipped");
  EXPECT_EQ(to_string(BatchStage::Queued), "queued");
  EXPECT_EQ(to_string(BatchStage::Empty), "empty");
}

TEST(Stages, UnknownTextIsRefused) {
  for (const char* text : {"", "xyz", "Queued", "queued ", "done", "nesting"}) {
    EXPECT_FALSE(parse_job_stage(text)) << text;
  }
  for (const char* text : {"", "xyz", "Queued", " queued", "claimed", "computed"}) {
    EXPECT_FALSE(parse_batch_stage(text)) << text;
  }
}

TEST(Stages, BatchFileWithoutStageIsHeldNotQueued) {
  const BatchState batch = batch_state_from_json({{"id", "B1"}, {"cutter", "cutter-1"}, {"jobs", {"J1"}}});
  EXPECT_EQ(batch.stage, BatchStage::Held);
  EXPECT_EQ(batch.stage_problem, "batch.json has no stage");
  EXPECT_EQ(batch.reason, "batch.json has no stage");
}

TEST(Stages, BatchFileWithUnknownStageIsHeld) {
  const BatchState batch = batch_state_from_json({{"id", "B1"}, {"stage", "xyz"}});
  EXPECT_EQ(batch.stage, BatchStage::Held);
  EXPECT_EQ(batch.stage_problem, "batch.json has an unknown stage 'xyz'");
  const BatchState numeric = batch_state_from_json({{"id", "B1"}, {"stage", 3}});
  EXPECT_EQ(numeric.stage_problem, "batch.json has an unknown stage '3'");
}

TEST(Stages, JobFileWithoutOrWithUnknownStageIsHeld) {
  const JobState missing = job_state_from_json({{"id", "J1"}, {"scan", "last.stl"}});
  EXPECT_EQ(missing.stage, JobStage::Held);
  EXPECT_EQ(missing.stage_problem, "state.json has no stage");
  const JobState unknown = job_state_from_json({{"id", "J1"}, {"stage", "cutting"}});
  EXPECT_EQ(unknown.stage, JobStage::Held);
  EXPECT_EQ(unknown.stage_problem, "state.json has an unknown stage 'cutting'");
  EXPECT_EQ(unknown.reason, "state.json has an unknown stage 'cutting'");
}

TEST(Stages, KnownStagesReadBackWithoutProblem) {
  JobState job;
  job.advance(JobStage::Sending, "to cutter-1");
  const JobState read = job_state_from_json(to_json(job));
  EXPECT_EQ(read.stage, JobStage::Sending);
  EXPECT_EQ(read.stage_problem, "");
  BatchState batch;
  batch.stage = BatchStage::Abandoned;
  EXPECT_EQ(batch_state_from_json(to_json(batch)).stage, BatchStage::Abandoned);
  EXPECT_EQ(batch_state_from_json(to_json(batch)).stage_problem, "");
}

}  // namespace
}  // namespace lastcut::daemon
