# What a desktop needs from the .deb (README "Install"): the desktop entry, the MIME type of .mxproj
# files, and the application icon, scalable and as PNGs rendered at build time by millexpert-render-icon.
install(FILES ${CMAKE_CURRENT_LIST_DIR}/millexpert.desktop DESTINATION share/applications)
install(FILES ${CMAKE_CURRENT_LIST_DIR}/millexpert-mime.xml DESTINATION share/mime/packages RENAME millexpert.xml)

set(_mx_icon_svg ${PROJECT_SOURCE_DIR}/resources/icons/millexpert.svg)
install(FILES ${_mx_icon_svg} DESTINATION share/icons/hicolor/scalable/apps)

add_executable(millexpert-render-icon ${CMAKE_CURRENT_LIST_DIR}/render_icon_main.cpp)
target_link_libraries(millexpert-render-icon PRIVATE Qt6::Gui Qt6::Svg)
mx_set_warnings(millexpert-render-icon)
set(MX_ICON_SIZES 16 24 32 48 64 128 256)
set(_mx_icon_pngs "")
foreach(_size IN LISTS MX_ICON_SIZES)
  set(_png ${PROJECT_BINARY_DIR}/packaging/icons/${_size}x${_size}/millexpert.png)
  # detect_leaks=0: a sanitizer build (preset asan) runs the renderer too, without the tests' suppressions.
  add_custom_command(OUTPUT ${_png}
                     COMMAND ${CMAKE_COMMAND} -E env ASAN_OPTIONS=detect_leaks=0
                             $<TARGET_FILE:millexpert-render-icon> ${_mx_icon_svg} ${_size} ${_png}
                     DEPENDS millexpert-render-icon ${_mx_icon_svg} COMMENT "Icon ${_size}x${_size}" VERBATIM)
  list(APPEND _mx_icon_pngs ${_png})
  install(FILES ${_png} DESTINATION share/icons/hicolor/${_size}x${_size}/apps)
endforeach()
add_custom_target(millexpert_icons ALL DEPENDS ${_mx_icon_pngs})
