// Per-edge allowances and balance notches per job: the sidecar keys (TOML and JSON alike, bad
// values refused with one exact line), the [jobs] defaults of lastcut.toml, and which of them a
// job's molds are made with.
#include <gtest/gtest.h>

#include "daemon/config/config_loader.hpp"
#include "daemon/station/job_mold_options.hpp"
#include "daemon/job/job_ticket.hpp"
#include "daemon_harness.hpp"

namespace lastcut::daemon {
namespace {

TEST(JobTicketMoldKeys, TomlAndJsonSidecarsGiveTheSameAllowancesAndSpacings) {
  const auto folder = testing::scratch_folder("mold-keys");
  testing::write_text(folder / "a.job.toml",
                      "lasting_mm = 16.0\nseam_mm = 5\ntop_mm = 0.5\nseam_notch_spacing_mm = 25\n"
                      "feather_notch_spacing_mm = 0\n");
  testing::write_text(folder / "b.job.json",
                      R"({"lasting_mm": 16, "seam_mm": 5.0, "top_mm": 0.5, "seam_notch_spacing_mm": 25,
                          "feather_notch_spacing_mm": 0})");
  for (const char* name : {"a.job.toml", "b.job.json"}) {
    const auto result = read_job_ticket(folder / name);
    ASSERT_TRUE(result) << result.error();
    EXPECT_EQ(result->lasting_mm, 16.0);
    EXPECT_EQ(result->seam_mm, 5.0);
    EXPECT_EQ(result->top_mm, 0.5);
    EXPECT_EQ(result->seam_notch_spacing_mm, 25.0);
    EXPECT_EQ(result->feather_notch_spacing_mm, 0.0);
    EXPECT_FALSE(result->allowance_mm);
    // The ticket survives the job state file (JSON) unchanged.
    const JobTicket back = ticket_from_json(ticket_to_json(*result));
    EXPECT_EQ(back.lasting_mm, result->lasting_mm);
    EXPECT_EQ(back.seam_mm, result->seam_mm);
    EXPECT_EQ(back.top_mm, result->top_mm);
    EXPECT_EQ(back.seam_notch_spacing_mm, result->seam_notch_spacing_mm);
    EXPECT_EQ(back.feather_notch_spacing_mm, result->feather_notch_spacing_mm);
  }
}

TEST(JobTicketMoldKeys, BadValuesAreRefusedWithOneExactLine) {
  const auto folder = testing::scratch_folder("bad-mold-keys");
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"lasting_mm = -1\n", "lasting_mm must be a number from 0 to 50"},
      {"seam_mm = 51\n", "seam_mm must be a number from 0 to 50"},
      {"top_mm = \"none\"\n", "top_mm must be a number from 0 to 50"},
      {"lasting_mm = nan\n", "lasting_mm must be a number from 0 to 50"},
      {"lasting_mm = inf\n", "lasting_mm must be a number from 0 to 50"},
      {"allowance_mm = 3\nseam_mm = 4\n", "allowance_mm (all edges) and lasting_mm/seam_mm/top_mm cannot be given together"},
      {"seam_notch_spacing_mm = 2\n", "seam_notch_spacing_mm must be 0 (off) or a number from 5 to 500"},
      {"feather_notch_spacing_mm = 501\n", "feather_notch_spacing_mm must be 0 (off) or a number from 5 to 500"},
      {"feather_notch_spacing_mm = -50\n", "feather_notch_spacing_mm must be 0 (off) or a number from 5 to 500"},
      {"seam_notch_spacing = 20\n", "unknown key \"seam_notch_spacing\""},
  };
  for (const auto& [text, expected] : cases) {
    testing::write_text(folder / "x.job.toml", text);
    const auto result = read_job_ticket(folder / "x.job.toml");
    ASSERT_FALSE(result) << text;
    EXPECT_EQ(result.error(), "sidecar x.job.toml: " + expected) << text;
  }
}

TEST(JobMoldOptions, SidecarFirstThenTheConfiguredDefaults) {
  JobsConfig jobs;
  JobTicket ticket;
  MoldOptions options = job_mold_options(ticket, jobs);  // nothing anywhere: the old net mold
  EXPECT_FALSE(options.edge_allowances);
  EXPECT_EQ(options.allowance_mm, 0.0);
  EXPECT_EQ(options.balance_notches.seam_spacing_mm, 0.0);

  jobs.default_allowance_mm = 4;
  EXPECT_EQ(job_mold_options(ticket, jobs).allowance_mm, 4.0);

  jobs.default_lasting_mm = 16, jobs.default_seam_mm = 5, jobs.default_seam_notch_spacing_mm = 25;
  options = job_mold_options(ticket, jobs);  // per-edge defaults win over the uniform default
  ASSERT_TRUE(options.edge_allowances);
  EXPECT_EQ(options.edge_allowances->lasting_mm, 16.0);
  EXPECT_EQ(options.edge_allowances->seam_mm, 5.0);
  EXPECT_EQ(options.edge_allowances->top_mm, 0.0);
  EXPECT_EQ(options.allowance_mm, 0.0);
  EXPECT_EQ(options.balance_notches.seam_spacing_mm, 25.0);

  ticket.seam_mm = 3;
  ticket.feather_notch_spacing_mm = 50;
  options = job_mold_options(ticket, jobs);  // each edge: the sidecar's, else the default
  EXPECT_EQ(options.edge_allowances->lasting_mm, 16.0);
  EXPECT_EQ(options.edge_allowances->seam_mm, 3.0);
  EXPECT_EQ(options.balance_notches.feather_spacing_mm, 50.0);

  JobTicket uniform;
  uniform.allowance_mm = 8;
  options = job_mold_options(uniform, jobs);  // the sidecar's one allowance all around
  EXPECT_FALSE(options.edge_allowances);
  EXPECT_EQ(options.allowance_mm, 8.0);
}

TEST(JobMoldOptions, ConfigDefaultsAreRangeChecked) {
  const auto folder = testing::scratch_folder("mold-defaults");
  const std::string base = "[paths]\nwatch = \"in\"\nspool = \"spool\"\nmachines = \"machines\"\n[jobs]\n"
                           "default_material = \"calf\"\ndefault_cutter = \"a\"\n";
  const std::string rest = "[materials.calf]\nwidth_mm = 500\nlength_mm = 900\n[cutters.a]\nprotocol = \"grbl\"\n"
                           "port = \"/dev/ttyUSB0\"\nmachine = \"grbl-drag-knife\"\n";
  testing::write_text(folder / "lastcut.toml", base + "default_lasting_mm = 16\ndefault_seam_mm = 5\n"
                                               "default_feather_notch_spacing_mm = 50\n" + rest);
  auto result = load_daemon_config(folder / "lastcut.toml");
  ASSERT_TRUE(result.config) << result.error;
  EXPECT_EQ(result.config->jobs.default_lasting_mm, 16.0);
  EXPECT_EQ(result.config->jobs.default_feather_notch_spacing_mm, 50.0);
  testing::write_text(folder / "lastcut.toml", base + "default_seam_notch_spacing_mm = 2\n" + rest);
  result = load_daemon_config(folder / "lastcut.toml");
  ASSERT_FALSE(result.config);
  EXPECT_NE(result.error.find("jobs.default_seam_notch_spacing_mm: must be 0 (off) or from 5 to 500"), std::string::npos)
      << result.error;
  testing::write_text(folder / "lastcut.toml", base + "default_lasting_mm = 60\n" + rest);
  result = load_daemon_config(folder / "lastcut.toml");
  ASSERT_FALSE(result.config);
  EXPECT_NE(result.error.find("jobs.default_lasting_mm"), std::string::npos) << result.error;
}

}  // namespace
}  // namespace lastcut::daemon
