# Every dependency comes from a Debian 12 package (see README.md, "Dependencies").
find_package(Threads REQUIRED)
find_package(glm REQUIRED)                 # libglm-dev
find_package(nlohmann_json 3 REQUIRED)     # nlohmann-json3-dev
find_package(CLI11 REQUIRED)               # libcli11-dev
find_package(tinyobjloader REQUIRED)       # libtinyobjloader-dev
find_package(OpenEXR 3 REQUIRED)           # libopenexr-dev (OpenEXR 3.1 on Debian 12)
find_package(PkgConfig REQUIRED)
pkg_check_modules(STB REQUIRED IMPORTED_TARGET stb)   # libstb-dev
if(FREEZERAY_BUILD_TESTS)
  find_package(Catch2 2 REQUIRED)          # catch2 (v2)
endif()
find_package(Python3 REQUIRED COMPONENTS Interpreter)
