# Every dependency is a Debian bookworm package installed by scripts/setup.sh.
# All are REQUIRED: a missing install step fails the configure, not a test later. The test and
# benchmark frameworks only where tests and benchmarks are built (the demo and the Debian package
# build the programs alone, scripts/setup.sh --programs).
find_package(Eigen3 3.4 REQUIRED NO_MODULE)
find_package(OpenMesh REQUIRED)
find_package(spdlog REQUIRED)
find_package(fmt REQUIRED)
if(LASTCUT_BUILD_TESTS)
  find_package(GTest REQUIRED)
endif()
find_package(CLI11 REQUIRED)
find_package(nlohmann_json 3 REQUIRED)
find_package(tomlplusplus REQUIRED)
if(LASTCUT_BUILD_BENCH)
  find_package(benchmark REQUIRED)
endif()
find_package(Threads REQUIRED)
find_package(PkgConfig REQUIRED)
pkg_check_modules(MODBUS REQUIRED IMPORTED_TARGET libmodbus)
pkg_check_modules(SERIALPORT REQUIRED IMPORTED_TARGET libserialport)
pkg_check_modules(POLYCLIPPING REQUIRED IMPORTED_TARGET polyclipping)
pkg_check_modules(SYSTEMD REQUIRED IMPORTED_TARGET libsystemd)
# Live status over MQTT (daemon/status); the tests start the mosquitto broker itself.
pkg_check_modules(MOSQUITTO REQUIRED IMPORTED_TARGET libmosquitto)
# The multi-station job ledger (daemon/ledger) talks to PostgreSQL through libpqxx.
pkg_check_modules(PQXX REQUIRED IMPORTED_TARGET libpqxx)
# The operator page lastcutd serves (daemon/web): Debian's cpp-httplib, a compiled library there.
pkg_check_modules(HTTPLIB REQUIRED IMPORTED_TARGET cpp-httplib)

# CHOLMOD (SuiteSparse) ships no CMake config in bookworm: find it by hand.
find_path(CHOLMOD_INCLUDE_DIR cholmod.h PATH_SUFFIXES suitesparse REQUIRED)
find_library(CHOLMOD_LIBRARY cholmod REQUIRED)
find_library(SUITESPARSECONFIG_LIBRARY suitesparseconfig REQUIRED)
add_library(lastcut_cholmod INTERFACE)
target_include_directories(lastcut_cholmod SYSTEM INTERFACE ${CHOLMOD_INCLUDE_DIR})
target_link_libraries(lastcut_cholmod INTERFACE ${CHOLMOD_LIBRARY} ${SUITESPARSECONFIG_LIBRARY})

