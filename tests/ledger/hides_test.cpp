// Hides on the ledger (migration 003): a hide entered on a cutter's table takes the computed jobs of
// its material, oldest first, and nothing else; strip batches never take them; the jobs that did not
// fit wait again with their reason; a hide is cut once (its name refused while loaded or used), an
// empty one may be loaded again; a nesting node that vanished leaves the hide loaded for another; a job
// split over hides, held and requeued, is computed again with only the pieces no hide has cut.
#include "tests/ledger/ledger_fixture.hpp"

namespace lastcut::test {
namespace {

class HidesTest : public LedgerTest {
 protected:
  // Three computed leather jobs (1, 2, 4) and one computed calf job (3), all for cutter-1.
  void SetUp() override {
    LedgerTest::SetUp();
    if (HasFatalFailure()) return;
    compute_ = client("compute");
    station_ = client("station");
    ASSERT_TRUE(compute_ && station_);
    ASSERT_TRUE(compute_->register_node({"compute"}, {}, 3).ok());
    ASSERT_TRUE(station_->register_node({"station"}, {"cutter-1"}, 3).ok());
    for (int n : {1, 2, 3, 4}) {
      ASSERT_TRUE(compute_->enqueue(scan(n, "cutter-1", n == 3 ? "calf" : "leather")).ok());
      auto claim = compute_->claim_job(30);
      ASSERT_TRUE(claim.ok() && claim->has_value());
      ASSERT_TRUE(compute_->mark_computed((*claim)->lease).ok());
    }
  }

  ledger::HideEntry hide(const std::string& name) {
    return {name, "leather", "cutter-1", "hides/" + name + "/" + name + ".dxf", 1.25};
  }

  std::unique_ptr<ledger::LedgerClient> compute_, station_;
};

TEST_F(HidesTest, AHideTakesItsMaterialsJobsAndTheMisfitsWaitAgain) {
  // No hide yet: a strip batch takes the calf job only, the leather jobs wait.
  auto strip = compute_->make_batch(group_now(10), 30, {"leather"});
  ASSERT_TRUE(strip.ok() && strip->has_value()) << strip.error();
  EXPECT_EQ((*strip)->material, "calf");
  EXPECT_EQ((*strip)->job_ids.size(), 1u);
  EXPECT_EQ((*strip)->hide_id, 0);
  auto none = compute_->make_hide_batch(daemon::ledger_hide_rule(0), 64, 30);
  ASSERT_TRUE(none.ok());
  EXPECT_FALSE(none->has_value()) << "no hide is loaded";

  auto entered = station_->enter_hide(hide("K-17"));
  ASSERT_TRUE(entered.ok()) << entered.error();
  EXPECT_EQ(query("SELECT state || ':' || cutter || ':' || entered_by FROM hides"), "loaded:cutter-1:station");
  auto made = compute_->make_hide_batch(daemon::ledger_hide_rule(0), 64, 30);
  ASSERT_TRUE(made.ok() && made->has_value()) << made.error();
  const ledger::BatchClaim& claim = **made;
  EXPECT_EQ(claim.hide_id, *entered);
  EXPECT_EQ(claim.hide_name, "K-17");
  EXPECT_EQ(claim.hide_file, "hides/K-17/K-17.dxf");
  EXPECT_EQ(claim.cutter, "cutter-1");
  EXPECT_EQ(claim.material, "leather");
  ASSERT_EQ(claim.job_ids.size(), 3u);
  EXPECT_EQ(claim.job_names, (std::vector<std::string>{"scan-1.stl", "scan-2.stl", "scan-4.stl"}));
  EXPECT_EQ(query("SELECT state FROM hides"), "nesting");
  EXPECT_EQ(station_->enter_hide(hide("K-17")).error(),
            "hide K-17 is already in the ledger (nesting, on cutter cutter-1): a hide is cut once; give a new hide "
            "its own ID");

  ledger::NestedBatch nested;
  nested.cut_file = "batches/" + std::to_string(claim.batch_id) + "/cut.plt";
  nested.pieces = 4;
  nested.utilisation = 0.61;
  nested.waiting = {{claim.job_ids[2], "waiting for a hide of leather: did not fit on hide K-17"}};
  ASSERT_TRUE(compute_->mark_nested(claim.lease, nested).ok());
  EXPECT_EQ(query("SELECT state FROM hides"), "used");
  EXPECT_EQ(query("SELECT state || ':' || pieces || ':' || utilisation FROM batches WHERE id = " +
                  std::to_string(claim.batch_id)),
            "queued:4:0.61");
  EXPECT_EQ(query("SELECT state || ':' || coalesce(batch_id::text, '-') || ':' || reason FROM jobs WHERE id = " +
                  std::to_string(claim.job_ids[2])),
            "computed:-:waiting for a hide of leather: did not fit on hide K-17");
  EXPECT_EQ(query("SELECT count(*) FROM jobs WHERE state = 'batched' AND batch_id = " + std::to_string(claim.batch_id)),
            "2");
  // The waiting job is not put on a strip, and the used hide is not nested again.
  auto after = compute_->make_batch(group_now(10), 30, {"leather"});
  ASSERT_TRUE(after.ok());
  EXPECT_FALSE(after->has_value());
  auto again = compute_->make_hide_batch(daemon::ledger_hide_rule(0), 64, 30);
  ASSERT_TRUE(again.ok());
  EXPECT_FALSE(again->has_value());

  // The station cuts the hide batch like any batch.
  auto cut = station_->claim_batch(30, "cutter-1");
  ASSERT_TRUE(cut.ok() && cut->has_value());
  EXPECT_EQ((*cut)->hide_name, "K-17");
  EXPECT_EQ((*cut)->cut_file, nested.cut_file);
}

TEST_F(HidesTest, ASplitJobHeldAndRequeuedGoesOnWithThePiecesNotCut) {
  // Job 5: five pieces of leather (items of 2, 1 and 2 copies) that may be split over hides.
  ASSERT_TRUE(compute_->enqueue(scan(5, "cutter-1", "leather")).ok());
  auto computing = compute_->claim_job(30);
  ASSERT_TRUE(computing.ok() && computing->has_value());
  const long long job = (*computing)->job_id;
  const std::string row = "FROM jobs WHERE id = " + std::to_string(job);
  ASSERT_TRUE(compute_->mark_computed((*computing)->lease, 5).ok());

  // Hide K-1 takes 1, 1 and 0 copies of its items and is cut; the other jobs wait.
  ASSERT_TRUE(station_->enter_hide(hide("K-1")).ok());
  auto first = compute_->make_hide_batch(daemon::ledger_hide_rule(0), 64, 30);
  ASSERT_TRUE(first.ok() && first->has_value()) << first.error();
  ledger::NestedBatch nested;
  nested.cut_file = "batches/" + std::to_string((*first)->batch_id) + "/cut.plt";
  nested.pieces = 2;
  const daemon::PartSplit split{{1, 1, 0}, {1, 0, 2}};
  nested.split = {{job, daemon::split_part({}, 0, {"leather", "cutter-1", 5, {}}, split), "2 of 5 on K-1"}};
  for (long long other : (*first)->job_ids) {
    if (other != job) nested.waiting.emplace_back(other, "waiting for a hide of leather");
  }
  ASSERT_TRUE(compute_->mark_nested((*first)->lease, nested).ok());
  auto cutting = station_->claim_batch(30, "cutter-1");
  ASSERT_TRUE(cutting.ok() && cutting->has_value());
  ASSERT_TRUE(station_->mark_sending((*cutting)->lease).ok());
  ASSERT_TRUE(station_->mark_cut((*cutting)->lease).ok());
  EXPECT_EQ(query("SELECT state || ' ' || part || ' ' || pieces " + row), "computed 1 3");

  // Hide K-2's batch cannot be made: the job is held, and an operator requeues it.
  ASSERT_TRUE(station_->enter_hide(hide("K-2")).ok());
  auto second = compute_->make_hide_batch(daemon::ledger_hide_rule(0), 64, 30);
  ASSERT_TRUE(second.ok() && second->has_value()) << second.error();
  ledger::NestedBatch unmade;
  for (long long id : (*second)->job_ids) unmade.held.emplace_back(id, "the batch could not be made: no machine profile");
  unmade.reason = "no machine profile";
  ASSERT_TRUE(compute_->mark_nested((*second)->lease, unmade).ok());
  EXPECT_EQ(query("SELECT state " + row), "held");
  ASSERT_TRUE(compute_->requeue_held(job).ok());

  // Computed again from its scan (5 pieces, one material): it goes on with the 3 pieces K-1 did not
  // take, not with all 5 (K-1's two would be cut twice).
  auto again = compute_->claim_job(30);
  ASSERT_TRUE(again.ok() && again->has_value());
  ASSERT_EQ((*again)->job_id, job);
  ASSERT_TRUE(compute_->mark_computed((*again)->lease, 5).ok());
  EXPECT_EQ(query("SELECT state || ' ' || part || ' ' || pieces || ' ' || material " + row), "computed 1 3 leather");
  EXPECT_EQ(daemon::parts_from_json(nlohmann::json::parse(query("SELECT parts::text " + row))),
            (std::vector<daemon::JobPart>{{"leather", "cutter-1", 2, {1, 1, 0}}, {"leather", "cutter-1", 3, {1, 0, 2}}}));
  EXPECT_EQ(query("SELECT detail FROM job_events WHERE event = 'computed' AND job_id = " + std::to_string(job) +
                  " ORDER BY id DESC LIMIT 1"),
            "goes on with part 2 of 2: 3 pieces of leather (the parts before it are cut)");
}

TEST_F(HidesTest, AnEmptyHideMayBeLoadedAgainAVanishedNestingLeavesItLoaded) {
  ASSERT_TRUE(station_->enter_hide(hide("S-1")).ok());
  auto made = compute_->make_hide_batch(daemon::ledger_hide_rule(0), 64, 30);
  ASSERT_TRUE(made.ok() && made->has_value());
  ledger::NestedBatch nothing;
  for (long long id : (*made)->job_ids) nothing.waiting.emplace_back(id, "waiting for a hide of leather: too small");
  nothing.reason = "no waiting job fitted on hide S-1";
  ASSERT_TRUE(compute_->mark_nested((*made)->lease, nothing).ok());
  EXPECT_EQ(query("SELECT state || ':' || reason FROM hides"), "empty:no waiting job fitted on hide S-1");
  EXPECT_EQ(query("SELECT state FROM batches WHERE id = " + std::to_string((*made)->batch_id)), "dissolved");
  EXPECT_EQ(query("SELECT count(*) FROM jobs WHERE state = 'computed' AND material = 'leather'"), "3");

  // Loaded again (a larger piece of the same hide ID after trimming, say): nested again, by a node
  // whose lease then runs out: the sweep dissolves its batch and the hide lies there, loaded.
  ASSERT_TRUE(station_->enter_hide(hide("S-1")).ok());
  auto lost = compute_->make_hide_batch(daemon::ledger_hide_rule(0), 64, 0.3);
  ASSERT_TRUE(lost.ok() && lost->has_value());
  auto swept = sweep_after_expiry(*station_, 0.3);
  ASSERT_TRUE(swept.ok()) << swept.error();
  EXPECT_EQ(swept->batches_dissolved, std::vector<long long>{(*lost)->batch_id});
  EXPECT_EQ(query("SELECT state FROM hides"), "loaded");
  EXPECT_EQ(query("SELECT count(*) FROM jobs WHERE state = 'computed' AND batch_id IS NULL AND material = 'leather'"),
            "3");
  auto retaken = station_->make_hide_batch(daemon::ledger_hide_rule(0), 64, 30);
  ASSERT_TRUE(retaken.ok() && retaken->has_value());
  EXPECT_EQ((*retaken)->job_ids.size(), 3u);
  EXPECT_EQ(compute_->mark_nested((*lost)->lease, {}).error().rfind("lease lost", 0), 0u)
      << "the node back from its pause acts on nothing";
}

TEST_F(HidesTest, AHideWaitsWhileJobsOfItsMaterialAreStillComputing) {
  ASSERT_TRUE(compute_->enqueue(scan(5, "cutter-1", "leather")).ok());  // ready, not computed yet
  ASSERT_TRUE(station_->enter_hide(hide("W-1")).ok());
  auto early = compute_->make_hide_batch(daemon::ledger_hide_rule(30), 64, 30);
  ASSERT_TRUE(early.ok());
  EXPECT_FALSE(early->has_value()) << "job 5 is still on its way and the hide has not waited 30 s";
  auto late = compute_->make_hide_batch(daemon::ledger_hide_rule(0), 64, 30);  // a window of 0 s: it has waited long enough
  ASSERT_TRUE(late.ok() && late->has_value());
  EXPECT_EQ((*late)->job_ids.size(), 3u);
}

}  // namespace
}  // namespace lastcut::test
