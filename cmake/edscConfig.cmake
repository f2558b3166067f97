# Package file of an installed edsc: the `edsc::edsc` executable and
# edsc_add_header() (see docs/header.md). Locations are relative to this file,
# so the installed tree can be moved.
get_filename_component(_edsc_prefix "${CMAKE_CURRENT_LIST_DIR}/../../.." ABSOLUTE)
if(NOT TARGET edsc::edsc)
  add_executable(edsc::edsc IMPORTED)
  set_target_properties(edsc::edsc PROPERTIES IMPORTED_LOCATION "${_edsc_prefix}/bin/edsc")
endif()
set(EDSC_EXECUTABLE "${_edsc_prefix}/bin/edsc")
set(EDSC_TEMPLATE_DIR "${_edsc_prefix}/share/edsc/templates")
unset(_edsc_prefix)
include("${CMAKE_CURRENT_LIST_DIR}/edscHeader.cmake")
set(edsc_FOUND TRUE)
