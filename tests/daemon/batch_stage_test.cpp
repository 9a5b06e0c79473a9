// A spool batch's changes of stage, all through set_batch_stage (spool_store/job_outcomes.hpp), on a
// real spool in a scratch folder: the jobs follow the batch, an end keeps its reason, the one log
// line is written (or left to the caller), and a batch.json that cannot be written is a problem
// in each of its jobs' reports, never a silent loss.
#include <fstream>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "daemon/spool/spool.hpp"
#include "daemon/spool_store/job_outcomes.hpp"
#include "daemon/station/engine_steps.hpp"
#include "daemon_harness.hpp"
#include "tests/station/log_lines.hpp"

namespace lastcut::daemon {
namespace {

// A spool with `count` computed jobs in work/, and a batch of them (its folder made when `with_folder`).
struct SpoolWithBatch {
  explicit SpoolWithBatch(const std::string& name, int count = 2, bool with_folder = true)
      : folder(testing::scratch_folder(name)), spool(folder) {
    EXPECT_EQ(spool.prepare().error(), "");
    for (int i = 0; i < count; ++i) {
      const auto scan = folder / ("s" + std::to_string(i) + ".stl");
      testing::write_text(scan, "x\n");
      const auto claimed = spool.claim(scan, {}, JobState{});
      EXPECT_EQ(claimed.error(), "");
      auto state = spool.read_state(JobFolder::Work, *claimed).value();
      EXPECT_TRUE(set_job_stage(spool, state, JobStage::Computed, "molds ready"));
      batch.job_ids.push_back(*claimed);
    }
    batch.id = spool.new_batch_id();
    batch.material = "calf";
    batch.cutter = "cutter-1";
    if (with_folder) std::filesystem::create_directories(spool.batch_dir(batch.id));
  }
  JobStage stage_of(const std::string& job_id) const { return spool.read_state(JobFolder::Work, job_id).value().stage; }

  std::filesystem::path folder;
  Spool spool;
  BatchState batch;
};

TEST(SetBatchStage, NestingMakesItsJobsPartOfTheBatchAndSaysItInOneLine) {
  SpoolWithBatch rig("batch-nesting");
  testing::LogLines log;
  ASSERT_TRUE(set_batch_stage(rig.spool, rig.batch, BatchStage::Nesting, "nesting 2 job(s) of calf"));
  EXPECT_EQ(rig.spool.read_batch(rig.batch.id).value().stage, BatchStage::Nesting);
  for (const std::string& id : rig.batch.job_ids) {
    const JobState state = rig.spool.read_state(JobFolder::Work, id).value();
    EXPECT_EQ(state.stage, JobStage::Batched);
    EXPECT_EQ(state.batch_id, rig.batch.id);
  }
  EXPECT_EQ(log.count("batch " + rig.batch.id + ": nesting 2 job(s) of calf"), 1) << log.text();
  EXPECT_EQ(log.count(": nested in batch " + rig.batch.id), 2) << log.text();
}

TEST(SetBatchStage, SendingAndBackToTheQueueMoveItsJobsAndTheCallerSaysIt) {
  SpoolWithBatch rig("batch-sending");
  ASSERT_TRUE(set_batch_stage(rig.spool, rig.batch, BatchStage::Nesting, "nesting"));
  ASSERT_TRUE(set_batch_stage(rig.spool, rig.batch, BatchStage::Queued, "queued for cutter-1"));
  testing::LogLines log;
  ASSERT_TRUE(set_batch_stage(rig.spool, rig.batch, BatchStage::Sending, "sending to cutter-1", BatchLine::ByCaller));
  for (const std::string& id : rig.batch.job_ids) EXPECT_EQ(rig.stage_of(id), JobStage::Sending);
  ASSERT_TRUE(set_batch_stage(rig.spool, rig.batch, BatchStage::Queued, "refused before cutting", BatchLine::ByCaller));
  for (const std::string& id : rig.batch.job_ids) EXPECT_EQ(rig.stage_of(id), JobStage::Batched);
  EXPECT_EQ(log.count("batch " + rig.batch.id + ":"), 0) << "the cutter worker says these: " << log.text();
}

TEST(SetBatchStage, AnEndKeepsItsNoteAsTheReasonAndIsAWarning) {
  SpoolWithBatch rig("batch-held", 1);
  testing::LogLines log;
  ASSERT_TRUE(set_batch_stage(rig.spool, rig.batch, BatchStage::Held, "lastcutd stopped while sending"));
  const BatchState read = rig.spool.read_batch(rig.batch.id).value();
  EXPECT_EQ(read.stage, BatchStage::Held);
  EXPECT_EQ(read.reason, "lastcutd stopped while sending");
  EXPECT_EQ(log.count("batch " + rig.batch.id + ": lastcutd stopped while sending"), 1) << log.text();
}

TEST(SetBatchStage, ABatchJsonThatCannotBeWrittenIsAProblemInEachJobsReport) {
  SpoolWithBatch rig("batch-unwritable", 2, false);  // no batch folder: batch.json cannot be written
  EXPECT_FALSE(set_batch_stage(rig.spool, rig.batch, BatchStage::Nesting, "nesting", BatchLine::Logged,
                               "cannot be written; its jobs wait for the next start"));
  for (const std::string& id : rig.batch.job_ids) {
    EXPECT_EQ(rig.stage_of(id), JobStage::Computed) << "not batched when the batch was not written";
    std::ifstream in(rig.spool.job_dir(JobFolder::Work, id) / kReportFile);
    const nlohmann::json report = nlohmann::json::parse(in, nullptr, false);
    ASSERT_TRUE(report.contains("problems")) << report.dump();
    const std::string problem = report["problems"][0]["problem"];
    EXPECT_EQ(problem.rfind("batch " + rig.batch.id + ": cannot be written; its jobs wait for the next start: ", 0), 0u)
        << problem;
  }
}

}  // namespace
}  // namespace lastcut::daemon
