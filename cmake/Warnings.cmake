# freezeray_set_warnings(target): the project's warning level, applied to our own code only.
function(freezeray_set_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wshadow=local)
  # No a * b + c fused into one rounding behind the code's back: chapter 07's vector triangle test
  # must give the scalar test's t to the bit, and with -march=native (or -mavx512f, which implies
  # FMA, for the AVX-512 kernel) g++ would fuse in one path and not the other. The default x86-64
  # target has no FMA, so this changes nothing there.
  target_compile_options(${target} PRIVATE -ffp-contract=off)
  # (A student copy compiles with these same options: make_student_copy.py turns off, by pragmas
  # in the stubbed files alone, the warnings of what a stub leaves unused, so that every other
  # file's object comes from the compiler cache.)
  if(FREEZERAY_WERROR)
    target_compile_options(${target} PRIVATE -Werror)
  endif()
  if(FREEZERAY_NATIVE)
    target_compile_options(${target} PRIVATE -march=native)
  endif()
endfunction()
