# SPDX-License-Identifier: MIT
# Installs tristreamGolden.cmake (tristream_add_golden_test), which the package's config file
# includes. It finds the trisim of the component "tools" by the path from its own directory, so
# the installed tree works wherever --prefix put it.
if(IS_ABSOLUTE "${CMAKE_INSTALL_BINDIR}")
  set(tristream_golden_trisim_rel "${CMAKE_INSTALL_BINDIR}/trisim")
elseif(IS_ABSOLUTE "${tristream_cmake_dir}")
  set(tristream_golden_trisim_rel "${CMAKE_INSTALL_PREFIX}/${CMAKE_INSTALL_BINDIR}/trisim")
else()
  file(RELATIVE_PATH tristream_golden_trisim_rel "/p/${tristream_cmake_dir}" "/p/${CMAKE_INSTALL_BINDIR}/trisim")
endif()
configure_file(${CMAKE_CURRENT_LIST_DIR}/tristreamGolden.cmake.in ${PROJECT_BINARY_DIR}/tristreamGolden.cmake @ONLY)
install(FILES ${PROJECT_BINARY_DIR}/tristreamGolden.cmake DESTINATION ${tristream_cmake_dir} COMPONENT core)
