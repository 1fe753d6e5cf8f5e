# `cmake --install build --prefix P`: both programs in P/bin, the built-in scenes and the compiled
# translations in P/share/tactile-workbench, a desktop file and the icon (SVG and PNG sizes) under
# P/share. The programs carry their scenes and translations inside, so an installed copy works
# without the source tree; the installed copies are there to read and to add languages without a
# rebuild (the workbench looks in P/share/tactile-workbench/translations after its own).
include(GNUInstallDirs)
set(TACTILE_SHARE_DIR ${CMAKE_INSTALL_DATADIR}/tactile-workbench)

install(TARGETS tactile tactile-workbench RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})

file(GLOB TACTILE_INSTALL_SCENES CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/resources/scenes/*.json)
install(FILES ${TACTILE_INSTALL_SCENES} DESTINATION ${TACTILE_SHARE_DIR}/scenes)

# The .qm files lrelease writes next to this directory's build files, one per .ts file.
foreach(ts IN LISTS TACTILE_TS_FILES)
  get_filename_component(qm_name ${ts} NAME_WE)
  install(FILES ${CMAKE_CURRENT_BINARY_DIR}/${qm_name}.qm DESTINATION ${TACTILE_SHARE_DIR}/translations)
endforeach()

install(FILES ${PROJECT_SOURCE_DIR}/resources/tactile-workbench.desktop
        DESTINATION ${CMAKE_INSTALL_DATADIR}/applications)
set(TACTILE_ICON_DIR ${CMAKE_INSTALL_DATADIR}/icons/hicolor)
install(FILES ${PROJECT_SOURCE_DIR}/resources/icons/tactile-workbench.svg
        DESTINATION ${TACTILE_ICON_DIR}/scalable/apps)
foreach(size 16 32 48 64 128 256)
  install(FILES ${PROJECT_SOURCE_DIR}/resources/icons/tactile-workbench-${size}.png
          DESTINATION ${TACTILE_ICON_DIR}/${size}x${size}/apps RENAME tactile-workbench.png)
endforeach()
