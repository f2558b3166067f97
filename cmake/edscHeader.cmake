# edsc_add_header(TARGET tgt EDS path/device.eds [OUTPUT name.h] [PREFIX P]
#                 [SERIAL N] [TEMPLATE_DIR dir])
#
# Generates the firmware header of `EDS` at build time into
# <binary dir>/edsc/<tgt>/, adds that folder to tgt's include path and makes
# tgt depend on the header, which is regenerated whenever the EDS (or edsc)
# changes. OUTPUT defaults to the EDS base name with `.h`.
# After cmake_parse_arguments(... arg ...) in the caller: no stray arguments,
# and every named keyword given.
macro(_edsc_require_arguments fn)
  if(arg_UNPARSED_ARGUMENTS)
    message(FATAL_ERROR "${fn}: unexpected arguments: ${arg_UNPARSED_ARGUMENTS}")
  endif()
  foreach(_edsc_keyword ${ARGN})
    if(NOT arg_${_edsc_keyword})
      message(FATAL_ERROR "${fn}: ${ARGN} are required")
    endif()
  endforeach()
endmacro()

function(edsc_add_header)
  cmake_parse_arguments(PARSE_ARGV 0 arg "" "TARGET;EDS;OUTPUT;PREFIX;SERIAL;TEMPLATE_DIR" "")
  _edsc_require_arguments(edsc_add_header TARGET EDS)
  if(NOT TARGET ${arg_TARGET})
    message(FATAL_ERROR "edsc_add_header: ${arg_TARGET} is not a target")
  endif()
  get_filename_component(eds "${arg_EDS}" ABSOLUTE BASE_DIR "${CMAKE_CURRENT_SOURCE_DIR}")
  if(NOT arg_OUTPUT)
    get_filename_component(arg_OUTPUT "${eds}" NAME_WE)
    string(APPEND arg_OUTPUT ".h")
  endif()
  set(dir "${CMAKE_CURRENT_BINARY_DIR}/edsc/${arg_TARGET}")
  set(out "${dir}/${arg_OUTPUT}")
  set(options)
  if(DEFINED arg_PREFIX)
    list(APPEND options --prefix "${arg_PREFIX}")
  endif()
  if(DEFINED arg_SERIAL)
    list(APPEND options --serial "${arg_SERIAL}")
  endif()
  set(template_deps)
  if(arg_TEMPLATE_DIR)
    get_filename_component(tdir "${arg_TEMPLATE_DIR}" ABSOLUTE BASE_DIR "${CMAKE_CURRENT_SOURCE_DIR}")
    list(APPEND options --template-dir "${tdir}")
    file(GLOB template_deps CONFIGURE_DEPENDS "${tdir}/*.mustache")
  endif()
  add_custom_command(OUTPUT "${out}"
    COMMAND edsc::edsc header "${eds}" -o "${out}" ${options}
    DEPENDS "${eds}" "$<TARGET_FILE:edsc::edsc>" ${template_deps}
    COMMENT "edsc: generating ${arg_OUTPUT} from ${arg_EDS}"
    VERBATIM)
  # Listing the header as a source makes the target wait for (and track) it.
  target_sources(${arg_TARGET} PRIVATE "${out}")
  target_include_directories(${arg_TARGET} PUBLIC "${dir}")
endfunction()

# edsc_add_opener_stack(EDS path/device.eds OPENER_SOURCE_DIR dir [DIR out])
#
# Adds OpENer's POSIX port built with the application `edsc header --stack
# opener` generates from `EDS` (target `OpENer`, docs/header.md "OpENer").
# OpENer takes its identity from cache variables when it is configured, so
# generation happens at configure time: the EDS is a configure dependency and
# editing it re-runs CMake, which regenerates DIR (default
# <binary dir>/edsc-opener) and rebuilds what changed. Unchanged files are not
# rewritten, so a reconfigure without an EDS change rebuilds nothing.
function(edsc_add_opener_stack)
  cmake_parse_arguments(PARSE_ARGV 0 arg "" "EDS;OPENER_SOURCE_DIR;DIR" "")
  _edsc_require_arguments(edsc_add_opener_stack EDS OPENER_SOURCE_DIR)
  get_filename_component(eds "${arg_EDS}" ABSOLUTE BASE_DIR "${CMAKE_CURRENT_SOURCE_DIR}")
  get_filename_component(opener "${arg_OPENER_SOURCE_DIR}" ABSOLUTE BASE_DIR "${CMAKE_CURRENT_SOURCE_DIR}")
  if(NOT arg_DIR)
    set(arg_DIR "${CMAKE_CURRENT_BINARY_DIR}/edsc-opener")
  endif()
  get_target_property(exe edsc::edsc IMPORTED_LOCATION)
  if(NOT exe)
    set(exe "${EDSC_EXECUTABLE}")
  endif()
  set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS "${eds}" "${exe}")
  execute_process(COMMAND "${exe}" header --stack opener "${eds}" -o "${arg_DIR}"
                  RESULT_VARIABLE rc ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "edsc_add_opener_stack: OpENer cannot serve ${arg_EDS}:\n${err}")
  endif()
  set(OPENER_SOURCE_DIR "${opener}" CACHE PATH "OpENer's source folder" FORCE)
  add_subdirectory("${arg_DIR}" edsc-opener-build)
endfunction()
