// The pattern-set step of a job (daemon/station/pattern_step.cpp) on real DXF-AAMA files written by the
// engine's writer: the pieces of two configured materials become two parts, each with its own items file,
// the rest goes with the job's material; the pen's lines are the internal lines, and the sew lines too
// unless [jobs] draw_sew_lines is false.
#include <gtest/gtest.h>

#include <unistd.h>

#include "daemon/station/engine_steps.hpp"
#include "engine/nest/nest_json.hpp"
#include "engine/pattern/aama_dxf.hpp"

namespace lastcut::daemon {
namespace {

PatternPiece square_piece(const std::string& name, const std::string& category, int quantity) {
  PatternPiece piece;
  piece.name = name;
  piece.category = category;
  piece.quantity = quantity;
  piece.cut_line_mm = {{0, 0}, {100, 0}, {100, 80}, {0, 80}};
  piece.internal_lines_mm = {{{10, 10}, {90, 10}}};
  piece.sew_lines_mm = {{{5, 5}, {95, 5}}};
  return piece;
}

DaemonConfig pattern_shop(bool draw_sew_lines) {
  DaemonConfig config;
  config.jobs.default_material = "calf";
  config.jobs.default_cutter = "cutter-1";
  config.jobs.draw_sew_lines = draw_sew_lines;
  MaterialConfig roll;
  config.materials["calf"] = roll;
  roll.cutter = "cutter-2";
  config.materials["lining"] = roll;
  return config;
}

class PatternStep : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = std::filesystem::temp_directory_path() / ("lastcut-pattern-step-" + std::to_string(::getpid()));
    std::filesystem::remove_all(dir_);
    std::filesystem::create_directories(dir_ / "job");
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }
  std::filesystem::path dir_;
};

TEST_F(PatternStep, PiecesOfTwoMaterialsMakeTwoPartsAndTheRestGoesWithTheJob) {
  write_aama_dxf(dir_ / "set.dxf", {square_piece("vamp", "calf", 1), square_piece("lining", "lining", 2),
                                    square_piece("toe puff", "felt", 1)});  // felt: not configured
  JobTicket ticket;
  ticket.material = "calf";
  ticket.cutter = "cutter-1";
  ticket.side = "pair";
  const Result<MoldsMade> made = compute_pattern_items(dir_ / "set.dxf", dir_ / "job", ticket, pattern_shop(true));
  ASSERT_TRUE(made) << made.error();
  EXPECT_TRUE(made->hold_reason.empty()) << made->hold_reason;
  ASSERT_EQ(made->parts.size(), 2u);
  EXPECT_EQ(made->parts[0], (JobPart{"calf", "cutter-1", 4}));    // vamp and toe puff, both feet
  EXPECT_EQ(made->parts[1], (JobPart{"lining", "cutter-2", 4}));  // 2 linings a foot, on the lining's cutter
  EXPECT_EQ(made->pieces_to_cut, 8);
  const auto calf = items_from_json(read_json_file(job_items_path(dir_ / "job", "calf")), "calf");
  const auto lining = items_from_json(read_json_file(job_items_path(dir_ / "job", "lining")), "lining");
  ASSERT_EQ(calf.size(), 4u);  // each piece and its twin
  ASSERT_EQ(lining.size(), 2u);
  EXPECT_NE(calf[2].label.find("toe-puff"), std::string::npos) << calf[2].label;  // a label is one word per field
  EXPECT_NE(lining[0].label.find("lining"), std::string::npos);
  EXPECT_FALSE(std::filesystem::exists(dir_ / "job" / kItemsFile));
}

TEST_F(PatternStep, ThePenDrawsTheSewLinesUnlessTheShopSaysNo) {
  write_aama_dxf(dir_ / "set.dxf", {square_piece("vamp", "calf", 1)});
  JobTicket ticket;
  ticket.material = "calf";
  ticket.cutter = "cutter-1";
  for (const bool draw : {true, false}) {
    const Result<MoldsMade> made = compute_pattern_items(dir_ / "set.dxf", dir_ / "job", ticket, pattern_shop(draw));
    ASSERT_TRUE(made) << made.error();
    EXPECT_TRUE(made->parts.empty());
    const auto items = items_from_json(read_json_file(dir_ / "job" / kItemsFile), "items");
    ASSERT_EQ(items.size(), 1u);
    EXPECT_EQ(items[0].drawn_lines_mm.size(), draw ? 2u : 1u) << "draw_sew_lines " << draw;
  }
}

}  // namespace
}  // namespace lastcut::daemon
