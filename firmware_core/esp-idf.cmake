# SPDX-License-Identifier: MIT
# firmware_core as an ESP-IDF component: CMakeLists.txt includes this file when ESP-IDF builds the
# folder. Every source of src/ (all C++), the public headers' folder, and C++17 for the component's
# own files: placed after ESP-IDF's global -std, this option is the one that counts.
# The TS_* settings of tristream/config.h are the component's compile definitions, which the project
# adds: idf_component_get_property(lib tristream COMPONENT_LIB), then
# target_compile_definitions(${lib} PUBLIC TS_PIXEL_FORMATS=0x08).
idf_component_register(SRCS src/blob.cpp src/compressed_blob.cpp src/render.cpp src/compressed_render.cpp
                            src/c_api.cpp src/compressed_c_api.cpp src/crc32.cpp
                       INCLUDE_DIRS include)
target_compile_options(${COMPONENT_LIB} PRIVATE -std=gnu++17 -fno-exceptions -fno-rtti)
