# edsc_add_header(TARGET tgt EDS path/device.eds [OUTPUT name.h] [PREFIX P]
#                 [SERIAL N] [TEMPLATE_DIR dir])
#
# Generates the firmware header of `EDS` at build time into
# <binary dir>/edsc/<tgt>/, adds that folder to tgt's include path and makes
# tgt depend on the header, which is regenerated whenever the EDS (or edsc)
# changes. OUTPUT defaults to the EDS base name with `.h`.
function(edsc_add_header)
  cmake_parse_arguments(PARSE_ARGV 0 arg "" "TARGET;EDS;OUTPUT;PREFIX;SERIAL;TEMPLATE_DIR" "")
  if(arg_UNPARSED_ARGUMENTS)
    message(FATAL_ERROR "edsc_add_header: unexpected arguments: ${arg_UNPARSED_ARGUMENTS}")
  endif()
  if(NOT arg_TARGET OR NOT arg_EDS)
    message(FATAL_ERROR "edsc_add_header: TARGET and EDS are required")
  endif()
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
