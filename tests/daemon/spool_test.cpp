// The spool's building blocks on real files: SHA-256 against the FIPS 180-4 examples, durable
// writes, claims that move scan and sidecar together, folder moves, sidecar validation.
#include <gtest/gtest.h>

#include "engine/core/durable_file.hpp"
#include "daemon/job/job_ticket.hpp"
#include "daemon/job/sha256.hpp"
#include "daemon/spool/spool.hpp"
#include "daemon_harness.hpp"

namespace lastcut::daemon {
namespace {

using testing::read_text;
using testing::write_text;

TEST(Sha256, MatchesTheStandardsExamples) {
  EXPECT_EQ(sha256_hex("abc"), "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
  EXPECT_EQ(sha256_hex(""), "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
  EXPECT_EQ(sha256_hex("abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq"),
            "248d6a61d20638b8e5c026930c3e6039a33ce45964ff2167f6ecedd419db06c1");
  const std::string million(1000000, 'a');
  EXPECT_EQ(sha256_hex(million), "cdc76e5c9914fb9281a1c7e284d73e67f1809a48a497200e046d39ccc7112cd0");
}

TEST(Sha256, FileHashEqualsMemoryHash) {
  const auto folder = testing::scratch_folder("sha");
  std::string bytes;
  for (int i = 0; i < 200000; ++i) bytes.push_back(static_cast<char>(i * 7));
  write_text(folder / "f.bin", bytes);
  EXPECT_EQ(sha256_file_hex(folder / "f.bin").value(), sha256_hex(bytes));
  EXPECT_FALSE(sha256_file_hex(folder / "missing.bin"));
}

TEST(DurableFile, ReplacesContentAndLeavesNoTemporary) {
  const auto folder = testing::scratch_folder("durable");
  ASSERT_EQ(write_file_durably(folder / "state.json", "one").error(), "");
  ASSERT_EQ(write_file_durably(folder / "state.json", "two").error(), "");
  EXPECT_EQ(read_text(folder / "state.json"), "two");
  EXPECT_EQ(testing::count_entries(folder), 1);
  for (const auto& entry : std::filesystem::directory_iterator(folder)) {
    EXPECT_EQ(entry.path().filename(), "state.json");
  }
  EXPECT_NE(write_file_durably(folder / "no-such-folder" / "x", "y").error(), "");
}

TEST(DurableFile, MoveAndCopy) {
  const auto folder = testing::scratch_folder("move");
  write_text(folder / "a", "payload");
  ASSERT_EQ(copy_file_durably(folder / "a", folder / "b").error(), "");
  ASSERT_EQ(move_durably(folder / "a", folder / "c").error(), "");
  EXPECT_FALSE(std::filesystem::exists(folder / "a"));
  EXPECT_EQ(read_text(folder / "b"), "payload");
  EXPECT_EQ(read_text(folder / "c"), "payload");
  EXPECT_NE(move_durably(folder / "a", folder / "d").error(), "");
}

TEST(Spool, ClaimMovesScanAndSidecarIntoAWorkFolder) {
  const auto folder = testing::scratch_folder("claim");
  Spool spool(folder / "spool");
  ASSERT_EQ(spool.prepare().error(), "");
  std::filesystem::create_directories(folder / "in");
  write_text(folder / "in" / "last.stl", "solid x\nendsolid x\n");
  write_text(folder / "in" / "last.job.toml", "order = \"4711\"\n");
  JobState state;
  state.sha256 = "abc";
  state.ticket.order = "4711";
  const Result<std::string> claim = spool.claim(folder / "in" / "last.stl", folder / "in" / "last.job.toml", state);
  ASSERT_EQ(claim.error(), "");
  const std::string& job_id = *claim;
  EXPECT_EQ(testing::count_entries(folder / "in"), 0);
  const auto dir = spool.job_dir(JobFolder::Work, job_id);
  EXPECT_TRUE(std::filesystem::exists(dir / "last.stl"));
  EXPECT_TRUE(std::filesystem::exists(dir / "last.job.toml"));
  const auto read = spool.read_state(JobFolder::Work, job_id);
  ASSERT_TRUE(read);
  EXPECT_EQ(read->scan_name, "last.stl");
  EXPECT_EQ(read->sidecar_name, "last.job.toml");
  EXPECT_EQ(read->ticket.order, "4711");
  EXPECT_EQ(read->stage, JobStage::Claimed);
  EXPECT_EQ(spool.locate(job_id), JobFolder::Work);
}

TEST(Spool, IdsAreUniqueAndSortByTime) {
  const auto folder = testing::scratch_folder("ids");
  Spool spool(folder);
  ASSERT_EQ(spool.prepare().error(), "");
  std::set<std::string> ids;
  std::string previous;
  for (int i = 0; i < 30; ++i) {
    write_text(folder / ("s" + std::to_string(i) + ".stl"), "x\n");
    const auto claim = spool.claim(folder / ("s" + std::to_string(i) + ".stl"), {}, JobState{});
    ASSERT_EQ(claim.error(), "");
    EXPECT_GT(*claim, previous);
    previous = *claim;
    ids.insert(*claim);
  }
  EXPECT_EQ(ids.size(), 30u);
  EXPECT_EQ(spool.list(JobFolder::Work).size(), 30u);
}

TEST(Spool, MoveJobWritesStateThenRenames) {
  const auto folder = testing::scratch_folder("movejob");
  Spool spool(folder);
  ASSERT_EQ(spool.prepare().error(), "");
  write_text(folder / "s.stl", "x\n");
  const auto claim = spool.claim(folder / "s.stl", {}, JobState{});
  ASSERT_EQ(claim.error(), "");
  const std::string& job_id = *claim;
  auto state = spool.read_state(JobFolder::Work, job_id).value();
  state.reason = "the file is cut off";
  state.advance(JobStage::Failed, state.reason);
  ASSERT_EQ(spool.move_job(JobFolder::Work, JobFolder::Failed, state).error(), "");
  EXPECT_EQ(spool.locate(job_id), JobFolder::Failed);
  const auto failed = spool.read_state(JobFolder::Failed, job_id).value();
  EXPECT_EQ(failed.stage, JobStage::Failed);
  EXPECT_EQ(failed.reason, "the file is cut off");
  EXPECT_TRUE(std::filesystem::exists(spool.job_dir(JobFolder::Failed, job_id) / "s.stl"));
  EXPECT_GE(failed.history.size(), 2u);
}

TEST(JobTicket, TomlAndJsonSidecarsAreReadAlike) {
  const auto folder = testing::scratch_folder("ticket");
  write_text(folder / "a.job.toml",
             "order = \"4711\"\ncustomer = \"Meier\"\nsize = \"EU 42\"\nside = \"pair\"\nquantity = 2\n"
             "material = \"calf\"\ncutter = \"b\"\nallowance_mm = 8.0\npriority = 3\n");
  write_text(folder / "b.job.json",
             R"({"order": 4711, "customer": "Meier", "size": "EU 42", "side": "pair", "quantity": 2,
                 "material": "calf", "cutter": "b", "allowance_mm": 8, "priority": 3})");
  for (const char* name : {"a.job.toml", "b.job.json"}) {
    const auto result = read_job_ticket(folder / name);
    ASSERT_TRUE(result) << result.error();
    EXPECT_EQ(result->order, "4711");
    EXPECT_EQ(result->side, "pair");
    EXPECT_EQ(result->quantity, 2);
    EXPECT_EQ(result->cutter, "b");
    EXPECT_DOUBLE_EQ(result->allowance_mm.value(), 8.0);
  }
}

TEST(JobTicket, ReferencePatternsSurviveTheStateJson) {
  const auto folder = testing::scratch_folder("ticket-references");
  write_text(folder / "r.job.toml", "reference_medial = \"patterns/4712-m.dxf\"\nreference_lateral = \"4712-l.svg\"\n");
  const auto result = read_job_ticket(folder / "r.job.toml");
  ASSERT_TRUE(result) << result.error();
  EXPECT_EQ(result->references.at("medial"), "patterns/4712-m.dxf");
  EXPECT_EQ(result->references.at("lateral"), "4712-l.svg");
  EXPECT_EQ(result->references.count("patch"), 0u);
  const JobTicket again = ticket_from_json(ticket_to_json(*result));
  EXPECT_EQ(again.references, result->references);
  EXPECT_EQ(reference_copy_name("medial", "patterns/4712-m.dxf"), "reference-medial.dxf");
}

TEST(JobTicket, BadSidecarsAreRefusedWithTheReason) {
  const auto folder = testing::scratch_folder("badticket");
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"order = \"1\"\ncolour = \"red\"\n", "unknown key \"colour\""},
      {"quantity = 0\n", "quantity must be"},
      {"side = \"both\"\n", "side \"both\""},
      {"allowance_mm = \"wide\"\n", "allowance_mm must be"},
      {"order = \n", "line 1"},
      {"split = \"sideways\"\n", "split \"sideways\" is not one of auto, expert"},
      {"reference_medial = 3\n", "reference_medial must be a file name"},
      {"reference_left = \"p.dxf\"\n", "unknown key \"reference_left\""},
  };
  for (const auto& [text, expected] : cases) {
    write_text(folder / "x.job.toml", text);
    const auto result = read_job_ticket(folder / "x.job.toml");
    EXPECT_FALSE(result) << text;
    EXPECT_NE(result.error().find(expected), std::string::npos) << result.error();
    EXPECT_EQ(result.error().find('\n'), std::string::npos) << "one line: " << result.error();
  }
  write_text(folder / "y.job.json", "{\"order\": ");
  EXPECT_NE(read_job_ticket(folder / "y.job.json").error().find("not valid JSON"), std::string::npos);
}

TEST(JobTicket, SplitRuleIsReadAndAnUnknownOneRefusedInOneLine) {
  const auto folder = testing::scratch_folder("splitticket");
  write_text(folder / "e.job.toml", "split = \"expert\"\n");
  const auto expert = read_job_ticket(folder / "e.job.toml");
  ASSERT_TRUE(expert) << expert.error();
  EXPECT_EQ(expert->split, "expert");
  EXPECT_EQ(ticket_from_json(ticket_to_json(*expert)).split, "expert");
  write_text(folder / "s.job.toml", "split = \"sideways\"\n");
  EXPECT_EQ(read_job_ticket(folder / "s.job.toml").error(), "sidecar s.job.toml: split \"sideways\" is not one of auto, expert");
}

TEST(JobTicket, SplittingOverHidesIsReadAndAnythingButABooleanRefusedInOneLine) {
  const auto folder = testing::scratch_folder("splithidesticket");
  write_text(folder / "h.job.toml", "split_over_hides = true\n");
  const auto split = read_job_ticket(folder / "h.job.toml");
  ASSERT_TRUE(split) << split.error();
  EXPECT_TRUE(split->split_over_hides);
  EXPECT_TRUE(ticket_from_json(ticket_to_json(*split)).split_over_hides);
  EXPECT_FALSE(ticket_from_json(ticket_to_json(JobTicket{})).split_over_hides);
  write_text(folder / "n.job.toml", "split_over_hides = \"yes\"\n");
  EXPECT_EQ(read_job_ticket(folder / "n.job.toml").error(), "sidecar n.job.toml: split_over_hides must be true or false");
}

TEST(JobTicket, SidecarIsFoundBesideTheScan) {
  const auto folder = testing::scratch_folder("findticket");
  write_text(folder / "last.stl", "x");
  EXPECT_TRUE(find_sidecar(folder / "last.stl").empty());
  write_text(folder / "last.job.json", "{}");
  EXPECT_EQ(find_sidecar(folder / "last.stl").filename(), "last.job.json");
  EXPECT_TRUE(is_sidecar_name("a.job.toml"));
  EXPECT_FALSE(is_sidecar_name("a.toml"));
}

}  // namespace
}  // namespace lastcut::daemon
