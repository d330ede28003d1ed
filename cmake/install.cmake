# SPDX-License-Identifier: MIT
# cmake --install: component "core" (the library as libtristream.a, its headers, the CMake
# package tristream::core with its version file, and tristream.pc), component "tools" (trisim,
# tripack, triencode). Consumers: find_package(tristream CONFIG) or pkg-config tristream.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

set_target_properties(ts_core PROPERTIES EXPORT_NAME core OUTPUT_NAME tristream)
install(TARGETS ts_core EXPORT tristreamTargets ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR} COMPONENT core)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/firmware_core/include/tristream DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}
        COMPONENT core)

set(tristream_cmake_dir ${CMAKE_INSTALL_LIBDIR}/cmake/tristream)
install(EXPORT tristreamTargets NAMESPACE tristream:: DESTINATION ${tristream_cmake_dir} COMPONENT core)
configure_package_config_file(${CMAKE_CURRENT_LIST_DIR}/tristreamConfig.cmake.in
                              ${PROJECT_BINARY_DIR}/tristreamConfig.cmake INSTALL_DESTINATION ${tristream_cmake_dir})
# 0.x: a minor release may break the API, so only the same major.minor is compatible.
write_basic_package_version_file(${PROJECT_BINARY_DIR}/tristreamConfigVersion.cmake
                                 VERSION ${PROJECT_VERSION} COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/tristreamConfig.cmake ${PROJECT_BINARY_DIR}/tristreamConfigVersion.cmake
        DESTINATION ${tristream_cmake_dir} COMPONENT core)
# tristream_add_golden_test, which the config file includes.
include(${CMAKE_CURRENT_LIST_DIR}/install_golden.cmake)

# Relocatable: the prefix is found from the .pc file's own place (pkg-config's pcfiledir), so the
# tree works wherever --prefix put it.
if(IS_ABSOLUTE "${CMAKE_INSTALL_LIBDIR}")
  set(tristream_pc_prefix "${CMAKE_INSTALL_PREFIX}")
else()
  file(RELATIVE_PATH tristream_pc_up "/p/${CMAKE_INSTALL_LIBDIR}/pkgconfig" "/p")
  set(tristream_pc_prefix "\${pcfiledir}/${tristream_pc_up}")
endif()
configure_file(${CMAKE_CURRENT_LIST_DIR}/tristream.pc.in ${PROJECT_BINARY_DIR}/tristream.pc @ONLY)
install(FILES ${PROJECT_BINARY_DIR}/tristream.pc DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig COMPONENT core)

install(TARGETS trisim tripack triencode RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR} COMPONENT tools)
