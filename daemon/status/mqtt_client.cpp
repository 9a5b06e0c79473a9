#include "daemon/status/mqtt_client.hpp"

#include <mosquitto.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <condition_variable>
#include <cstring>
#include <mutex>

namespace lastcut::daemon {
namespace {

void init_library_once() {
  static std::once_flag once;
  std::call_once(once, [] { mosquitto_lib_init(); });
}

// What check_broker's callbacks report back to the waiting thread.
struct BrokerAnswer {
  std::mutex mutex;
  std::condition_variable answered;
  bool done = false;
  int connack = -1;
  std::string lost;  // why the connection ended before an answer (in the network thread: its errno)
};

}  // namespace

std::string mqtt_error_text(int code) {
  if (code == MOSQ_ERR_ERRNO) return std::strerror(errno);
  return mosquitto_strerror(code);
}

Result<mosquitto*> new_mqtt_client(const StatusConfig& config, const std::string& client_id, void* user_data) {
  init_library_once();
  mosquitto* client = mosquitto_new(client_id.c_str(), true, user_data);
  if (!client) return Status::failure("status: the MQTT client cannot be created: " + std::string(std::strerror(errno)));
  const auto refuse = [client](const std::string& what, int code) {
    mosquitto_destroy(client);
    return Status::failure("status: " + what + ": " + mqtt_error_text(code));
  };
  if (!config.username.empty()) {
    if (const int set = mosquitto_username_pw_set(client, config.username.c_str(),
                                                  config.password.empty() ? nullptr : config.password.c_str());
        set != MOSQ_ERR_SUCCESS) {
      return refuse("username/password not usable", set);
    }
  }
  if (config.tls) {
    const char* ca_file = config.ca_file.empty() ? nullptr : config.ca_file.c_str();
    const char* ca_path = config.ca_file.empty() ? "/etc/ssl/certs" : nullptr;
    if (const int set = mosquitto_tls_set(client, ca_file, ca_path, nullptr, nullptr, nullptr); set != MOSQ_ERR_SUCCESS) {
      return refuse("TLS not usable with ca_file \"" + config.ca_file + "\"", set);
    }
  }
  return client;
}

Status check_broker(const StatusConfig& config, double timeout_s) {
  BrokerAnswer answer;
  Result<mosquitto*> made = new_mqtt_client(config, "lastcutd-check-" + std::to_string(::getpid()), &answer);
  if (!made) return made.status();
  mosquitto* client = *made;
  mosquitto_connect_callback_set(client, [](mosquitto*, void* data, int code) {
    auto& reply = *static_cast<BrokerAnswer*>(data);
    std::lock_guard lock(reply.mutex);
    if (reply.done) return;
    reply.done = true;
    reply.connack = code;
    reply.answered.notify_all();
  });
  mosquitto_disconnect_callback_set(client, [](mosquitto*, void* data, int code) {
    auto& reply = *static_cast<BrokerAnswer*>(data);
    std::lock_guard lock(reply.mutex);
    if (reply.done) return;
    reply.lost = mqtt_error_text(code);
    reply.done = true;
    reply.answered.notify_all();
  });
  Status result = Status::success();
  // Asynchronous, so that a host that drops packets costs timeout_s and not the TCP timeout.
  mosquitto_loop_start(client);
  if (const int connecting = mosquitto_connect_async(client, config.host.c_str(), config.port, config.keepalive_s);
      connecting != MOSQ_ERR_SUCCESS) {
    result = Status::failure(mqtt_error_text(connecting));
    mosquitto_loop_stop(client, true);
  } else {
    std::unique_lock lock(answer.mutex);
    if (!answer.answered.wait_for(lock, std::chrono::duration<double>(timeout_s), [&] { return answer.done; })) {
      result = Status::failure("no answer within " + std::to_string(static_cast<int>(timeout_s)) + " s");
    } else if (answer.connack != 0) {
      result = Status::failure(answer.connack < 0 ? answer.lost : mosquitto_connack_string(answer.connack));
    }
    lock.unlock();
    mosquitto_disconnect(client);
    mosquitto_loop_stop(client, false);
  }
  mosquitto_destroy(client);
  return result;
}

}  // namespace lastcut::daemon
