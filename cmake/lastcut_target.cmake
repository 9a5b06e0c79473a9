# lastcut_warnings(TARGET): the project's warning set. Our code builds with no warnings.
function(lastcut_warnings target)
  # -Wshadow=local is gcc's; clang (the fuzz tree, LASTCUT_FUZZ) does not know it.
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic $<$<CXX_COMPILER_ID:GNU>:-Wshadow=local>
                                           -Wno-missing-field-initializers)
endfunction()

# `sanitize_tests`: what the ASan + UBSan tree (scripts/test.sh) builds: the tests labelled
# `sanitize` and the programs (lastcut, lastcutd, lastcut-sim) tests run, not every other test.
if(NOT TARGET sanitize_tests)
  add_custom_target(sanitize_tests)
endif()

# lastcut_library(NAME SOURCES... [DEPS ...]): one engine/driver/daemon module as a static library.
# The include root is the repository, so headers are included as "engine/flatten/arap.hpp".
function(lastcut_library name)
  cmake_parse_arguments(ARG "" "" "SOURCES;DEPS" ${ARGN})
  add_library(${name} STATIC ${ARG_SOURCES})
  target_include_directories(${name} PUBLIC ${PROJECT_SOURCE_DIR})
  target_link_libraries(${name} PUBLIC ${ARG_DEPS})
  lastcut_warnings(${name})
  if(LASTCUT_SANITIZE)
    target_compile_options(${name} PUBLIC -fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=undefined)
    target_link_options(${name} PUBLIC -fsanitize=address,undefined)
  endif()
endfunction()

# lastcut_test(NAME SOURCES... DEPS ... [LABELS ...]): a GoogleTest executable registered with CTest.
function(lastcut_test name)
  cmake_parse_arguments(ARG "" "TIMEOUT;RESOURCE_LOCK;COST" "SOURCES;DEPS;LABELS" ${ARGN})
  add_executable(${name} ${ARG_SOURCES})
  target_link_libraries(${name} PRIVATE ${ARG_DEPS} GTest::gtest GTest::gtest_main)
  target_compile_definitions(${name} PRIVATE
    LASTCUT_SOURCE_DIR="${PROJECT_SOURCE_DIR}"
    LASTCUT_SHARED_DATA_DIR="${LASTCUT_SHARED_DATA_DIR}"
    LASTCUT_BINARY_DIR="${PROJECT_BINARY_DIR}")
  lastcut_warnings(${name})
  # A test's own code at -O1: its speed lies in the libraries it calls (at -O2), and compiling the
  # tests was three fifths of the build, most of it optimising gtest's and json's templates. In the
  # clang sanitizer tree (LASTCUT_FUZZ) at -O0: there the instrumented compile is what CI waits for.
  if(LASTCUT_FUZZ)
    target_compile_options(${name} PRIVATE -O0)
  else()
    target_compile_options(${name} PRIVATE $<$<CONFIG:RelWithDebInfo>:-O1>)
  endif()
  if(LASTCUT_SANITIZE)
    target_compile_options(${name} PRIVATE -fsanitize=address,undefined -fno-omit-frame-pointer)
    target_link_options(${name} PRIVATE -fsanitize=address,undefined)
  endif()
  if(NOT ARG_TIMEOUT)
    set(ARG_TIMEOUT 300)
  endif()
  set(extra_properties "")
  if(ARG_RESOURCE_LOCK)
    set(extra_properties RESOURCE_LOCK ${ARG_RESOURCE_LOCK})
  endif()
  # COST: ctest starts the costliest tests first when it has no timings of its own yet (a fresh
  # clone, CI): the long ones then overlap the many short ones instead of running alone at the end.
  if(ARG_COST)
    list(APPEND extra_properties COST ${ARG_COST})
  endif()
  include(GoogleTest)
  if("sanitize" IN_LIST ARG_LABELS)
    add_dependencies(sanitize_tests ${name})
  endif()
  gtest_discover_tests(${name} DISCOVERY_TIMEOUT 60 PROPERTIES TIMEOUT ${ARG_TIMEOUT} LABELS "${ARG_LABELS}" ${extra_properties})
endfunction()

# lastcut_program(NAME SOURCES... DEPS ...): an executable placed in <build>/bin.
function(lastcut_program name)
  cmake_parse_arguments(ARG "" "" "SOURCES;DEPS" ${ARGN})
  add_executable(${name} ${ARG_SOURCES})
  target_link_libraries(${name} PRIVATE ${ARG_DEPS})
  set_target_properties(${name} PROPERTIES RUNTIME_OUTPUT_DIRECTORY ${PROJECT_BINARY_DIR}/bin)
  lastcut_warnings(${name})
  if(LASTCUT_SANITIZE)
    target_compile_options(${name} PRIVATE -fsanitize=address,undefined -fno-omit-frame-pointer)
    target_link_options(${name} PRIVATE -fsanitize=address,undefined)
  endif()
  add_dependencies(sanitize_tests ${name})
endfunction()
