# SPDX-License-Identifier: MIT
# cmake --install: component "core" (the library as libtristream.a, its headers with the
# configuration it was built with in tristream/config_build.h, the CMake package tristream::core
# with its version file, and tristream.pc), component "tools" (trisim, tripack, triencode, tribaseline; none in
# a TRISTREAM_CORE_ONLY build). Consumers: find_package(tristream CONFIG) or pkg-config tristream.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

# The installed tristream/config_build.h records the TRISTREAM_<knob> cache variables; a TS_ knob
# defined in CMAKE_C_FLAGS or CMAKE_CXX_FLAGS would build a core that it does not describe.
foreach(lang C CXX)
  if(CMAKE_${lang}_FLAGS MATCHES "-DTS_(SUBPIXEL_BITS|MAX_DIMENSION|GRADIENT_FRAC_BITS|MAX_GRADIENT|PIXEL_FORMATS|METHODS|COLOR_SPACES|LAYERED)")
    message(FATAL_ERROR "CMAKE_${lang}_FLAGS defines TS_${CMAKE_MATCH_1}: set the cache variable "
            "TRISTREAM_${CMAKE_MATCH_1} instead (-DTRISTREAM_${CMAKE_MATCH_1}=...), which builds the core with it "
            "and records it in the installed tristream/config_build.h")
  endif()
endforeach()

set_target_properties(ts_core PROPERTIES EXPORT_NAME core OUTPUT_NAME tristream)
install(TARGETS ts_core EXPORT tristreamTargets ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR} COMPONENT core)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/firmware_core/include/tristream DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}
        COMPONENT core PATTERN config.h EXCLUDE)
# config.h with TRISTREAM_INSTALLED_CONFIG 1, and config_build.h (firmware_core/CMakeLists.txt).
install(FILES ${tristream_installed_include}/config.h ${tristream_installed_include}/config_build.h
        DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/tristream COMPONENT core)

# The package's record of the configuration (tristreamConfig.cmake sets tristream_<knob>).
set(tristream_recorded "")
foreach(knob SUBPIXEL_BITS MAX_DIMENSION GRADIENT_FRAC_BITS MAX_GRADIENT PIXEL_FORMATS METHODS COLOR_SPACES LAYERED)
  string(APPEND tristream_recorded "set(tristream_${knob} ${tristream_config_${knob}})\n")
endforeach()
string(STRIP "${TRISTREAM_ARM_FLAGS}" tristream_arm_flags)
string(APPEND tristream_recorded "set(tristream_ARM_FLAGS \"${tristream_arm_flags}\")\n"
       "set(tristream_CPU \"${tristream_config_CPU}\")\nset(tristream_FLOAT_ABI \"${tristream_config_FLOAT_ABI}\")\n")

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

if(NOT TRISTREAM_CORE_ONLY)
  install(TARGETS trisim tripack triencode tribaseline RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR} COMPONENT tools)
endif()
