# The warnings of pmdplan's own code, in one place: every target built from our sources (the layer
# libraries, the command-line program, the tests, the benchmarks, the Python module, the fuzz
# harnesses) calls pmdplan_warnings(<target>). Third-party headers come in as SYSTEM include
# folders (imported targets, the urdfdom and OMPL wrappers), so their warnings are not ours.
# With PMDPLAN_WERROR (the default) a warning fails the build: scripts/build (gcc) and
# scripts/configure-sanitize (clang) both build with it, so CI fails on a new warning. A packager
# with another compiler may pass -DPMDPLAN_WERROR=OFF (setup.py does: pip builds with whatever
# compiler the user has). tests/tooling/warning_flags_test.cmake compiles a file with one warning
# under exactly these flags and expects the compiler to fail.
option(PMDPLAN_WERROR "Turn warnings in pmdplan's own code into errors" ON)

set(PMDPLAN_WARNING_FLAGS -Wall -Wextra -Wpedantic)
# GCC 12 only: its -Wrestrict (in -Wall) reports a `"," + text` string concatenation inlined at -O3
# as a memcpy of 2^63 bytes in libstdc++'s char_traits.h; a false positive of that release (GCC 13
# no longer reports it), seen in six files. Any other GCC and clang keep the warning.
if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU" AND CMAKE_CXX_COMPILER_VERSION VERSION_GREATER_EQUAL 12
   AND CMAKE_CXX_COMPILER_VERSION VERSION_LESS 13)
  list(APPEND PMDPLAN_WARNING_FLAGS -Wno-restrict)
endif()
if(PMDPLAN_WERROR)
  list(APPEND PMDPLAN_WARNING_FLAGS -Werror)
endif()

function(pmdplan_warnings target)
  target_compile_options(${target} PRIVATE ${PMDPLAN_WARNING_FLAGS})
endfunction()

# Called once at the end of the top-level CMakeLists.txt: every target compiled in this build is
# ours, so each must carry the flags; a new test, benchmark or harness that forgot
# pmdplan_warnings() stops the configure step instead of compiling unchecked.
function(pmdplan_check_warnings_everywhere)
  set(directories ${CMAKE_SOURCE_DIR})
  set(missing "")
  while(directories)
    list(POP_FRONT directories directory)
    get_property(subdirectories DIRECTORY ${directory} PROPERTY SUBDIRECTORIES)
    list(APPEND directories ${subdirectories})
    get_property(targets DIRECTORY ${directory} PROPERTY BUILDSYSTEM_TARGETS)
    foreach(target IN LISTS targets)
      get_target_property(type ${target} TYPE)
      if(type MATCHES "^(EXECUTABLE|STATIC_LIBRARY|SHARED_LIBRARY|MODULE_LIBRARY|OBJECT_LIBRARY)$")
        get_target_property(options ${target} COMPILE_OPTIONS)
        if(NOT options OR NOT "-Wall" IN_LIST options)
          list(APPEND missing ${target})
        endif()
      endif()
    endforeach()
  endwhile()
  if(missing)
    message(FATAL_ERROR "built without pmdplan_warnings() (cmake/pmdplanWarnings.cmake): ${missing}")
  endif()
endfunction()
