// The sidecar's `split` key reaches the segmentation of the daemon's molds step: a job with
// split = "expert" is cut along the expert's plane (its report says so), one without along the
// automatic plane; both give the two molds.
#include <gtest/gtest.h>

#include "daemon/station/engine_steps.hpp"
#include "daemon_harness.hpp"
#include "engine/lastgen/generate_last.hpp"

namespace lastcut::daemon {
namespace {

TEST(MoldsStep, SidecarSplitRuleReachesTheSegmentation) {
  const auto folder = testing::scratch_folder("molds-split");
  LastParams params = LastParams::for_eu_size(40, FootSide::Right);
  params.target_triangles = 8000;
  const auto scan = folder / "last.stl";
  write_stl_binary(scan, generate_last(params).mesh);
  for (const std::string split : {"", "auto", "expert"}) {
    JobTicket ticket;
    ticket.split = split;
    const auto made = compute_molds(scan, folder / ("job-" + split), ticket, MoldOptions{}, 30.0, MoldQualityLimits{});
    ASSERT_TRUE(made) << made.error();
    EXPECT_EQ(made->piece_count, 2);
    bool expert_noted = false;
    for (const auto& note : made->measures.at("notes"))
      expert_noted = expert_noted || note.get<std::string>().starts_with("expert split: second toe at");
    EXPECT_EQ(expert_noted, split == "expert") << "split = \"" << split << "\"";
  }
}

}  // namespace
}  // namespace lastcut::daemon
