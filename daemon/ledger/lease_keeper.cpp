// The lease heartbeat thread (see lease_keeper.hpp).
#include "daemon/ledger/lease_keeper.hpp"

#include <algorithm>
#include <chrono>
#include <vector>

#include "daemon/ledger/ledger_connection.hpp"

namespace lastcut::ledger {
namespace {

std::pair<int, long long> key(const Lease& lease) { return {static_cast<int>(lease.kind), lease.object_id}; }

}  // namespace

LeaseKeeper::LeaseKeeper(std::string url, std::string node, double lease_s, double heartbeat_s, Log log)
    : url_(std::move(url)), node_(std::move(node)), lease_s_(lease_s), heartbeat_s_(heartbeat_s), log_(std::move(log)) {
  thread_ = std::thread([this] { run(); });
}

LeaseKeeper::~LeaseKeeper() {
  {
    std::lock_guard lock(mutex_);
    stopping_ = true;
  }
  wake_.notify_all();
  thread_.join();
}

void LeaseKeeper::keep(const Lease& lease) {
  std::lock_guard lock(mutex_);
  kept_[key(lease)] = lease;
  lost_.erase(key(lease));
}

void LeaseKeeper::drop(const Lease& lease) {
  std::lock_guard lock(mutex_);
  kept_.erase(key(lease));
  lost_.erase(key(lease));
}

bool LeaseKeeper::lost(const Lease& lease) const {
  std::lock_guard lock(mutex_);
  return lost_.count(key(lease)) > 0;
}

double LeaseKeeper::retry_s() const { return std::min(1.0, heartbeat_s_); }

void LeaseKeeper::run() {
  std::unique_ptr<LedgerClient> client;
  std::unique_lock lock(mutex_);
  while (!stopping_) {
    lock.unlock();
    beat(client);
    lock.lock();
    const double wait_s = reachable_ ? heartbeat_s_ : retry_s();
    wake_.wait_for(lock, std::chrono::duration<double>(wait_s), [this] { return stopping_; });
  }
}

void LeaseKeeper::beat(std::unique_ptr<LedgerClient>& client) {
  const auto went_unreachable = [&](const std::string& why) {
    if (reachable_.exchange(false)) log_("leases not renewed, retrying: " + why);
  };
  if (!client) {
    auto connected = LedgerClient::connect(url_, node_);
    if (!connected) return went_unreachable(connected.error());
    client = std::move(*connected);
  }
  std::vector<Lease> leases;
  {
    std::lock_guard lock(mutex_);
    for (const auto& [k, lease] : kept_) leases.push_back(lease);
  }
  if (Status beat = client->heartbeat(); !beat) return went_unreachable(beat.error());
  for (const Lease& lease : leases) {
    Status renewed = client->renew(lease, lease_s_);
    if (renewed) continue;
    // Only the ledger's own refusal loses a lease; any other failure is retried.
    if (renewed.error().rfind("lease lost", 0) != 0) return went_unreachable(renewed.error());
    std::lock_guard lock(mutex_);
    if (kept_.erase(key(lease))) {
      lost_.insert(key(lease));
      log_(renewed.error());
    }
  }
  if (!reachable_.exchange(true)) log_("ledger reachable again, leases renewed");
}

}  // namespace lastcut::ledger
