# Reads compiler/layers.txt, the table of rooms and the rooms each may use
# (its own comment says how it reads): EDSC_ROOMS lists the rooms top to
# bottom, EDSC_ROOM_USES_<room> the rooms on its line. The `never` lines are
# tests/layers' to check.
function(edsc_read_layers table)
  set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${table})
  file(STRINGS ${table} lines)
  set(rooms)
  foreach(line IN LISTS lines)
    if(line MATCHES "^[ \t]*(#|$)" OR line MATCHES "^never ")
      continue()
    endif()
    if(NOT line MATCHES "^([a-z_]+):[ \t]*(.*)$")
      message(FATAL_ERROR "${table}: not a line of the table: ${line}")
    endif()
    set(room ${CMAKE_MATCH_1})
    string(REGEX REPLACE "[ \t]+" ";" uses "${CMAKE_MATCH_2}")
    list(REMOVE_ITEM uses "")
    list(APPEND rooms ${room})
    set(EDSC_ROOM_USES_${room} ${uses} PARENT_SCOPE)
  endforeach()
  set(EDSC_ROOMS ${rooms} PARENT_SCOPE)
endfunction()
