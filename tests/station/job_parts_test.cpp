// A job of several materials (daemon/job/job_parts.hpp, daemon/station/job_piece_rules.hpp): which
// material each piece is cut from, the parts' order and cutters, the items file of each part, and the
// job state's move from one part to the next, written down by hand from the configuration below.
#include <gtest/gtest.h>

#include <unistd.h>

#include <fstream>

#include "daemon/job/job_state.hpp"
#include "daemon/station/engine_steps.hpp"
#include "daemon/station/job_piece_rules.hpp"
#include "engine/nest/nest_json.hpp"

namespace lastcut::daemon {
namespace {

DaemonConfig shop() {
  DaemonConfig config;
  config.jobs.default_material = "calf";
  config.jobs.default_cutter = "cutter-1";
  MaterialConfig roll;
  config.materials["calf"] = roll;
  roll.cutter = "cutter-2";
  config.materials["lining"] = roll;
  config.materials["felt"] = MaterialConfig{};  // no cutter of its own
  MaterialConfig hide;
  hide.kind = MaterialKind::Hide;
  hide.cutter = "cutter-3";
  config.materials["leather"] = hide;
  return config;
}

NestItem square_item(const std::string& label, int demand) {
  NestItem item;
  item.label = label;
  item.demand = demand;
  item.shape = Polygon2{{{0, 0}, {50, 0}, {50, 50}, {0, 50}}};
  return item;
}

TEST(JobParts, APieceIsCutFromTheConfiguredMaterialItNamesElseFromTheJobs) {
  const DaemonConfig config = shop();
  JobTicket ticket;
  ticket.material = "leather";
  const JobMaterial job = job_material(ticket, config);
  EXPECT_EQ(piece_material("lining", job, config), "lining");
  EXPECT_EQ(piece_material("upper leather", job, config), "leather");  // not configured: the job's
  EXPECT_EQ(piece_material("", job, config), "leather");
  ticket.material.clear();
  EXPECT_EQ(job_material(ticket, config).name, "calf");  // jobs.default_material
}

TEST(JobParts, RollsAndSheetsComeFirstThenHidesEachOnItsCutter) {
  const DaemonConfig config = shop();
  JobTicket ticket;
  ticket.material = "leather";
  ticket.cutter = "cutter-9";  // the sidecar's: for the job's own material
  const std::vector<JobPart> parts =
      job_parts({"leather", "lining", "felt", "leather", "lining"}, {2, 3, 1, 2, 1}, ticket, config);
  ASSERT_EQ(parts.size(), 3u);
  EXPECT_EQ(parts[0], (JobPart{"felt", "cutter-1", 1}));     // no cutter of its own: jobs.default_cutter
  EXPECT_EQ(parts[1], (JobPart{"lining", "cutter-2", 4}));   // the material's cutter
  EXPECT_EQ(parts[2], (JobPart{"leather", "cutter-9", 4}));  // the job's own material: the ticket's cutter
  EXPECT_EQ(describe_parts(parts), "1 piece of felt on cutter-1, then 4 pieces of lining on cutter-2, then 4 pieces of leather on cutter-9");
  EXPECT_TRUE(job_parts({"leather", "leather"}, {1, 1}, ticket, config).empty()) << "one material: no parts";
}

TEST(JobParts, EachPartsItemsGoToAFileOfTheirOwn) {
  const auto dir = std::filesystem::temp_directory_path() / ("lastcut-job-parts-" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  const DaemonConfig config = shop();
  JobTicket ticket;
  ticket.material = "leather";
  const std::vector<NestItem> items = {square_item("vamp", 2), square_item("lining", 2), square_item("counter", 1)};
  const Result<MoldsMade> made =
      save_job_items_by_material(dir, items, {"leather", "lining", "leather"}, ticket, config, MoldsMade{}, "pieces");
  ASSERT_TRUE(made) << made.error();
  EXPECT_EQ(made->pieces_to_cut, 5);
  ASSERT_EQ(made->parts.size(), 2u);
  EXPECT_FALSE(std::filesystem::exists(dir / kItemsFile));
  EXPECT_EQ(job_items_path(dir, "lining").filename(), "items-lining.json");
  const auto leather = items_from_json(read_json_file(job_items_path(dir, "leather")), "leather");
  ASSERT_EQ(leather.size(), 2u);
  EXPECT_EQ(leather[0].label, "vamp");
  EXPECT_EQ(leather[1].label, "counter");
  EXPECT_EQ(items_from_json(read_json_file(job_items_path(dir, "lining")), "lining").at(0).label, "lining");
  // A material that is no part of this job: the job's items.json (its reader then says what is missing).
  EXPECT_EQ(job_items_path(dir, "upper leather/2").filename(), "items.json");
  remove_job_items(dir);
  EXPECT_TRUE(std::filesystem::is_empty(dir));
  // One material: items.json, as before.
  const Result<MoldsMade> single =
      save_job_items_by_material(dir, items, {"leather", "leather", "leather"}, ticket, config, MoldsMade{}, "pieces");
  ASSERT_TRUE(single) << single.error();
  EXPECT_TRUE(single->parts.empty());
  EXPECT_EQ(job_items_path(dir, "leather"), dir / kItemsFile);
  std::filesystem::remove_all(dir);
}

TEST(JobParts, AJobMovesToItsNextPartAndKeepsItsPlaceWhenComputedAgain) {
  JobState state;
  const std::vector<JobPart> parts = {{"lining", "cutter-2", 6}, {"leather", "cutter-1", 2}};
  state.take_parts(parts);
  EXPECT_EQ(state.ticket.material, "lining");
  EXPECT_EQ(state.piece_count, 6);
  EXPECT_EQ(parts_progress(state.parts, state.part, false), "6 pieces of lining now; 2 pieces of leather next");
  state.batch_id = "B1";
  ASSERT_TRUE(state.next_part());
  EXPECT_EQ(state.ticket.material, "leather");
  EXPECT_EQ(state.ticket.cutter, "cutter-1");
  EXPECT_EQ(state.piece_count, 2);
  EXPECT_EQ(state.batch_id, "");
  EXPECT_EQ(parts_progress(state.parts, state.part, false), "6 pieces of lining cut; 2 pieces of leather now");
  EXPECT_EQ(parts_progress(state.parts, state.part, true), "6 pieces of lining cut; 2 pieces of leather cut");
  // Through state.json and back.
  JobState read = job_state_from_json(to_json(state));
  EXPECT_EQ(read.parts, parts);
  EXPECT_EQ(read.part, 1);
  EXPECT_FALSE(read.next_part()) << "the last part";
  // Computed again with the same parts: still at the leather; with others: from the first.
  read.take_parts(parts);
  EXPECT_EQ(read.part, 1);
  EXPECT_EQ(read.ticket.material, "leather");
  read.take_parts({{"lining", "cutter-2", 8}, {"leather", "cutter-1", 2}});
  EXPECT_EQ(read.part, 0);
  EXPECT_EQ(read.piece_count, 8);
  read.take_parts({});
  EXPECT_TRUE(read.parts.empty());
  EXPECT_EQ(parts_progress(read.parts, read.part, false), "");
}

TEST(JobParts, AHideThatTakesSomeOfAJobsPiecesMakesTheRestItsNextPart) {
  // A job of one material (no parts): 3 items of 2, 1 and 2 copies; the hide took 1, 1 and 0.
  JobState state;
  state.ticket.material = "leather";
  state.ticket.cutter = "cutter-1";
  state.piece_count = 5;
  const PartSplit first{{1, 1, 0}, {1, 0, 2}};
  EXPECT_EQ(describe_split(first, "leather", "H-7"), "2 of 5 pieces of leather on hide H-7; 3 wait for the next hide");
  state.parts = split_part(state.parts, state.part, {"leather", "cutter-1", 5, {}}, first);
  state.take_current_part();
  ASSERT_EQ(state.parts.size(), 2u);
  EXPECT_EQ(state.parts[0], (JobPart{"leather", "cutter-1", 2, {1, 1, 0}}));
  EXPECT_EQ(state.parts[1], (JobPart{"leather", "cutter-1", 3, {1, 0, 2}}));
  EXPECT_EQ(state.piece_count, 2);
  EXPECT_EQ(part_copies(state.parts, state.part), (std::vector<int>{1, 1, 0}));
  // The hide is cut; the rest waits for the next hide, which takes some of it again.
  ASSERT_TRUE(state.next_part());
  EXPECT_EQ(state.piece_count, 3);
  state.parts = split_part(state.parts, state.part, {}, {{1, 0, 1}, {0, 0, 1}});
  state.take_current_part();
  ASSERT_EQ(state.parts.size(), 3u);
  EXPECT_EQ(state.parts[1], (JobPart{"leather", "cutter-1", 2, {1, 0, 1}}));
  EXPECT_EQ(state.parts[2], (JobPart{"leather", "cutter-1", 1, {0, 0, 1}}));
  EXPECT_EQ(parts_progress(state.parts, state.part, false),
            "2 pieces of leather cut; 2 pieces of leather now; 1 piece of leather next");
  // A part of a job of several materials splits in place: the parts after it follow the rest.
  const auto mixed = split_part({{"lining", "cutter-2", 4, {}}, {"leather", "cutter-1", 3, {}}, {"felt", "cutter-1", 1, {}}},
                                1, {}, {{2, 0}, {0, 1}});
  ASSERT_EQ(mixed.size(), 4u);
  EXPECT_EQ(mixed[1].pieces, 2);
  EXPECT_EQ(mixed[2], (JobPart{"leather", "cutter-1", 1, {0, 1}}));
  EXPECT_EQ(mixed[3].material, "felt");
  // Through state.json and back, copies and all.
  const JobState read = job_state_from_json(to_json(state));
  EXPECT_EQ(read.parts, state.parts);
  EXPECT_EQ(read.part, 1);
  EXPECT_TRUE(part_copies({}, 0).empty());
}

TEST(JobParts, AJobComputedAgainAfterASplitGoesOnWithWhatNoHideHasCut) {
  const JobPart whole{"leather", "cutter-1", 5, {}};
  const JobPart first{"leather", "cutter-1", 2, {1, 1, 0}}, second{"leather", "cutter-1", 2, {1, 0, 1}},
      last{"leather", "cutter-1", 1, {0, 0, 1}};
  // One material, split over two hides: hide 1 cut, the rest current.
  EXPECT_EQ(resume_parts({first, {"leather", "cutter-1", 3, {1, 0, 2}}}, 1, {}, whole),
            (ResumedParts{{first, {"leather", "cutter-1", 3, {1, 0, 2}}}, 1}));
  // Held before the first hide was cut: nothing cut, the job whole again, of one material (no parts).
  EXPECT_EQ(resume_parts({first, {"leather", "cutter-1", 3, {1, 0, 2}}}, 0, {}, whole), (ResumedParts{{}, 0}));
  // Split three ways, the first hide cut, the second not: what is not cut is one part again.
  EXPECT_EQ(resume_parts({first, second, last}, 1, {}, whole),
            (ResumedParts{{first, {"leather", "cutter-1", 3, {1, 0, 2}}}, 1}));
  EXPECT_EQ(resume_parts({first, second, last}, 2, {}, whole), (ResumedParts{{first, second, last}, 2}));
  EXPECT_EQ(describe_resumed({{first, second, last}, 2}),
            "goes on with part 3 of 3: 1 piece of leather (the parts before it are cut)");
  EXPECT_EQ(describe_resumed({{first, second, last}, 0}), "");
  // Several materials: the lining cut, the leather split and its first hide cut.
  const std::vector<JobPart> computed = {{"lining", "cutter-2", 4, {}}, {"leather", "cutter-1", 3, {}}};
  const JobPart placed{"leather", "cutter-1", 2, {2, 0}}, rest{"leather", "cutter-1", 1, {0, 1}};
  EXPECT_EQ(resume_parts({computed[0], placed, rest}, 2, computed, whole), (ResumedParts{{computed[0], placed, rest}, 2}));
  EXPECT_EQ(resume_parts({computed[0], placed, rest}, 1, computed, whole), (ResumedParts{computed, 1}));
  // The pieces changed (a style edited, another configuration): from the first part, as computed.
  const std::vector<JobPart> changed = {{"lining", "cutter-2", 4, {}}, {"leather", "cutter-1", 4, {}}};
  EXPECT_EQ(resume_parts({computed[0], placed, rest}, 2, changed, whole), (ResumedParts{changed, 0}));
  EXPECT_EQ(resume_parts({first, second}, 1, {}, whole), (ResumedParts{{}, 0})) << "4 of 5 pieces stored";
  EXPECT_EQ(resume_parts({{"felt", "cutter-1", 5, {}}}, 0, computed, whole), (ResumedParts{computed, 0}));
  EXPECT_EQ(resume_parts({first, {"leather", "cutter-1", 3, {1, 2}}}, 1, {}, whole), (ResumedParts{{}, 0}))
      << "copies of another items file";
  EXPECT_EQ(resume_parts({first, last}, 7, {}, whole), (ResumedParts{{}, 0})) << "a part out of range";

  // The spool's job state (state.json) takes the same way: computed again, still at the rest.
  JobState state;
  state.ticket.material = "leather";
  state.ticket.cutter = "cutter-1";
  state.parts = {first, second, last};
  state.part = 1;
  state.piece_count = 5;  // what the computation made
  state.take_parts({});
  EXPECT_EQ(state.parts, (std::vector<JobPart>{first, {"leather", "cutter-1", 3, {1, 0, 2}}}));
  EXPECT_EQ(state.part, 1);
  EXPECT_EQ(state.piece_count, 3);
  EXPECT_EQ(part_copies(state.parts, state.part), (std::vector<int>{1, 0, 2}));
}

TEST(JobParts, APartSplitOverHidesReadsItsCopiesOfTheItemsFile) {
  const auto dir = std::filesystem::temp_directory_path() / ("lastcut-part-items-" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const auto file = dir / "items.json";
  std::ofstream(file) << items_to_json({square_item("vamp", 2), square_item("quarter", 1), square_item("counter", 2)});
  const PartItems all = read_part_items(file, {}, "items.json");
  EXPECT_EQ(all.items.size(), 3u);
  EXPECT_EQ(all.file_index, (std::vector<int>{0, 1, 2}));
  const PartItems part = read_part_items(file, {1, 0, 2}, "items.json");
  ASSERT_EQ(part.items.size(), 2u);
  EXPECT_EQ(part.items[0].label, "vamp");
  EXPECT_EQ(part.items[0].demand, 1);
  EXPECT_EQ(part.items[1].label, "counter");
  EXPECT_EQ(part.file_index, (std::vector<int>{0, 2}));
  EXPECT_EQ(part.file_items, 3) << "the file's count, whatever the part cuts";
  const auto refusal = [&](const std::vector<int>& copies) {
    try {
      read_part_items(file, copies, "items.json of job 7");
    } catch (const EngineError& error) {
      return std::string(error.what());
    }
    return std::string("read");
  };
  EXPECT_EQ(refusal({1, 1}), "items.json of job 7: the part names 2 pieces, the file holds 3");
  EXPECT_EQ(refusal({3, 0, 0}), "items.json of job 7: the part cuts 3 copies of a piece the file has 2 of");
  EXPECT_EQ(refusal({0, 0, 0}), "items.json of job 7: the part has no pieces left to cut");
  std::filesystem::remove_all(dir);
}

TEST(JobParts, ADamagedPartsListKeepsTheEntriesItCanRead) {
  const auto parts = parts_from_json(nlohmann::json::parse(
      R"([{"material":"lining","cutter":"cutter-2","pieces":6}, 7, {"cutter":"x"}, {"material":"leather","cutter":3,"pieces":"two"}])"));
  ASSERT_EQ(parts.size(), 2u);
  EXPECT_EQ(parts[0], (JobPart{"lining", "cutter-2", 6}));
  EXPECT_EQ(parts[1], (JobPart{"leather", "", 0}));
  EXPECT_TRUE(parts_from_json(nlohmann::json::object()).empty());
}

}  // namespace
}  // namespace lastcut::daemon
