#include "daemon/status/mqtt_status.hpp"

#include <mosquitto.h>

#include <chrono>

#include <spdlog/spdlog.h>

#include "daemon/status/mqtt_client.hpp"

namespace lastcut::daemon {
namespace {

constexpr int kQos = 1;  // at least once: a retained state or an event is not lost on a dropped packet
// How long a reconnection waits for libmosquitto's resent messages to be confirmed (see run()).
constexpr std::chrono::seconds kResendWait(5);

}  // namespace

MqttStatus::MqttStatus(StatusConfig config, const std::vector<std::string>& cutters)
    : config_(std::move(config)), topics_(config_.topic_prefix), url_(config_.mqtt_url) {
  retained_[topics_.station_online(config_.station)] = "true";
  const std::string now = utc_now_iso();
  for (const std::string& name : cutters) {
    const CutterStatus idle{name};
    cutters_[name] = idle;
    retained_[topics_.cutter_state(name)] = cutter_state_payload(idle, config_.station, now).dump();
    retained_[topics_.cutter_batch(name)] = "";
    retained_[topics_.cutter_progress(name)] = cutter_progress_payload(idle, now).dump();
  }
  for (const auto& [topic, payload] : retained_) dirty_.insert(topic);
}

MqttStatus::~MqttStatus() { stop(); }

Status MqttStatus::start() {
  Result<mosquitto*> client = new_mqtt_client(config_, "lastcutd-" + config_.station, this);
  if (!client) return client.status();
  client_ = *client;
  const std::string will = "false";
  mosquitto_will_set(client_, topics_.station_online(config_.station).c_str(), static_cast<int>(will.size()),
                     will.data(), kQos, true);
  mosquitto_connect_callback_set(client_, &MqttStatus::on_connect);
  mosquitto_disconnect_callback_set(client_, &MqttStatus::on_disconnect);
  mosquitto_publish_callback_set(client_, &MqttStatus::on_publish);
  mosquitto_reconnect_delay_set(client_, 1, 10, true);
  if (const int started = mosquitto_loop_start(client_); started != MOSQ_ERR_SUCCESS) {
    mosquitto_destroy(client_);
    client_ = nullptr;
    return Status::failure(std::string("status: the MQTT network thread did not start: ") + mosquitto_strerror(started));
  }
  // Refused or unreachable now: the network thread keeps trying with backoff.
  if (const int connecting = mosquitto_connect_async(client_, config_.host.c_str(), config_.port, config_.keepalive_s);
      connecting != MOSQ_ERR_SUCCESS) {
    std::lock_guard lock(mutex_);
    refused_reason_ = mqtt_error_text(connecting);
    spdlog::warn("status: MQTT broker {} not reachable ({}); retrying, the daemon works on meanwhile", url_,
                 refused_reason_);
  }
  publisher_ = std::thread([this] { run(); });
  spdlog::info("status: publishing as station {} under {}/ to {}", config_.station, config_.topic_prefix, url_);
  return Status::success();
}

void MqttStatus::stop() {
  if (!client_) return;
  {
    std::lock_guard lock(mutex_);
    stopping_ = true;
  }
  wake_.notify_all();
  if (publisher_.joinable()) publisher_.join();
  say_goodbye();
  mosquitto_disconnect(client_);
  mosquitto_loop_stop(client_, false);
  mosquitto_destroy(client_);
  client_ = nullptr;
}

void MqttStatus::say_goodbye() {
  std::unique_lock lock(mutex_);
  if (!connected_) return;  // the broker already has, or will have, our last will
  // Acknowledgements are collected from here on: the broker may answer before the id is known.
  collecting_acks_ = true;
  lock.unlock();
  flush();
  const std::string offline = "false";
  int id = -1;
  const int sent = mosquitto_publish(client_, &id, topics_.station_online(config_.station).c_str(),
                                     static_cast<int>(offline.size()), offline.data(), kQos, true);
  lock.lock();
  const auto acknowledged = [&] { return acknowledged_ids_.count(id) > 0; };
  if (sent != MOSQ_ERR_SUCCESS ||
      !wake_.wait_for(lock, std::chrono::seconds(2), [&] { return acknowledged() || !connected_; }) || !acknowledged()) {
    spdlog::warn("status: the broker did not confirm station {} offline; its last will says so", config_.station);
  }
}

void MqttStatus::on_connect(mosquitto*, void* self, int code) {
  auto& status = *static_cast<MqttStatus*>(self);
  std::lock_guard lock(status.mutex_);
  if (code != 0) {
    const std::string reason = mosquitto_connack_string(code);
    if (reason != status.refused_reason_) {
      spdlog::error("status: MQTT broker {} refused the connection: {}; retrying", status.url_, reason);
      status.refused_reason_ = reason;
    }
    return;
  }
  status.connected_ = true;
  status.republish_all_ = true;
  status.refused_reason_.clear();
  if (!status.connected_once_) {
    spdlog::info("status: connected to MQTT broker {}", status.url_);
  } else if (status.dropped_events_ > 0) {
    spdlog::info("status: MQTT broker {} back; status published again, {} job event(s) dropped while it was away",
                 status.url_, status.dropped_events_);
  } else {
    spdlog::info("status: MQTT broker {} back; status published again, no job event lost", status.url_);
  }
  status.connected_once_ = true;
  status.dropped_events_ = 0;
  status.wake_.notify_all();
}

void MqttStatus::on_disconnect(mosquitto*, void* self, int code) {
  auto& status = *static_cast<MqttStatus*>(self);
  std::lock_guard lock(status.mutex_);
  const bool was_connected = status.connected_;
  status.connected_ = false;
  if (was_connected && !status.stopping_) {
    spdlog::warn("status: MQTT broker {} lost ({}); job events queue (at most {}), retrying", status.url_,
                 mqtt_error_text(code), status.config_.queue_limit);
  } else if (!status.connected_once_ && !status.stopping_) {
    // Never reached since the start: said once, retried by libmosquitto's thread.
    const std::string reason = mqtt_error_text(code);
    if (status.refused_reason_.empty()) {
      spdlog::warn("status: MQTT broker {} not reachable ({}); retrying, the daemon works on meanwhile", status.url_,
                   reason);
      status.refused_reason_ = reason;
    }
  }
  status.wake_.notify_all();
}

void MqttStatus::on_publish(mosquitto*, void* self, int message_id) {
  auto& status = *static_cast<MqttStatus*>(self);
  std::lock_guard lock(status.mutex_);
  if (status.unconfirmed_ > 0) --status.unconfirmed_;
  if (status.unconfirmed_ == 0) status.wake_.notify_all();
  if (status.collecting_acks_) {
    status.acknowledged_ids_.insert(message_id);
    status.wake_.notify_all();
  }
}

void MqttStatus::job_changed(const JobEvent& event) {
  Message message{topics_.job_event(event.job_id), job_event_payload(event, config_.station).dump()};
  {
    std::lock_guard lock(mutex_);
    if (events_.size() >= static_cast<std::size_t>(config_.queue_limit)) {
      events_.pop_front();
      ++dropped_events_;
    }
    events_.push_back(std::move(message));
  }
  wake_.notify_all();
}

void MqttStatus::nesting_done(const NestingStatus& status) {
  const std::string payload = nesting_payload(status, config_.station, utc_now_iso()).dump();
  {
    std::lock_guard lock(mutex_);
    set_retained(topics_.material_nesting(status.material), payload);
    if (!status.hide.empty()) set_retained(topics_.hide_nesting(status.hide), payload);
  }
  wake_.notify_all();
}

void MqttStatus::cutter_changed(const CutterStatus& status) {
  const std::string now = utc_now_iso();
  {
    std::lock_guard lock(mutex_);
    CutterStatus& last = cutters_[status.cutter];
    const bool changed = last.state != status.state || last.batch != status.batch || last.reason != status.reason;
    if (changed) {
      set_retained(topics_.cutter_state(status.cutter), cutter_state_payload(status, config_.station, now).dump());
      set_retained(topics_.cutter_batch(status.cutter), status.batch);
    }
    // Progress belongs to the batch being sent and stays at its last value afterwards; one
    // message per whole percent keeps a long cut at about 100 messages.
    if (status.state == "sending") {
      const nlohmann::json progress = cutter_progress_payload(status, now);
      const auto percent = progress["percent"].get<std::size_t>();
      auto sent = percent_sent_.find(status.cutter);
      if (changed || sent == percent_sent_.end() || sent->second != percent) {
        set_retained(topics_.cutter_progress(status.cutter), progress.dump());
        percent_sent_[status.cutter] = percent;
      }
    }
    last = status;
  }
  wake_.notify_all();
}

void MqttStatus::set_retained(const std::string& topic, const std::string& payload) {
  retained_[topic] = payload;
  dirty_.insert(topic);
}

void MqttStatus::run() {
  std::unique_lock lock(mutex_);
  for (;;) {
    wake_.wait(lock, [this] {
      return stopping_ || (connected_ && (republish_all_ || !dirty_.empty() || !events_.empty()));
    });
    if (stopping_) return;
    if (republish_all_) {
      // After a reconnection libmosquitto resends the QoS 1 messages that were in flight when the link
      // dropped. A retained value resent after the current one would win at the broker (seen: the idle
      // progress of the start over the finished batch's), so the current state goes out again only
      // once those are confirmed; what is not confirmed within kResendWait is taken as lost.
      wake_.wait_for(lock, kResendWait, [this] { return stopping_ || !connected_ || unconfirmed_ == 0; });
      if (stopping_) return;
      if (!connected_) continue;
      unconfirmed_ = 0;
      for (const auto& [topic, payload] : retained_) dirty_.insert(topic);
      republish_all_ = false;
    }
    lock.unlock();
    const bool flushed = flush();
    lock.lock();
    // A publish failed although the link looked up: the loss is not noticed yet; try again soon.
    if (!flushed) wake_.wait_for(lock, std::chrono::seconds(1), [this] { return stopping_; });
  }
}

bool MqttStatus::flush() {
  std::vector<Message> retained;
  std::deque<Message> events;
  {
    std::lock_guard lock(mutex_);
    for (const std::string& topic : dirty_) retained.push_back({topic, retained_[topic]});
    dirty_.clear();
    events.swap(events_);
  }
  const auto publish = [this](const Message& message, bool retain) {
    {
      std::lock_guard lock(mutex_);
      ++unconfirmed_;  // before the call: the broker may confirm before mosquitto_publish returns
    }
    const bool sent = mosquitto_publish(client_, nullptr, message.topic.c_str(), static_cast<int>(message.payload.size()),
                                        message.payload.data(), kQos, retain) == MOSQ_ERR_SUCCESS;
    if (!sent) {
      std::lock_guard lock(mutex_);
      if (unconfirmed_ > 0) --unconfirmed_;
    }
    return sent;
  };
  // What was not sent goes back in front of anything queued meanwhile, in order; the limit holds.
  const auto put_back = [this, &events] {
    std::lock_guard lock(mutex_);
    events.insert(events.end(), events_.begin(), events_.end());
    events_.swap(events);
    while (events_.size() > static_cast<std::size_t>(config_.queue_limit)) {
      events_.pop_front();
      ++dropped_events_;
    }
  };
  for (std::size_t i = 0; i < retained.size(); ++i) {
    if (!publish(retained[i], true)) {
      {
        std::lock_guard lock(mutex_);
        for (std::size_t j = i; j < retained.size(); ++j) dirty_.insert(retained[j].topic);
      }
      put_back();
      return false;
    }
  }
  while (!events.empty()) {
    if (!publish(events.front(), false)) {
      put_back();
      return false;
    }
    events.pop_front();
  }
  return true;
}

}  // namespace lastcut::daemon
