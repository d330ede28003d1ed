# SPDX-License-Identifier: MIT
# The variants of the benchmark programs, for m4/ and riscv/ alike: for each optimisation level
# and method a program for RGB blobs, bench_<opt>_<method>, and one for grey blobs,
# bench_<opt>_<method>_grey, each with a core of one format (RGB565 BE), that method and that
# colour space.
# bench_variant(<opt> <method> <rgb|grey>) sets, in the caller's scope, `name` (<opt>_<method>
# or <opt>_<method>_grey), `method_bit` (TS_METHODS) and `spaces` (TS_COLOR_SPACES).
function(bench_variant opt method space)
  if(method STREQUAL "bilinear")
    set(method_bit 0x1 PARENT_SCOPE)
  else()
    set(method_bit 0x2 PARENT_SCOPE)
  endif()
  if(space STREQUAL "rgb")
    set(name ${opt}_${method} PARENT_SCOPE)
    set(spaces 0x2 PARENT_SCOPE)
  else()
    set(name ${opt}_${method}_grey PARENT_SCOPE)
    set(spaces 0x1 PARENT_SCOPE)
  endif()
endfunction()
