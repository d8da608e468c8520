# freezeray_set_warnings(target): the project's warning level, applied to our own code only.
function(freezeray_set_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wshadow=local)
  # No a * b + c fused into one rounding behind the code's back: chapter 07's vector triangle test
  # must give the scalar test's t to the bit, and with -march=native (or -mavx512f, which implies
  # FMA, for the AVX-512 kernel) g++ would fuse in one path and not the other. The default x86-64
  # target has no FMA, so this changes nothing there.
  target_compile_options(${target} PRIVATE -ffp-contract=off)
  # A student copy (tests/grading/make_student_copy.py marks its root with .freezeray-student-copy):
  # each stub leaves unused the parameters, locals and helper functions its region used, and those
  # warnings would look like the student's mistakes; they are off there, every other warning stays.
  if(EXISTS ${PROJECT_SOURCE_DIR}/.freezeray-student-copy)
    target_compile_options(${target} PRIVATE -Wno-unused-parameter -Wno-unused-variable -Wno-unused-but-set-variable
                                             -Wno-unused-function)
  endif()
  if(FREEZERAY_WERROR)
    target_compile_options(${target} PRIVATE -Werror)
  endif()
  if(FREEZERAY_NATIVE)
    target_compile_options(${target} PRIVATE -march=native)
  endif()
endfunction()
