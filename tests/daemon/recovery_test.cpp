// lastcutd's start-up recovery with the real binaries, on spools prepared as a crash (or a
// hand-edited file) would leave them: a batch.json whose stage is missing or unknown is held with
// its jobs and never sent (a simulated plotter records what reached it), and the temporary files
// of unfinished durable writes are removed while the real files stay.
#include <gtest/gtest.h>

#include <thread>

#include "daemon_rig.hpp"

namespace lastcut::daemon::testing {
namespace {

// A job folder in work/ as the daemon leaves it once the job is part of a batch.
void write_batched_job(const DaemonRig& rig, const std::string& id, const std::string& batch_id) {
  const auto dir = rig.spool() / "work" / id;
  std::filesystem::create_directories(dir);
  write_text(dir / (id + ".stl"), "solid x\nendsolid x\n");
  const nlohmann::json state{{"id", id},       {"scan", id + ".stl"},  {"stage", "batched"},
                             {"batch", batch_id}, {"pieces", 2},         {"ticket", {{"material", "calf"}, {"cutter", "cutter-1"}}},
                             {"history", nlohmann::json::array()}};
  write_text(dir / "state.json", state.dump(2));
}

// A batch folder with a cut file; `stage` null leaves the key out.
void write_batch(const DaemonRig& rig, const std::string& id, const std::string& job_id, const nlohmann::json& stage,
                 const std::string& cut_program) {
  const auto dir = rig.spool() / "batches" / id;
  std::filesystem::create_directories(dir);
  write_text(dir / "cut.plt", cut_program);
  nlohmann::json batch{{"id", id},       {"material", "calf"}, {"cutter", "cutter-1"},
                       {"jobs", {job_id}}, {"cut_file", "cut.plt"}, {"pieces", 2}};
  if (!stage.is_null()) batch["stage"] = stage;
  write_text(dir / "batch.json", batch.dump(2));
}

nlohmann::json read_json(const std::filesystem::path& file) {
  return nlohmann::json::parse(read_text(file), nullptr, false);
}

TEST(DaemonRecovery, BatchWithMissingOrUnknownStageIsHeldAndNeverSent) {
  DaemonRig rig("recovery-stage", RigOptions{});
  const std::string missing_job = "20261121-235000-001", unknown_job = "20261121-235000-002",
                    queued_job = "20261121-235000-003";
  const std::string missing_batch = "B20261121-235001-001", unknown_batch = "B20261121-235001-002",
                    queued_batch = "B20261121-235001-003";
  // Each cut file is different, so the plotter's record tells which batch reached it.
  write_batched_job(rig, missing_job, missing_batch);
  write_batch(rig, missing_batch, missing_job, nullptr, "IN;SP1;PU0,0;PD111,0;PU;SP0;\n");
  write_batched_job(rig, unknown_job, unknown_batch);
  write_batch(rig, unknown_batch, unknown_job, "xyz", "IN;SP1;PU0,0;PD222,0;PU;SP0;\n");
  // A well-formed queued batch shows the plotter takes what it is sent.
  write_batched_job(rig, queued_job, queued_batch);
  write_batch(rig, queued_batch, queued_job, "queued", "IN;SP1;PU0,0;PD333,0;PU;SP0;\n");

  rig.start_cutters();
  rig.start_daemon();
  ASSERT_TRUE(wait_until([&] { return rig.settled(3); }, 60)) << read_text(rig.daemon_log());
  const auto status_log = rig.root() / "status.txt";
  EXPECT_EQ(run_command({binary("lastcut").string(), "status", "--spool", rig.spool().string()}, status_log), 0);
  EXPECT_EQ(rig.stop_daemon(), 0);
  rig.stop_cutters();

  const auto held = rig.jobs("held");
  ASSERT_EQ(held.size(), 2u) << read_text(rig.daemon_log());
  EXPECT_EQ(held.at(missing_job).value("reason", ""),
            "batch " + missing_batch + ": batch.json has no stage; not sent, an operator must check it");
  EXPECT_EQ(held.at(unknown_job).value("reason", ""),
            "batch " + unknown_batch + ": batch.json has an unknown stage 'xyz'; not sent, an operator must check it");
  EXPECT_EQ(rig.jobs("done").count(queued_job), 1u);

  const auto missing = read_json(rig.spool() / "batches" / missing_batch / "batch.json");
  EXPECT_EQ(missing.value("stage", ""), "held");
  EXPECT_EQ(missing.value("reason", ""), held.at(missing_job).value("reason", ""));
  const auto unknown = read_json(rig.spool() / "batches" / unknown_batch / "batch.json");
  EXPECT_EQ(unknown.value("stage", ""), "held");

  const std::string status = read_text(status_log);
  EXPECT_NE(status.find("batch.json has no stage"), std::string::npos) << status;
  EXPECT_NE(status.find("batch.json has an unknown stage 'xyz'"), std::string::npos) << status;
  const std::string log = read_text(rig.daemon_log());
  EXPECT_NE(log.find("batch " + missing_batch + ": batch.json has no stage"), std::string::npos) << log;

  const std::string received = rig.received("cutter-1");
  EXPECT_EQ(received.find("PD111"), std::string::npos) << received;
  EXPECT_EQ(received.find("PD222"), std::string::npos) << received;
  EXPECT_EQ(count_occurrences(received, "PD333"), 1) << received;
}

TEST(DaemonRecovery, JobStateWithUnknownStageIsHeldWithTheReason) {
  DaemonRig rig("recovery-job-stage", RigOptions{});
  const std::string id = "20261121-235000-001";
  write_batched_job(rig, id, "");
  auto state = read_json(rig.spool() / "work" / id / "state.json");
  state["stage"] = "cutting";
  write_text(rig.spool() / "work" / id / "state.json", state.dump(2));

  rig.start_daemon();
  ASSERT_TRUE(wait_until([&] { return rig.settled(1); }, 30)) << read_text(rig.daemon_log());
  EXPECT_EQ(rig.stop_daemon(), 0);
  EXPECT_EQ(rig.jobs("held").at(id).value("reason", ""),
            "state.json has an unknown stage 'cutting'; an operator must check the job");
}

TEST(DaemonRecovery, UnfinishedWritesAreRemovedAndRealFilesKept) {
  DaemonRig rig("recovery-temporaries", RigOptions{});
  const std::string id = "20261121-235000-001", batch_id = "B20261121-235001-001";
  // A job that was cut (only its move to done/ is left), with leftovers beside and below it.
  write_batched_job(rig, id, batch_id);
  const auto job = rig.spool() / "work" / id;
  auto state = read_json(job / "state.json");
  state["stage"] = "cut";
  write_text(job / "state.json", state.dump(2));
  std::filesystem::create_directories(job / "molds");
  write_text(job / "molds" / "medial.dxf", "0\nEOF\n");
  write_text(job / "molds" / ".tmp-report.json-4242", "{\"half");
  write_text(job / ".tmp-state.json-4242", "{\"st");
  write_text(job / ".tmp-pieces.json-4242", "");
  write_batch(rig, batch_id, id, "cut", "IN;\n");
  write_text(rig.spool() / "batches" / batch_id / ".tmp-cut.plt-4242", "IN;PU");
  write_text(rig.spool() / ".tmp-status.json-4242", "{");
  // Killed between making a batch folder and writing its first batch.json: only a temporary in it.
  const auto unborn = rig.spool() / "batches" / "B20261121-235002-001";
  std::filesystem::create_directories(unborn);
  write_text(unborn / ".tmp-batch.json-4242", "{\"st");

  rig.start_daemon();
  ASSERT_TRUE(wait_until([&] { return rig.settled(1); }, 30)) << read_text(rig.daemon_log());
  EXPECT_EQ(rig.stop_daemon(), 0);

  const auto done = rig.spool() / "done" / id;
  EXPECT_EQ(rig.jobs("done").at(id).value("stage", ""), "cut");
  EXPECT_EQ(read_text(done / (id + ".stl")), "solid x\nendsolid x\n");
  EXPECT_EQ(read_text(done / "molds" / "medial.dxf"), "0\nEOF\n");
  EXPECT_EQ(read_text(rig.spool() / "batches" / batch_id / "cut.plt"), "IN;\n");
  for (const auto& leftover : {done / "molds" / ".tmp-report.json-4242", done / ".tmp-state.json-4242",
                               done / ".tmp-pieces.json-4242", rig.spool() / "batches" / batch_id / ".tmp-cut.plt-4242",
                               rig.spool() / ".tmp-status.json-4242", unborn}) {
    EXPECT_FALSE(std::filesystem::exists(leftover)) << leftover;
  }
}

}  // namespace
}  // namespace lastcut::daemon::testing
