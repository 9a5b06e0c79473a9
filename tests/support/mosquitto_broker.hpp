#pragma once
// A real mosquitto broker for tests, and a small subscriber that records what it hears.
//
// MosquittoBroker: /usr/sbin/mosquitto (Debian package mosquitto, scripts/setup.sh) on
// 127.0.0.1 and a free port, configured by a file in the test's folder, without persistence
// (a restart forgets retained messages, the hard case for "status resumes"). start() returns
// why it could not start - a missing install step makes the test fail with that line. The
// port stays the same across stop()/start(); the destructor kills the broker.
//
// MqttSubscriber: a libmosquitto client with its own network thread, subscribed to a filter
// (again after every reconnection), keeping every message in arrival order with its retain flag.
#include <filesystem>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "tests/support/child_process.hpp"

struct mosquitto;
struct mosquitto_message;

namespace lastcut::test {

class MosquittoBroker {
 public:
  // `listener_lines`: more settings of the listener (TLS files, password_file, allow_anonymous false).
  explicit MosquittoBroker(std::filesystem::path folder, const std::string& listener_lines = "");
  ~MosquittoBroker();
  MosquittoBroker(const MosquittoBroker&) = delete;
  MosquittoBroker& operator=(const MosquittoBroker&) = delete;

  // Starts the broker and waits (10 s at most) until it accepts connections; "" on success,
  // else the reason and the broker's log.
  std::string start();
  // SIGTERM, then wait for the exit (SIGKILL after 5 s).
  void stop();
  bool running();
  int port() const { return port_; }
  std::string url() const { return "mqtt://127.0.0.1:" + std::to_string(port_); }
  std::filesystem::path log_file() const { return folder_ / "mosquitto.log"; }

 private:
  std::filesystem::path folder_;
  int port_ = 0;
  std::unique_ptr<ChildProcess> process_;
};

struct MqttMessage {
  std::string topic;
  std::string payload;
  bool retained = false;
};

class MqttSubscriber {
 public:
  MqttSubscriber(int port, std::string filter = "#");
  ~MqttSubscriber();
  MqttSubscriber(const MqttSubscriber&) = delete;
  MqttSubscriber& operator=(const MqttSubscriber&) = delete;

  // Waits until the subscription is confirmed (after a connection); false after timeout_s.
  bool wait_subscribed(double timeout_s);
  std::vector<MqttMessage> messages() const;
  std::vector<MqttMessage> on(const std::string& topic) const;
  std::optional<MqttMessage> last(const std::string& topic) const;
  // Polls `done` every 50 ms until true or timeout_s; returns its last value.
  bool wait_until(const std::function<bool()>& done, double timeout_s) const;

 private:
  static void on_connect(mosquitto* client, void* self, int code);
  static void on_subscribe(mosquitto* client, void* self, int mid, int count, const int* granted);
  static void on_message(mosquitto* client, void* self, const mosquitto_message* message);

  std::string filter_;
  mosquitto* client_ = nullptr;
  mutable std::mutex mutex_;
  bool subscribed_ = false;
  std::vector<MqttMessage> messages_;
};

}  // namespace lastcut::test
