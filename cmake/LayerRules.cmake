# The layer rules of docs/architecture.md, checked on the sources (configure time and CTest) and on
# the link interface (configure time). Bottom up: engine, document, then services and widgets side by
# side, then cli (on the services) and gui (on both).

# The #include "..." paths each layer must not use: the layers above it.
set(MX_LAYER_FORBIDDEN_document "^(cli|gui|services|widgets)/|main_window")
set(MX_LAYER_FORBIDDEN_services "^(cli|gui|widgets)/|main_window")
set(MX_LAYER_FORBIDDEN_widgets "^(cli|gui|services)/|main_window")
set(MX_LAYER_FORBIDDEN_gui "^cli/")

# mx_find_layer_violations(LAYER DIR OUT_VAR): "file: #include "x"" for every forbidden include.
function(mx_find_layer_violations layer dir out_var)
  set(_forbidden "${MX_LAYER_FORBIDDEN_${layer}}")
  if(_forbidden STREQUAL "")
    message(FATAL_ERROR "no layer rule for '${layer}'")
  endif()
  file(GLOB_RECURSE _sources ${dir}/*.cpp ${dir}/*.h)
  set(_bad "")
  foreach(_src IN LISTS _sources)
    file(STRINGS ${_src} _includes REGEX "^[ \t]*#[ \t]*include[ \t]*\"")
    foreach(_line IN LISTS _includes)
      string(REGEX REPLACE "^[^\"]*\"([^\"]*)\".*$" "\\1" _path "${_line}")
      if(_path MATCHES "${_forbidden}")
        list(APPEND _bad "${_src}: #include \"${_path}\"")
      endif()
    endforeach()
  endforeach()
  set(${out_var} "${_bad}" PARENT_SCOPE)
endfunction()

# mx_check_layer(LAYER DIR TARGET [FORBIDDEN_LINKS regex]): fails the configure step on a violation.
function(mx_check_layer layer dir target)
  cmake_parse_arguments(L "" "FORBIDDEN_LINKS" "" ${ARGN})
  mx_find_layer_violations(${layer} ${dir} _bad)
  if(_bad)
    string(REPLACE ";" "\n  " _text "${_bad}")
    message(FATAL_ERROR "layer '${layer}' includes a header it must not use (docs/architecture.md):\n  ${_text}")
  endif()
  if(L_FORBIDDEN_LINKS)
    get_target_property(_libs ${target} LINK_LIBRARIES)
    foreach(_lib IN LISTS _libs)
      if(_lib MATCHES "${L_FORBIDDEN_LINKS}")
        message(FATAL_ERROR "${target} (layer '${layer}') must not link ${_lib}")
      endif()
    endforeach()
  endif()
endfunction()
