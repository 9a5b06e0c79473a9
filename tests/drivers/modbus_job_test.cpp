// Modbus jobs over REAL loopback TCP and pseudo-terminals (RTU): lastcut's client against
// `lastcut-sim modbus-*`, and each side against an independent implementation: mbpoll (Debian)
// and the npm package modbus-serial (client and server). Missing tools FAIL these tests.
#include <gtest/gtest.h>

#include <chrono>
#include <fstream>
#include <thread>

#include "drivers/cutter.hpp"
#include "tests/drivers/sim_process.hpp"

namespace lastcut::drivers {
namespace {

using testing::SimProcess;
using testing::TempDir;
using testing::read_file;
using testing::run_command;

std::string make_program(size_t bytes) {
  std::string program;
  for (size_t i = 0; program.size() < bytes; ++i) program += "PD" + std::to_string(i * 13 % 9999) + "," + std::to_string(i) + ";\n";
  program.resize(bytes);
  return program;
}

struct ModbusFixture {
  TempDir dir;
  int port = testing::free_loopback_port();
  std::unique_ptr<SimProcess> sim;
  CutterConfig config;
  explicit ModbusFixture(std::vector<std::string> extra = {}, bool rtu = false, const std::string& cut_s = "0.3") {
    std::vector<std::string> args{rtu ? "modbus-rtu" : "modbus-tcp", "--record", dir / "rec", "--cut-s", cut_s};
    if (rtu) args.insert(args.end(), {"--link", dir / "plc"});
    else args.insert(args.end(), {"--port", std::to_string(port)});
    args.insert(args.end(), extra.begin(), extra.end());
    sim = std::make_unique<SimProcess>(args);
    config.name = "test-plc";
    config.protocol = "modbus";
    config.modbus = rtu ? "rtu:" + (dir / "plc") + ",19200" : "tcp://127.0.0.1:" + std::to_string(port);
    config.timeout_s = 1.5;
    config.job_id = "JOB-42-LEFT";
  }
  SendResult send(const std::string& program) {
    const std::atomic<bool> never{false};
    return send_job(config, program, nullptr, never);
  }
};

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

TEST(ModbusJob, TcpJobArrivesByteExactAndIsDoneOnlyWhenThePlcSaysSo) {
  ModbusFixture f;
  ASSERT_TRUE(f.sim->ready()) << f.sim->ready_line();
  const std::string program = make_program(1001);  // odd: the last register carries one padded byte
  std::vector<std::string> states;
  const std::atomic<bool> never{false};
  const SendResult result = send_job(f.config, program, [&](const SendProgress& p) { states.push_back(p.device_state); }, never);
  EXPECT_EQ(result.outcome, SendOutcome::Done) << result.reason;
  ASSERT_FALSE(states.empty());
  EXPECT_EQ(states.back(), "done");
  bool saw_running = false;
  for (const auto& s : states) saw_running |= s.rfind("running", 0) == 0;
  EXPECT_TRUE(saw_running);
  EXPECT_EQ(f.sim->stop(), 0);
  EXPECT_EQ(read_file(f.dir.path() / "rec" / "modbus-received.bin"), program);
  EXPECT_NE(read_file(f.dir.path() / "rec" / "modbus-stats.json").find("\"job_id\": \"JOB-42-LEFT\""), std::string::npos);
}

TEST(ModbusJob, RtuJobOverAPseudoTerminal) {
  ModbusFixture f({}, true);
  ASSERT_TRUE(f.sim->ready()) << f.sim->ready_line();
  const std::string program = make_program(700);
  const SendResult result = f.send(program);
  EXPECT_EQ(result.outcome, SendOutcome::Done) << result.reason;
  EXPECT_EQ(f.sim->stop(), 0);
  EXPECT_EQ(read_file(f.dir.path() / "rec" / "modbus-received.bin"), program);
}

TEST(ModbusJob, RejectedBlockFailsBeforeCuttingAndTheErrorIsNotClearedByUs) {
  ModbusFixture f({"--fault", "error-at-line=2:77"});
  ASSERT_TRUE(f.sim->ready());
  const SendResult result = f.send(make_program(1000));
  EXPECT_EQ(result.outcome, SendOutcome::Failed);
  EXPECT_NE(result.reason.find("error code 77"), std::string::npos) << result.reason;
  const SendResult next = f.send(make_program(10));
  EXPECT_EQ(next.outcome, SendOutcome::Failed);
  EXPECT_NE(next.reason.find("clear it at the machine"), std::string::npos) << next.reason;
  const ProbeResult probe = probe_cutter(f.config);
  EXPECT_FALSE(probe.ready);
  EXPECT_EQ(probe.state, "error");
}

TEST(ModbusJob, ErrorWhileCuttingInterrupts) {
  ModbusFixture f({"--fault", "alarm-at-line=1:55"});
  ASSERT_TRUE(f.sim->ready());
  const SendResult result = f.send(make_program(500));
  EXPECT_EQ(result.outcome, SendOutcome::Interrupted);
  EXPECT_NE(result.reason.find("error code 55 while cutting"), std::string::npos) << result.reason;
}

TEST(ModbusJob, DroppedConnectionDuringTransferFailsWithinTheTimeout) {
  ModbusFixture f({"--fault", "drop-at-line=2"});
  ASSERT_TRUE(f.sim->ready());
  const auto start = std::chrono::steady_clock::now();
  const SendResult result = f.send(make_program(1000));
  EXPECT_EQ(result.outcome, SendOutcome::Failed) << result.reason;
  EXPECT_NE(result.reason.find("nothing was started"), std::string::npos) << result.reason;
  EXPECT_LT(seconds_since(start), f.config.timeout_s + 3);
}

TEST(ModbusJob, StalledPlcFailsWithinTheTimeout) {
  ModbusFixture f({"--fault", "stall-at-line=2"});
  ASSERT_TRUE(f.sim->ready());
  const auto start = std::chrono::steady_clock::now();
  const SendResult result = f.send(make_program(1000));
  EXPECT_EQ(result.outcome, SendOutcome::Failed);
  EXPECT_NE(result.reason.find("no reply"), std::string::npos) << result.reason;
  EXPECT_LT(seconds_since(start), f.config.timeout_s + 3);
}

TEST(ModbusJob, GarbageReplyFails) {
  ModbusFixture f({"--fault", "garbage-at-line=2"});
  ASSERT_TRUE(f.sim->ready());
  const SendResult result = f.send(make_program(1000));
  EXPECT_EQ(result.outcome, SendOutcome::Failed) << result.reason;
}

TEST(ModbusJob, MapThatDoesNotMatchThePlcNamesTheException) {
  ModbusFixture f;
  ASSERT_TRUE(f.sim->ready());
  const std::string map = f.dir / "big-window.toml";
  std::ofstream(map) << "[registers]\nwindow = 5000\n";
  f.config.modbus_map = map;
  const SendResult result = f.send(make_program(100));
  EXPECT_EQ(result.outcome, SendOutcome::Failed);
  EXPECT_NE(result.reason.find("illegal data address (exception 2)"), std::string::npos) << result.reason;
}

TEST(ModbusJob, CancelWhileCuttingSendsAbort) {
  ModbusFixture f({}, false, "5");
  ASSERT_TRUE(f.sim->ready());
  std::atomic<bool> cancel{false};
  const SendResult result = send_job(f.config, make_program(300), [&](const SendProgress& p) {
    if (p.device_state.rfind("running", 0) == 0) cancel.store(true);
  }, cancel);
  EXPECT_EQ(result.outcome, SendOutcome::Interrupted);
  EXPECT_NE(result.reason.find("abort sent"), std::string::npos) << result.reason;
  EXPECT_TRUE(probe_cutter(f.config).ready) << "after abort the PLC is ready again";
}

// ---- interoperability with independent implementations ----

std::string mbpoll(int port, const std::string& args) {
  std::string out;
  const int rc = run_command("mbpoll -m tcp -p " + std::to_string(port) + " -a 1 -0 -1 -o 1 " + args, out);
  EXPECT_EQ(rc, 0) << "mbpoll " << args << ":\n" << out;
  return out;
}

TEST(ModbusInterop, MbpollRunsTheHandshakeAgainstTheSimulator) {
  ModbusFixture f({}, false, "0.1");
  ASSERT_TRUE(f.sim->ready());
  std::string out;
  ASSERT_EQ(run_command("command -v mbpoll", out), 0) << "mbpoll is not installed: run scripts/setup.sh";
  EXPECT_NE(mbpoll(f.port, "-r 0 -c 4 127.0.0.1").find("[0]: \t1"), std::string::npos);  // ready
  mbpoll(f.port, "-r 19 127.0.0.1 0 4");         // program_bytes = 4
  mbpoll(f.port, "-r 10 127.0.0.1 1");           // command = begin
  EXPECT_NE(mbpoll(f.port, "-r 0 127.0.0.1").find("[0]: \t2"), std::string::npos);      // receiving
  mbpoll(f.port, "-r 100 127.0.0.1 16706 2627");  // "AB" "\nC"
  mbpoll(f.port, "-r 21 127.0.0.1 1 4");         // block 1, 4 bytes
  const std::string state = mbpoll(f.port, "-r 0 -c 4 127.0.0.1");
  EXPECT_NE(state.find("[0]: \t3"), std::string::npos) << state;  // loaded
  EXPECT_NE(state.find("[3]: \t1"), std::string::npos) << state;  // block 1 acknowledged
  mbpoll(f.port, "-r 10 127.0.0.1 2");           // start
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  EXPECT_NE(mbpoll(f.port, "-r 0 127.0.0.1").find("[0]: \t5"), std::string::npos);      // done
  run_command("mbpoll -m tcp -p " + std::to_string(f.port) + " -a 1 -0 -1 -o 1 -r 9000 127.0.0.1", out);
  EXPECT_NE(out.find("Illegal data address"), std::string::npos) << out;
  EXPECT_EQ(f.sim->stop(), 0);
  EXPECT_EQ(read_file(f.dir.path() / "rec" / "modbus-received.bin"), "AB\nC");
}

TEST(ModbusInterop, MbpollReadsTheSimulatorOverRtu) {
  ModbusFixture f({}, true);
  ASSERT_TRUE(f.sim->ready());
  std::string out;
  const int rc = run_command("mbpoll -m rtu -b 19200 -P none -a 1 -0 -1 -o 1 -r 0 -c 4 " + (f.dir / "plc"), out);
  EXPECT_EQ(rc, 0) << out;
  EXPECT_NE(out.find("[0]: \t1"), std::string::npos) << out;
}

std::string node_script(const std::string& name) {
  return std::string(LASTCUT_SOURCE_DIR) + "/tests/drivers/node/" + name;
}

TEST(ModbusInterop, NodeModbusSerialClientRunsAJobOnTheSimulator) {
  ModbusFixture f({}, false, "0.1");
  ASSERT_TRUE(f.sim->ready());
  const std::string program = make_program(777);
  const std::string file = f.dir / "program.hpgl";
  std::ofstream(file, std::ios::binary) << program;
  std::string out;
  const int rc = run_command("node " + node_script("modbus_client_job.js") + " " + std::to_string(f.port) + " " + file + " NODE-1", out);
  EXPECT_EQ(rc, 0) << out;
  EXPECT_NE(out.find("done"), std::string::npos) << out;
  EXPECT_EQ(f.sim->stop(), 0);
  EXPECT_EQ(read_file(f.dir.path() / "rec" / "modbus-received.bin"), program);
}

TEST(ModbusInterop, LastcutClientRunsAJobOnTheNodeModbusSerialServer) {
  TempDir dir;
  const int port = testing::free_loopback_port();
  const std::string out_file = dir / "received.bin";
  SimProcess server("node", {node_script("modbus_plc_server.js"), std::to_string(port), out_file});
  ASSERT_TRUE(server.ready()) << "node modbus-serial server did not start: " << server.ready_line();
  CutterConfig config;
  config.protocol = "modbus";
  config.modbus = "tcp://127.0.0.1:" + std::to_string(port);
  config.timeout_s = 2;
  config.job_id = "NODE-PLC";
  const std::string program = make_program(1500);
  const std::atomic<bool> never{false};
  const SendResult result = send_job(config, program, nullptr, never);
  EXPECT_EQ(result.outcome, SendOutcome::Done) << result.reason;
  server.stop();
  EXPECT_EQ(read_file(out_file), program);
  EXPECT_EQ(read_file(out_file + ".id"), "NODE-PLC");
}

}  // namespace
}  // namespace lastcut::drivers
