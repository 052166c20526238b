# Section 1 man pages of the four programs, generated from their --help by help2man (packaging/bootstrap.sh
# installs it) and installed gzipped, as Debian does. The version is project()'s: the window's --version
# says "MillExpert", and the man page's name must be the command's.
find_program(MX_HELP2MAN help2man)
if(NOT MX_HELP2MAN)
  message(FATAL_ERROR "help2man is missing; bash packaging/bootstrap.sh installs what is missing")
endif()

set(_mx_man_pages "")
# mx_man_page(TARGET NAME): man1/TARGET.1.gz, NAME being the one-line summary of its NAME section.
function(mx_man_page target name)
  set(_page ${PROJECT_BINARY_DIR}/packaging/man/${target}.1)
  # detect_leaks=0: a sanitizer build (preset asan) runs the programs too, without the tests' suppressions.
  add_custom_command(OUTPUT ${_page}.gz
                     COMMAND ${CMAKE_COMMAND} -E env ASAN_OPTIONS=detect_leaks=0
                             ${MX_HELP2MAN} --no-info --section=1 --name=${name}
                             --version-string=${PROJECT_VERSION} --output=${_page}
                             $<TARGET_FILE:${target}>
                     COMMAND gzip -9nf ${_page}
                     DEPENDS ${target} COMMENT "Man page ${target}.1" VERBATIM)
  install(FILES ${_page}.gz DESTINATION share/man/man1)
  set(_mx_man_pages ${_mx_man_pages} ${_page}.gz PARENT_SCOPE)
endfunction()

mx_man_page(millexpert "milling stability lobes, expert tool selection and control (the window)")
mx_man_page(millexpert-cli "every MillExpert computation from the command line, with JSON on stdout")
mx_man_page(millexpert-report "the expert report of a MillExpert project as PDF or HTML")
mx_man_page(millexpert-plot "charts of millexpert-cli lobes and control results as PNG or PDF")
add_custom_target(millexpert_man_pages ALL DEPENDS ${_mx_man_pages})
