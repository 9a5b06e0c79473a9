#include "daemon/job/stages.hpp"

#include <algorithm>
#include <array>
#include <utility>

namespace lastcut::daemon {
namespace {

// The one spelling of each stage on disk (state.json, batch.json, report.json, history).
constexpr std::array<std::pair<JobStage, std::string_view>, 8> kJobStages{{
    {JobStage::Claimed, "claimed"},
    {JobStage::Computed, "computed"},
    {JobStage::Batched, "batched"},
    {JobStage::Sending, "sending"},
    {JobStage::Cut, "cut"},
    {JobStage::Failed, "failed"},
    {JobStage::Held, "held"},
    {JobStage::Skipped, "skipped"},
}};

constexpr std::array<std::pair<BatchStage, std::string_view>, 7> kBatchStages{{
    {BatchStage::Nesting, "nesting"},
    {BatchStage::Queued, "queued"},
    {BatchStage::Sending, "sending"},
    {BatchStage::Cut, "cut"},
    {BatchStage::Held, "held"},
    {BatchStage::Abandoned, "abandoned"},
    {BatchStage::Empty, "empty"},
}};

// Row i names value i, so to_string indexes the table; a table out of order or missing its
// enum's last value fails to compile.
template <typename Table>
constexpr bool rows_in_enum_order(const Table& table) {
  for (std::size_t i = 0; i < table.size(); ++i) {
    if (static_cast<std::size_t>(table[i].first) != i) return false;
  }
  return true;
}
static_assert(rows_in_enum_order(kJobStages) && kJobStages.back().first == JobStage::Skipped);
static_assert(rows_in_enum_order(kBatchStages) && kBatchStages.back().first == BatchStage::Empty);

template <typename Enum, typename Table>
std::optional<Enum> parse(const Table& table, std::string_view text) {
  const auto row = std::find_if(table.begin(), table.end(), [&](const auto& entry) { return entry.second == text; });
  if (row == table.end()) return std::nullopt;
  return row->first;
}

template <typename Enum, std::size_t N>
constexpr std::array<Enum, N> values_of(const std::array<std::pair<Enum, std::string_view>, N>& table) {
  std::array<Enum, N> values{};
  for (std::size_t i = 0; i < N; ++i) values[i] = table[i].first;
  return values;
}

constexpr auto kAllJobStages = values_of(kJobStages);
constexpr auto kAllBatchStages = values_of(kBatchStages);

}  // namespace

bool has_ended(JobStage stage) {
  switch (stage) {
    case JobStage::Claimed:
    case JobStage::Computed:
    case JobStage::Batched:
    case JobStage::Sending: return false;
    case JobStage::Cut:
    case JobStage::Failed:
    case JobStage::Held:
    case JobStage::Skipped: return true;
  }
  return true;
}

bool in_progress(BatchStage stage) {
  switch (stage) {
    case BatchStage::Nesting:
    case BatchStage::Queued:
    case BatchStage::Sending: return true;
    case BatchStage::Cut:
    case BatchStage::Held:
    case BatchStage::Abandoned:
    case BatchStage::Empty: return false;
  }
  return false;
}

std::string_view to_string(JobStage stage) { return kJobStages[static_cast<std::size_t>(stage)].second; }
std::string_view to_string(BatchStage stage) { return kBatchStages[static_cast<std::size_t>(stage)].second; }

std::optional<JobStage> parse_job_stage(std::string_view text) { return parse<JobStage>(kJobStages, text); }
std::optional<BatchStage> parse_batch_stage(std::string_view text) { return parse<BatchStage>(kBatchStages, text); }

std::span<const JobStage> all_job_stages() { return kAllJobStages; }
std::span<const BatchStage> all_batch_stages() { return kAllBatchStages; }

std::string missing_stage_reason(std::string_view file_name) { return std::string(file_name) + " has no stage"; }

std::string unknown_stage_reason(std::string_view file_name, std::string_view text) {
  return std::string(file_name) + " has an unknown stage '" + std::string(text) + "'";
}

}  // namespace lastcut::daemon
