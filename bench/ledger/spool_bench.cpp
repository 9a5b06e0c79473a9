// bench_spool: the file spool (daemon/spool/spool.hpp) doing per scan what bench_ledger does on the
// PostgreSQL ledger, on one node: a scan is dropped in the watch folder (written and fsynced), claimed
// into work/ID (state.json), marked computed, grouped five at a time into a batch (batch.json, each
// job's state batched), the batch and its jobs marked sending, then cut, the jobs moved to done/.
// Every state write is the daemon's own (write_file_durably / move_durably: fsync of file and
// folders). Nothing is computed or cut: this measures the spool alone, in a temporary folder on the
// file system of $TMPDIR (where bench_ledger's PostgreSQL server keeps its data too). Prints claims
// per second, the time from a scan's drop to its claim (p50/p99) and the spool's bytes per job.
//
//   bench_spool [--scans 200]
#include <sys/stat.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "daemon/spool/spool.hpp"
#include "engine/core/durable_file.hpp"

namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;
using lastcut::Status;
using lastcut::daemon::BatchStage;
using lastcut::daemon::BatchState;
using lastcut::daemon::JobFolder;
using lastcut::daemon::JobStage;
using lastcut::daemon::JobState;
using lastcut::daemon::Spool;

constexpr int kBatchJobs = 5;  // bench_ledger's make_batch(5)

struct DiskUse {
  long long files = 0, folders = 0;
  long long file_bytes = 0;       // the files' lengths
  long long allocated_bytes = 0;  // blocks the file system gave files and folders
};

DiskUse disk_use(const fs::path& root, const std::string& skip_name) {
  DiskUse use;
  for (const auto& entry : fs::recursive_directory_iterator(root)) {
    if (entry.path().filename() == skip_name) continue;
    struct stat info {};
    if (::lstat(entry.path().c_str(), &info) != 0) continue;
    use.allocated_bytes += static_cast<long long>(info.st_blocks) * 512;
    if (S_ISDIR(info.st_mode)) {
      ++use.folders;
    } else {
      ++use.files;
      use.file_bytes += info.st_size;
    }
  }
  return use;
}

double percentile(std::vector<double> values, double p) {
  if (values.empty()) return 0;
  std::sort(values.begin(), values.end());
  return values[std::min(values.size() - 1, static_cast<std::size_t>(p * (values.size() - 1) + 0.5))];
}

// Cuts the batch of `jobs` (all computed): batched, sending, cut, each step batch.json and every job's
// state.json, the jobs then moved to done/ as lastcutd's cut step does.
Status cut_batch(Spool& spool, std::vector<JobState>& jobs) {
  BatchState batch;
  batch.id = spool.new_batch_id();
  batch.material = "calf";
  batch.cutter = "cutter-1";
  batch.created_at = lastcut::daemon::utc_now_iso();
  for (const JobState& job : jobs) batch.job_ids.push_back(job.id);
  std::error_code error;
  fs::create_directory(spool.batch_dir(batch.id), error);
  if (error) return Status::failure("cannot create " + spool.batch_dir(batch.id).string() + ": " + error.message());
  const auto step = [&](BatchStage batch_stage, JobStage job_stage) -> Status {
    batch.stage = batch_stage;
    batch.updated_at = lastcut::daemon::utc_now_iso();
    if (Status written = spool.write_batch(batch); !written) return written;
    for (JobState& job : jobs) {
      job.batch_id = batch.id;
      job.advance(job_stage);
      if (Status written = spool.write_state(JobFolder::Work, job); !written) return written;
    }
    return Status::success();
  };
  if (Status s = step(BatchStage::Queued, JobStage::Batched); !s) return s;
  if (Status s = step(BatchStage::Sending, JobStage::Sending); !s) return s;
  batch.stage = BatchStage::Cut;
  if (Status written = spool.write_batch(batch); !written) return written;
  for (JobState& job : jobs) {
    job.advance(JobStage::Cut);
    if (Status moved = spool.move_job(JobFolder::Work, JobFolder::Done, job); !moved) return moved;
  }
  jobs.clear();
  return Status::success();
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"bench_spool: the file spool under M scans on one node (compare bench_ledger)"};
  int scans = 200;
  app.add_option("--scans", scans, "scans dropped")->check(CLI::Range(1, 100000));
  CLI11_PARSE(app, argc, argv);

  std::string pattern = (fs::temp_directory_path() / "lastcut-spool-bench-XXXXXX").string();
  if (!::mkdtemp(pattern.data())) {
    std::fprintf(stderr, "bench_spool: cannot make a temporary folder\n");
    return 1;
  }
  const fs::path folder = pattern, incoming = folder / "incoming";
  fs::create_directories(incoming);
  Spool spool(folder / "spool");
  const auto give_up = [&folder](const std::string& why) {
    std::fprintf(stderr, "bench_spool: %s\n", why.c_str());
    std::error_code ec;
    fs::remove_all(folder, ec);
    return 1;
  };
  if (Status ready = spool.prepare(); !ready) return give_up(ready.error());

  const std::string scan_name = "scan.stl";  // the scan itself: not the spool's bookkeeping
  std::vector<double> drop_to_claim_ms;
  std::vector<JobState> computed;
  int claims = 0;
  const auto start = Clock::now();
  for (int s = 0; s < scans; ++s) {
    const fs::path scan = incoming / scan_name;
    if (Status dropped = lastcut::write_file_durably(scan, "solid scan " + std::to_string(s) + "\nendsolid\n"); !dropped) {
      return give_up(dropped.error());
    }
    const auto dropped_at = Clock::now();
    JobState state;
    state.sha256 = std::to_string(s);
    state.ticket.material = "calf";
    state.ticket.cutter = "cutter-1";
    auto id = spool.claim(scan, {}, state);
    if (!id) return give_up(id.error());
    drop_to_claim_ms.push_back(std::chrono::duration<double, std::milli>(Clock::now() - dropped_at).count());
    ++claims;
    std::optional<JobState> job = spool.read_state(JobFolder::Work, *id);
    if (!job) return give_up("cannot read back the state of job " + *id);
    job->attempts = 1;
    job->advance(JobStage::Computed);
    if (Status written = spool.write_state(JobFolder::Work, *job); !written) return give_up(written.error());
    computed.push_back(*job);
    if (static_cast<int>(computed.size()) == kBatchJobs || s + 1 == scans) {
      if (Status cut = cut_batch(spool, computed); !cut) return give_up(cut.error());
    }
  }
  const double wall_s = std::chrono::duration<double>(Clock::now() - start).count();

  const auto done = static_cast<long long>(spool.list(JobFolder::Done).size());
  const DiskUse use = disk_use(spool.root(), scan_name);
  std::printf("scans %d on one node, jobs done %lld of %d, batches %zu, wall %.2f s\n", scans, done, scans,
              spool.list_batches().size(), wall_s);
  std::printf("claims per second: %.0f (each scan: drop, claim, computed, batched, sending, cut, moved to done/)\n",
              claims / wall_s);
  std::printf("drop to claim: p50 %.1f ms, p99 %.1f ms\n", percentile(drop_to_claim_ms, 0.5),
              percentile(drop_to_claim_ms, 0.99));
  std::printf("spool per job (scans not counted): %.1f files, %.1f folders, %.0f bytes in files, %.0f bytes allocated "
              "(files and folders, fsync on)\n",
              double(use.files) / scans, double(use.folders) / scans, double(use.file_bytes) / scans,
              double(use.allocated_bytes) / scans);
  std::error_code ec;
  fs::remove_all(folder, ec);
  return done == scans ? 0 : 2;
}
