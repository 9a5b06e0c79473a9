#pragma once
// MqttStatus: lastcutd's live status published to an MQTT broker (docs/status-mqtt.md) -
// which cutter does what, how far the cut is, every job's state changes, whether the station is
// online. A StatusObserver of the pipeline; it never blocks the pipeline and never stops it:
//
//   pipeline threads --job_changed / cutter_changed--> (mutex, no I/O) current retained state
//                                                      + bounded queue of job events
//   publisher thread  --mosquitto_publish-->  libmosquitto's network thread --> broker
//
// The broker may be away at start, stop or restart at any time: libmosquitto reconnects with
// backoff (1 s doubling to 10 s); meanwhile the retained state is kept current in memory and job
// events queue up to [status] queue_limit (the oldest dropped first, counted and logged). At each
// (re)connection the station's "online" and every cutter's retained topics are published again,
// once libmosquitto's resent in-flight messages are confirmed (an older value must not land last),
// so subscribers see current state after a broker restart without persistence. The last will
// sets "online" to "false" when the daemon dies without a clean stop; stop() sets it itself.
// Each change of the link (connected, lost, back, refused) is logged once.
#include <condition_variable>
#include <deque>
#include <map>
#include <mutex>
#include <set>
#include <string>
#include <thread>
#include <vector>

#include "daemon/config/daemon_config.hpp"
#include "daemon/job/status_observer.hpp"
#include "daemon/status/status_topics.hpp"
#include "engine/core/status.hpp"

struct mosquitto;

namespace lastcut::daemon {

class MqttStatus final : public StatusObserver {
 public:
  // `config.enabled` must be true; `cutters`: the configured cutter names, announced idle.
  MqttStatus(StatusConfig config, const std::vector<std::string>& cutters);
  ~MqttStatus() override;
  MqttStatus(const MqttStatus&) = delete;
  MqttStatus& operator=(const MqttStatus&) = delete;

  // Starts the client and both threads. Fails only when the client cannot be set up (bad TLS
  // files, out of memory); a broker that cannot be reached yet is retried, not an error.
  Status start();
  // Publishes what is queued and "online" = "false" (waiting at most ~2 s for the broker's
  // acknowledgement), then disconnects. Called after the pipeline has stopped.
  void stop();

  void job_changed(const JobEvent& event) override;
  void cutter_changed(const CutterStatus& status) override;
  void nesting_done(const NestingStatus& status) override;

 private:
  struct Message {
    std::string topic;
    std::string payload;
  };

  static void on_connect(mosquitto* client, void* self, int code);
  static void on_disconnect(mosquitto* client, void* self, int code);
  static void on_publish(mosquitto* client, void* self, int message_id);
  void run();
  // Publishes the dirty retained topics, then the queued events; returns false when a publish
  // failed (the rest stays queued). Called without mutex_ held.
  bool flush();
  void set_retained(const std::string& topic, const std::string& payload);  // mutex_ held
  void say_goodbye();

  const StatusConfig config_;
  const StatusTopics topics_;
  const std::string url_;  // for log lines
  mosquitto* client_ = nullptr;
  std::thread publisher_;

  std::mutex mutex_;
  std::condition_variable wake_;
  bool stopping_ = false;
  bool connected_ = false;
  bool connected_once_ = false;
  bool republish_all_ = false;    // a (re)connection: every retained topic goes out again
  std::string refused_reason_;    // last refusal logged, "" after a connection
  std::map<std::string, std::string> retained_;  // topic -> current payload
  std::set<std::string> dirty_;                   // retained topics changed since last published
  std::deque<Message> events_;
  std::size_t dropped_events_ = 0;                // since the last "back" log line
  std::map<std::string, CutterStatus> cutters_;   // last reported, for change detection
  std::map<std::string, std::size_t> percent_sent_;  // cutter -> last progress percent published
  std::size_t unconfirmed_ = 0;                   // QoS 1 publishes the broker has not confirmed yet
  bool collecting_acks_ = false;                  // stopping: waiting for online = "false" to be confirmed
  std::set<int> acknowledged_ids_;
};

}  // namespace lastcut::daemon
