# A compiler cache (ccache, the Debian package) in front of the compiler when it is installed:
# a translation unit whose source, headers and options are unchanged is not compiled again.
#
# It also lets a copy of the tree reuse this build's objects. Paths under the source folder are
# made relative to the compiling folder (CCACHE_BASEDIR), and the compiling folder is not
# hashed (CCACHE_NOHASHDIR), so a copy of the tree whose build folder sits at the same place
# within it (the grading proof's student copy, tests/grading/prove_exercises.py) compiles only
# the files that differ: those holding exercise regions, and whatever includes them. ccache keys
# an object by the contents of everything it was compiled from, so an object can never be stale.
option(FREEZERAY_COMPILER_CACHE "Compile through ccache when it is installed" ON)
if(FREEZERAY_COMPILER_CACHE AND NOT CMAKE_CXX_COMPILER_LAUNCHER)
  find_program(FREEZERAY_CCACHE ccache)
  if(FREEZERAY_CCACHE)
    set(CMAKE_CXX_COMPILER_LAUNCHER
        ${CMAKE_COMMAND} -E env CCACHE_BASEDIR=${PROJECT_SOURCE_DIR} CCACHE_NOHASHDIR=1 ${FREEZERAY_CCACHE})
    message(STATUS "Compiling through ${FREEZERAY_CCACHE}")
  endif()
endif()
