# SPDX-License-Identifier: MIT
# cmake -DIN=<blob.bin> -DOUT=<file.c> -P bin_to_c.cmake: the blob as `const uint8_t golden_blob[]`.
file(READ ${IN} hex HEX)
string(LENGTH "${hex}" n)
math(EXPR size "${n} / 2")
string(REGEX REPLACE "([0-9a-f][0-9a-f])" "0x\\1," body "${hex}")
file(WRITE ${OUT} "#include <stddef.h>\n#include <stdint.h>\nconst uint8_t golden_blob[${size}] = {${body}};\nconst size_t golden_blob_size = ${size};\n")
