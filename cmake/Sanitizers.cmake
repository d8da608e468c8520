# Sanitized and fuzzing builds. Both apply to every target of the project (libraries, renderers,
# tests), because a sanitizer sees only the code compiled with it.
#
#   -DFREEZERAY_SANITIZE=address,undefined   AddressSanitizer + UndefinedBehaviorSanitizer
#   -DFREEZERAY_SANITIZE=thread              ThreadSanitizer (cannot be combined with address)
#   -DFREEZERAY_FUZZ=ON                      libFuzzer targets in tests/fuzz (Clang only; see
#                                            tests/fuzz/README.md); implies address,undefined
#                                            unless FREEZERAY_SANITIZE says otherwise
#
# A finding of UBSan stops the program (-fno-sanitize-recover), so a test that triggers
# undefined behaviour fails instead of printing a line nobody reads. Use
# -DCMAKE_BUILD_TYPE=RelWithDebInfo for reports with file and line numbers.

set(FREEZERAY_SANITIZE "" CACHE STRING
    "Build everything with sanitizers: empty (none), address,undefined, or thread")
set_property(CACHE FREEZERAY_SANITIZE PROPERTY STRINGS "" "address,undefined" "address" "undefined" "thread")
option(FREEZERAY_FUZZ "Build the libFuzzer targets of tests/fuzz (requires Clang)" OFF)

if(FREEZERAY_FUZZ)
  if(NOT CMAKE_CXX_COMPILER_ID MATCHES "Clang")
    message(FATAL_ERROR "FREEZERAY_FUZZ needs Clang with libFuzzer, for example "
                        "CC=clang-14 CXX=clang++-14 cmake -S . -B build-fuzz -DFREEZERAY_FUZZ=ON")
  endif()
  if(NOT FREEZERAY_SANITIZE)
    set(FREEZERAY_SANITIZE "address,undefined" CACHE STRING
        "Build everything with sanitizers: empty (none), address,undefined, or thread" FORCE)
  elseif(FREEZERAY_SANITIZE MATCHES "thread")
    message(FATAL_ERROR "FREEZERAY_FUZZ works with address and undefined, not with thread")
  endif()
endif()

if(FREEZERAY_SANITIZE)
  string(REPLACE "," ";" freezeray_sanitizer_list "${FREEZERAY_SANITIZE}")
  foreach(sanitizer IN LISTS freezeray_sanitizer_list)
    if(NOT sanitizer MATCHES "^(address|undefined|thread|leak)$")
      message(FATAL_ERROR "FREEZERAY_SANITIZE: unknown sanitizer '${sanitizer}' "
                          "(expected address,undefined or thread)")
    endif()
  endforeach()
  if("thread" IN_LIST freezeray_sanitizer_list AND "address" IN_LIST freezeray_sanitizer_list)
    message(FATAL_ERROR "FREEZERAY_SANITIZE: thread and address cannot be combined")
  endif()
  add_compile_options(-fsanitize=${FREEZERAY_SANITIZE} -fno-omit-frame-pointer)
  add_link_options(-fsanitize=${FREEZERAY_SANITIZE})
  if("undefined" IN_LIST freezeray_sanitizer_list)
    add_compile_options(-fno-sanitize-recover=undefined)
  endif()
  message(STATUS "FreezeRay: sanitizers ${FREEZERAY_SANITIZE} on every target")
endif()

if(FREEZERAY_FUZZ)
  # Coverage feedback for libFuzzer in all our code; the fuzz targets link -fsanitize=fuzzer.
  add_compile_options(-fsanitize=fuzzer-no-link)
  add_link_options(-fsanitize=fuzzer-no-link)
endif()
