# nlohmann_json for the wasm preset, from the Debian package, with nothing downloaded.
#
# Under emscripten's toolchain find_package looks only inside emscripten's sysroot, so the
# Debian package's config (/usr/share/cmake/nlohmann_json) is not found; and using it anyway
# would add /usr/include, whose glibc headers must never reach an emscripten compile. The
# library is header-only and includes nothing outside the standard library, so its own folder
# (nlohmann/) is copied into the build tree and an interface target points there alone.
find_path(CAROM_NLOHMANN_JSON_INCLUDE_DIR nlohmann/json.hpp
  PATHS /usr/include /usr/local/include NO_DEFAULT_PATH NO_CMAKE_FIND_ROOT_PATH)
if(NOT CAROM_NLOHMANN_JSON_INCLUDE_DIR)
  message(FATAL_ERROR "carom: nlohmann/json.hpp not found for the wasm build; install it with:\n"
                      "  sudo apt-get install -y nlohmann-json3-dev")
endif()

set(version_header ${CAROM_NLOHMANN_JSON_INCLUDE_DIR}/nlohmann/detail/abi_macros.hpp)
if(NOT EXISTS ${version_header})
  set(version_header ${CAROM_NLOHMANN_JSON_INCLUDE_DIR}/nlohmann/json.hpp)
endif()
file(STRINGS ${version_header} version_lines REGEX "#define NLOHMANN_JSON_VERSION_(MAJOR|MINOR) ")
string(REGEX REPLACE ".*MAJOR ([0-9]+).*" "\\1" json_major "${version_lines}")
string(REGEX REPLACE ".*MINOR ([0-9]+).*" "\\1" json_minor "${version_lines}")
if("${json_major}.${json_minor}" VERSION_LESS 3.11)
  message(FATAL_ERROR "carom: nlohmann_json 3.11 or newer is needed; "
                      "${CAROM_NLOHMANN_JSON_INCLUDE_DIR} has ${json_major}.${json_minor}")
endif()

set(copied_include_dir ${CMAKE_BINARY_DIR}/nlohmann_json/include)
file(COPY ${CAROM_NLOHMANN_JSON_INCLUDE_DIR}/nlohmann DESTINATION ${copied_include_dir})
add_library(nlohmann_json::nlohmann_json INTERFACE IMPORTED)
set_target_properties(nlohmann_json::nlohmann_json PROPERTIES
  INTERFACE_INCLUDE_DIRECTORIES ${copied_include_dir}
  INTERFACE_SYSTEM_INCLUDE_DIRECTORIES ${copied_include_dir})
