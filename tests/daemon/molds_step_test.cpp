// The daemon's molds step (compute_molds) on a symmetric last: the sidecar's side names the halves
// medial/lateral and reaches the piece labels; with no side the pieces carry the neutral names and
// the report the warning. The hole limit it is given is the one the engine applies. A sidecar side
// that contradicts the scan is warned about once.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <nlohmann/json.hpp>

#include "daemon/station/engine_steps.hpp"
#include "daemon_harness.hpp"
#include "engine/lastgen/generate_last.hpp"
#include "engine/mesh/write_mesh.hpp"
#include "engine/nest/nest_json.hpp"

namespace lastcut::daemon {
namespace {

// A generated EU 40 last of 12k triangles, written as the binary STL a scanner would drop.
std::filesystem::path last_scan(const std::filesystem::path& folder, FootSide side, bool symmetric) {
  LastParams params = LastParams::for_eu_size(40, side);
  params.symmetric = symmetric;
  params.target_triangles = 12000;
  const auto scan = folder / (symmetric ? "straight.stl" : "last.stl");
  write_stl_binary(scan, generate_last(params).mesh);
  return scan;
}

std::vector<std::string> labels_of(const std::filesystem::path& job_dir) {
  std::ifstream in(job_dir / kItemsFile);
  std::vector<std::string> labels;
  for (const NestItem& item : items_from_json(nlohmann::json::parse(in), "items.json")) labels.push_back(item.label);
  std::sort(labels.begin(), labels.end());
  return labels;
}

TEST(MoldsStep, TheSidecarsSideNamesASymmetricLastsHalves) {
  const auto folder = testing::scratch_folder("molds-step-side");
  const auto scan = last_scan(folder, FootSide::Right, true);

  JobTicket ticket;
  ticket.order = "77";
  ticket.side = "right";
  const Result<MoldsMade> named = compute_molds(scan, folder / "named", ticket, MoldOptions{}, 30.0, MoldQualityLimits{});
  ASSERT_TRUE(named) << named.error();
  EXPECT_EQ(named->measures["side"], "right");
  EXPECT_EQ(labels_of(folder / "named"), (std::vector<std::string>{"#77 R lat", "#77 R med"}));

  ticket.side = "";
  const Result<MoldsMade> unnamed = compute_molds(scan, folder / "unnamed", ticket, MoldOptions{}, 30.0, MoldQualityLimits{});
  ASSERT_TRUE(unnamed) << unnamed.error();
  EXPECT_TRUE(unnamed->measures["side"].is_null());
  ASSERT_EQ(unnamed->measures["warnings"].size(), 1u);
  EXPECT_TRUE(unnamed->measures["warnings"][0].get<std::string>().starts_with("symmetric last: the side was not named"));
  EXPECT_EQ(labels_of(folder / "unnamed"), (std::vector<std::string>{"#77 side_a", "#77 side_b"}));
}

TEST(MoldsStep, ASidecarSideThatContradictsTheScanIsWarnedOnce) {
  const auto folder = testing::scratch_folder("molds-step-side-mismatch");
  const auto scan = last_scan(folder, FootSide::Left, false);

  JobTicket ticket;
  ticket.order = "78";
  ticket.side = "right";
  const Result<MoldsMade> made = compute_molds(scan, folder / "job", ticket, MoldOptions{}, 30.0, MoldQualityLimits{});
  ASSERT_TRUE(made) << made.error();
  ASSERT_EQ(made->measures["warnings"].size(), 1u) << made->measures["warnings"].dump();
  EXPECT_TRUE(made->measures["warnings"][0].get<std::string>().starts_with("the side named is right but the scan is a left last"));
  EXPECT_FALSE(made->measures.contains("warning"));
}

}  // namespace
}  // namespace lastcut::daemon
