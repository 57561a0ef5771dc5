# Helpers shared by every target of the project.

# Per-target warnings and language level.
function(pmap_target_defaults target)
  target_compile_features(${target} PUBLIC cxx_std_17)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wno-psabi)
  # Sanitizers (doc/robustness.md). GCC's "undefined" group leaves out
  # float-cast-overflow: named explicitly. Every report stops the program.
  set(sanitizers address,undefined,float-cast-overflow)
  if(PMAP_FUZZ)  # coverage for libFuzzer; the fuzz targets link -fsanitize=fuzzer
    set(sanitizers fuzzer-no-link,${sanitizers})
  endif()
  if(PMAP_SANITIZE OR PMAP_FUZZ)
    target_compile_options(${target} PRIVATE
      -fsanitize=${sanitizers} -fno-omit-frame-pointer -fno-sanitize-recover=all)
    target_link_options(${target} PUBLIC -fsanitize=address,undefined,float-cast-overflow)
    # Eigen stops trusting malloc's 16-byte alignment under ASan and then
    # frees with its own header, while Ceres, MRPT and OpenCV (built without
    # ASan) allocate with plain malloc: matrices crossing the boundary (a
    # ceres::GradientChecker::ProbeResults) were freed wrongly. Both mallocs
    # align to 16 bytes on x86-64: keep Eigen's ABI the same as theirs.
    target_compile_definitions(${target} PUBLIC EIGEN_MALLOC_ALREADY_ALIGNED=1)
  endif()
endfunction()

# pmap_add_library(<name> SOURCES ... [PUBLIC_DEPS ...] [PRIVATE_DEPS ...])
# Creates pmap_<name> (alias pmap::<name>) with include/ as its public include
# dir (the headers other libraries and the apps use) and internal/, when it
# exists, as a private one (headers used inside the library alone).
function(pmap_add_library name)
  cmake_parse_arguments(ARG "" "" "SOURCES;PUBLIC_DEPS;PRIVATE_DEPS" ${ARGN})
  add_library(pmap_${name} STATIC ${ARG_SOURCES})
  add_library(pmap::${name} ALIAS pmap_${name})
  target_include_directories(pmap_${name} PUBLIC
    $<BUILD_INTERFACE:${CMAKE_CURRENT_SOURCE_DIR}/include>)
  if(IS_DIRECTORY ${CMAKE_CURRENT_SOURCE_DIR}/internal)
    target_include_directories(pmap_${name} PRIVATE ${CMAKE_CURRENT_SOURCE_DIR}/internal)
    set_target_properties(pmap_${name} PROPERTIES
      PMAP_INTERNAL_DIR ${CMAKE_CURRENT_SOURCE_DIR}/internal)
  endif()
  target_link_libraries(pmap_${name} PUBLIC ${ARG_PUBLIC_DEPS} PRIVATE ${ARG_PRIVATE_DEPS})
  pmap_target_defaults(pmap_${name})
endfunction()

# pmap_add_app(<name> SOURCES ... DEPS ...)
function(pmap_add_app name)
  cmake_parse_arguments(ARG "" "" "SOURCES;DEPS" ${ARGN})
  add_executable(${name} ${ARG_SOURCES})
  target_link_libraries(${name} PRIVATE ${ARG_DEPS})
  pmap_target_defaults(${name})
  set_target_properties(${name} PROPERTIES RUNTIME_OUTPUT_DIRECTORY ${PROJECT_BINARY_DIR}/bin)
endfunction()

# pmap_see_internals(<target> <dep>...): lets a test or benchmark include the
# internal headers of each project library <dep> (pmap::<lib>) it names;
# other names are ignored.
function(pmap_see_internals target)
  foreach(dep ${ARGN})
    if(dep MATCHES "^pmap::(.+)$")
      set(lib pmap_${CMAKE_MATCH_1})
      if(TARGET ${lib})
        get_target_property(dir ${lib} PMAP_INTERNAL_DIR)
        if(dir)
          target_include_directories(${target} PRIVATE ${dir})
        endif()
      endif()
    endif()
  endforeach()
endfunction()

# pmap_add_gtest(<name> SOURCES ... DEPS ... [LABELS ...] [FIXTURES ...])
# FIXTURES: CTest fixtures the tests require (e.g. simulated worlds).
function(pmap_add_gtest name)
  cmake_parse_arguments(ARG "" "" "SOURCES;DEPS;LABELS;FIXTURES" ${ARGN})
  add_executable(${name} ${ARG_SOURCES})
  target_link_libraries(${name} PRIVATE ${ARG_DEPS} GTest::gtest GTest::gtest_main)
  pmap_see_internals(${name} ${ARG_DEPS})
  pmap_target_defaults(${name})
  target_compile_definitions(${name} PRIVATE
    PMAP_SOURCE_DIR="${PROJECT_SOURCE_DIR}"
    PMAP_BINARY_DIR="${PROJECT_BINARY_DIR}"
    PMAP_TEST_TMP_DIR="${PROJECT_BINARY_DIR}/test-tmp")
  set_target_properties(${name} PROPERTIES RUNTIME_OUTPUT_DIRECTORY ${PROJECT_BINARY_DIR}/tests)
  set(props LABELS "${ARG_LABELS}")
  if(ARG_FIXTURES)
    list(APPEND props FIXTURES_REQUIRED "${ARG_FIXTURES}")
  endif()
  gtest_discover_tests(${name} TEST_PREFIX "${name}." DISCOVERY_TIMEOUT 60 PROPERTIES ${props})
  pmap_note_sanitized_test(${name} "${ARG_LABELS}")
endfunction()

# Test executables whose tests scripts/sanitize-tests.sh runs (labels unit or
# robustness) are collected here; the target `sanitized-tests` (tests/
# CMakeLists.txt) builds only them and the apps, not the end-to-end suites.
function(pmap_note_sanitized_test name labels)
  if(labels MATCHES "(^|;)(unit|robustness)(;|$)")
    set_property(GLOBAL APPEND PROPERTY PMAP_SANITIZED_TESTS ${name})
  endif()
endfunction()
