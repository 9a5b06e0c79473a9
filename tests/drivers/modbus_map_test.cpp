// Modbus register map (TOML file vs built-in default, validation), endpoint parsing and the
// operator-facing text of every Modbus exception code.
#include <gtest/gtest.h>

#include <fstream>
#include <modbus/modbus.h>

#include "drivers/modbus/modbus_client.hpp"
#include "drivers/modbus/register_map.hpp"
#include "tests/drivers/sim_process.hpp"

namespace lastcut::drivers::modbus {
namespace {

TEST(RegisterMap, ShippedTomlIsExactlyTheBuiltInDefault) {
  RegisterMap loaded;
  // Start from a map that differs everywhere, so every key must come from the file.
  loaded.status = 900, loaded.error_code = 901, loaded.progress_permille = 902, loaded.block_ack = 903;
  loaded.command = 904, loaded.job_id = 905, loaded.job_id_words = 3, loaded.program_bytes = 950;
  loaded.block_number = 960, loaded.block_length = 961, loaded.window = 1000, loaded.window_words = 7;
  loaded.status_codes = {10, 11, 12, 13, 14, 15, 16};
  loaded.command_codes = {20, 21, 22, 23};
  loaded.poll_s = 9;
  std::string error;
  ASSERT_TRUE(load_register_map(std::string(LASTCUT_SOURCE_DIR) + "/config/modbus-register-map.toml", loaded, error)) << error;
  const RegisterMap d;
  EXPECT_EQ(loaded.status, d.status);
  EXPECT_EQ(loaded.error_code, d.error_code);
  EXPECT_EQ(loaded.progress_permille, d.progress_permille);
  EXPECT_EQ(loaded.block_ack, d.block_ack);
  EXPECT_EQ(loaded.command, d.command);
  EXPECT_EQ(loaded.job_id, d.job_id);
  EXPECT_EQ(loaded.job_id_words, d.job_id_words);
  EXPECT_EQ(loaded.program_bytes, d.program_bytes);
  EXPECT_EQ(loaded.block_number, d.block_number);
  EXPECT_EQ(loaded.block_length, d.block_length);
  EXPECT_EQ(loaded.window, d.window);
  EXPECT_EQ(loaded.window_words, d.window_words);
  EXPECT_EQ(loaded.status_codes.not_ready, d.status_codes.not_ready);
  EXPECT_EQ(loaded.status_codes.ready, d.status_codes.ready);
  EXPECT_EQ(loaded.status_codes.receiving, d.status_codes.receiving);
  EXPECT_EQ(loaded.status_codes.loaded, d.status_codes.loaded);
  EXPECT_EQ(loaded.status_codes.running, d.status_codes.running);
  EXPECT_EQ(loaded.status_codes.done, d.status_codes.done);
  EXPECT_EQ(loaded.status_codes.error, d.status_codes.error);
  EXPECT_EQ(loaded.command_codes.begin, d.command_codes.begin);
  EXPECT_EQ(loaded.command_codes.start, d.command_codes.start);
  EXPECT_EQ(loaded.command_codes.abort, d.command_codes.abort);
  EXPECT_EQ(loaded.command_codes.clear_error, d.command_codes.clear_error);
  EXPECT_DOUBLE_EQ(loaded.poll_s, d.poll_s);
}

std::string write_map(const testing::TempDir& dir, const std::string& text) {
  const std::string path = dir / "map.toml";
  std::ofstream(path) << text;
  return path;
}

TEST(RegisterMap, RefusesBrokenMapsWithAReason) {
  testing::TempDir dir;
  RegisterMap map;
  std::string error;
  EXPECT_FALSE(load_register_map(write_map(dir, "[registers]\nwindow = 0\n"), map, error));
  EXPECT_NE(error.find("overlap"), std::string::npos) << error;
  map = {};
  EXPECT_FALSE(load_register_map(write_map(dir, "[registers]\nwindow_words = 200\n"), map, error));
  EXPECT_NE(error.find("123"), std::string::npos) << error;
  map = {};
  EXPECT_FALSE(load_register_map(write_map(dir, "[registers]\nblock_length = 40\n"), map, error));
  EXPECT_NE(error.find("block_length"), std::string::npos) << error;
  map = {};
  EXPECT_FALSE(load_register_map(write_map(dir, "[registers\nstatus = 1\n"), map, error));
  EXPECT_NE(error.find("line 1"), std::string::npos) << error;
  map = {};
  EXPECT_FALSE(load_register_map(dir / "missing.toml", map, error));
}

// Found by the register_map fuzz target: an address near INT_MAX overflowed the overlap check
// (UBSan), and one beyond int was silently cut down (4294967296 became register 0).
TEST(RegisterMap, RefusesAddressesOutsideSixteenBits) {
  testing::TempDir dir;
  RegisterMap map;
  std::string error;
  EXPECT_FALSE(load_register_map(write_map(dir, "[registers]\nwindow = 2147483600\n"), map, error));
  EXPECT_NE(error.find("registers.window must be an integer 0..65535"), std::string::npos) << error;
  map = {};
  EXPECT_FALSE(load_register_map(write_map(dir, "[registers]\nstatus = 4294967296\n"), map, error));
  EXPECT_NE(error.find("registers.status"), std::string::npos) << error;
  map = {};
  EXPECT_FALSE(load_register_map(write_map(dir, "[command]\nabort = -1\n"), map, error));
  EXPECT_NE(error.find("command.abort"), std::string::npos) << error;
  map = {};
  EXPECT_FALSE(load_register_map(write_map(dir, "[timing]\npoll_s = nan\n"), map, error));
  EXPECT_NE(error.find("poll_s"), std::string::npos) << error;
  map = {};
  map.window = 2147483600;
  EXPECT_FALSE(validate_register_map(map, error));
  EXPECT_NE(error.find("out of range"), std::string::npos) << error;
}

TEST(ModbusEndpoint, ParsesTcpAndRtu) {
  ModbusEndpoint e;
  std::string error;
  ASSERT_TRUE(parse_modbus_endpoint("tcp://127.0.0.1:1502", e, error)) << error;
  EXPECT_FALSE(e.rtu);
  EXPECT_EQ(e.host, "127.0.0.1");
  EXPECT_EQ(e.port, 1502);
  ASSERT_TRUE(parse_modbus_endpoint("rtu:/dev/ttyUSB1,9600,8E1", e, error)) << error;
  EXPECT_TRUE(e.rtu);
  EXPECT_EQ(e.device, "/dev/ttyUSB1");
  EXPECT_EQ(e.baud, 9600);
  EXPECT_EQ(e.parity, 'E');
  for (const char* bad : {"tcp://127.0.0.1", "tcp://:1502", "rtu:", "rtu:/dev/x,fast", "rtu:/dev/x,9600,9Q1", "modbus://x"}) {
    EXPECT_FALSE(parse_modbus_endpoint(bad, e, error)) << bad;
    EXPECT_FALSE(error.empty());
  }
}

TEST(ModbusErrors, EveryExceptionCodeHasAnOperatorReadableText) {
  EXPECT_NE(explain_modbus_error(EMBXILFUN).find("exception 1"), std::string::npos);
  EXPECT_NE(explain_modbus_error(EMBXILADD).find("register map does not match"), std::string::npos);
  EXPECT_NE(explain_modbus_error(EMBXILVAL).find("exception 3"), std::string::npos);
  EXPECT_NE(explain_modbus_error(EMBXSFAIL).find("exception 4"), std::string::npos);
  EXPECT_NE(explain_modbus_error(EMBXACK).find("exception 5"), std::string::npos);
  EXPECT_NE(explain_modbus_error(EMBXSBUSY).find("exception 6"), std::string::npos);
  EXPECT_NE(explain_modbus_error(EMBXNACK).find("exception 7"), std::string::npos);
  EXPECT_NE(explain_modbus_error(EMBXMEMPAR).find("exception 8"), std::string::npos);
  EXPECT_NE(explain_modbus_error(EMBXGPATH).find("exception 10"), std::string::npos);
  EXPECT_NE(explain_modbus_error(EMBXGTAR).find("exception 11"), std::string::npos);
  EXPECT_NE(explain_modbus_error(EMBBADCRC).find("CRC"), std::string::npos);
  EXPECT_NE(explain_modbus_error(ETIMEDOUT).find("no reply"), std::string::npos);
}

}  // namespace
}  // namespace lastcut::drivers::modbus
