#include "mosquitto_broker.hpp"

#include <arpa/inet.h>
#include <mosquitto.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <chrono>
#include <fstream>
#include <sstream>
#include <thread>

#include "tests/support/loopback_port.hpp"

namespace lastcut::test {
namespace {

constexpr const char* kMosquitto = "/usr/sbin/mosquitto";

bool accepts_connections(int port) {
  const int fd = ::socket(AF_INET, SOCK_STREAM, 0);
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_port = htons(static_cast<uint16_t>(port));
  address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  const bool connected = ::connect(fd, reinterpret_cast<sockaddr*>(&address), sizeof address) == 0;
  ::close(fd);
  return connected;
}

std::string read_all(const std::filesystem::path& file) {
  std::ifstream in(file);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace

MosquittoBroker::MosquittoBroker(std::filesystem::path folder, const std::string& listener_lines)
    : folder_(std::move(folder)), port_(free_loopback_port()) {
  std::filesystem::create_directories(folder_);
  std::ofstream config(folder_ / "mosquitto.conf");
  config << "listener " << port_ << " 127.0.0.1\n"
         << (listener_lines.find("allow_anonymous") == std::string::npos ? "allow_anonymous true\n" : "")
         << listener_lines
         << "persistence false\n"
         << "log_dest stderr\n"
         << "log_type error\nlog_type warning\nlog_type notice\nlog_type information\n"
         << "connection_messages true\n";
  // As root mosquitto would switch to the user "mosquitto", which may not read the test folder.
  if (::geteuid() == 0) config << "user root\n";
}

MosquittoBroker::~MosquittoBroker() = default;  // the ChildProcess kills a running broker

std::string MosquittoBroker::start() {
  if (::access(kMosquitto, X_OK) != 0) {
    return std::string(kMosquitto) + " not found: install the Debian package mosquitto (scripts/setup.sh)";
  }
  if (port_ == 0) return "no free port on 127.0.0.1";
  try {
    process_ = std::make_unique<ChildProcess>(
        std::vector<std::string>{kMosquitto, "-c", (folder_ / "mosquitto.conf").string()}, log_file());
  } catch (const std::exception& e) {
    return e.what();
  }
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(10);
  while (std::chrono::steady_clock::now() < deadline) {
    if (!running()) return "mosquitto exited at start: " + read_all(log_file());
    if (accepts_connections(port_)) return "";
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  return "mosquitto does not accept connections on port " + std::to_string(port_) + " after 10 s: " +
         read_all(log_file());
}

void MosquittoBroker::stop() {
  if (process_) process_->stop(5);
  process_.reset();
}

bool MosquittoBroker::running() { return process_ && process_->running(); }

MqttSubscriber::MqttSubscriber(int port, std::string filter) : filter_(std::move(filter)) {
  static std::once_flag once;
  std::call_once(once, [] { mosquitto_lib_init(); });
  client_ = mosquitto_new(nullptr, true, this);
  mosquitto_connect_callback_set(client_, &MqttSubscriber::on_connect);
  mosquitto_subscribe_callback_set(client_, &MqttSubscriber::on_subscribe);
  mosquitto_message_callback_set(client_, &MqttSubscriber::on_message);
  mosquitto_reconnect_delay_set(client_, 1, 1, false);
  mosquitto_loop_start(client_);
  mosquitto_connect_async(client_, "127.0.0.1", port, 10);
}

MqttSubscriber::~MqttSubscriber() {
  mosquitto_disconnect(client_);
  mosquitto_loop_stop(client_, false);
  mosquitto_destroy(client_);
}

void MqttSubscriber::on_connect(mosquitto* client, void* self, int code) {
  auto& subscriber = *static_cast<MqttSubscriber*>(self);
  if (code == 0) mosquitto_subscribe(client, nullptr, subscriber.filter_.c_str(), 1);
}

void MqttSubscriber::on_subscribe(mosquitto*, void* self, int, int, const int*) {
  auto& subscriber = *static_cast<MqttSubscriber*>(self);
  std::lock_guard lock(subscriber.mutex_);
  subscriber.subscribed_ = true;
}

void MqttSubscriber::on_message(mosquitto*, void* self, const mosquitto_message* message) {
  auto& subscriber = *static_cast<MqttSubscriber*>(self);
  std::lock_guard lock(subscriber.mutex_);
  subscriber.messages_.push_back(
      {message->topic, std::string(static_cast<const char*>(message->payload), static_cast<std::size_t>(message->payloadlen)),
       message->retain});
}

bool MqttSubscriber::wait_subscribed(double timeout_s) {
  return wait_until(
      [this] {
        std::lock_guard lock(mutex_);
        return subscribed_;
      },
      timeout_s);
}

std::vector<MqttMessage> MqttSubscriber::messages() const {
  std::lock_guard lock(mutex_);
  return messages_;
}

std::vector<MqttMessage> MqttSubscriber::on(const std::string& topic) const {
  std::vector<MqttMessage> found;
  for (MqttMessage& message : messages()) {
    if (message.topic == topic) found.push_back(std::move(message));
  }
  return found;
}

std::optional<MqttMessage> MqttSubscriber::last(const std::string& topic) const {
  auto found = on(topic);
  if (found.empty()) return std::nullopt;
  return found.back();
}

bool MqttSubscriber::wait_until(const std::function<bool()>& done, double timeout_s) const {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout_s);
  while (!done()) {
    if (std::chrono::steady_clock::now() >= deadline) return done();
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  return true;
}

}  // namespace lastcut::test
