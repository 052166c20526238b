# Proves check_clang_format.cmake names a misformatted file: copies SAMPLE (a .cpp.in) as a .cpp and
# the repository's .clang-format into a fresh WORK_DIR, then runs the check there; the CTest entry
# matches the check's report, which names the file.
#   cmake -DCLANG_FORMAT=exe -DSAMPLE=file.cpp.in -DSTYLE=.clang-format -DWORK_DIR=dir -P check_clang_format_detects.cmake
cmake_minimum_required(VERSION 3.25)
file(REMOVE_RECURSE ${WORK_DIR})
get_filename_component(_name ${SAMPLE} NAME)
string(REGEX REPLACE "\\.in$" "" _name ${_name})
configure_file(${SAMPLE} ${WORK_DIR}/${_name} COPYONLY)
configure_file(${STYLE} ${WORK_DIR}/.clang-format COPYONLY)
execute_process(COMMAND ${CMAKE_COMMAND} -DCLANG_FORMAT=${CLANG_FORMAT} -DSCAN_DIR=${WORK_DIR}
                -P ${CMAKE_CURRENT_LIST_DIR}/check_clang_format.cmake RESULT_VARIABLE _rc)
file(REMOVE_RECURSE ${WORK_DIR})
if(_rc EQUAL 0)
  message(FATAL_ERROR "the format check passed a misformatted ${_name}")
endif()
message(STATUS "the format check failed on ${_name}, as it should")
