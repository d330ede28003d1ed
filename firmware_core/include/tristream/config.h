/* SPDX-License-Identifier: MIT */
/* Every compile-time knob of the core, with its default. Override by defining the macro before
   this header is included (e.g. -DTS_SUBPIXEL_BITS=4), and build the core and everything that
   includes its headers with the same definitions (the CMake targets carry them); blobs record the
   values that change their layout (see blob_config_hash), and the core rejects a blob packed for
   another configuration. The macros are valid C89 through C2x and C++98 onward (tristream.h
   includes this file); the typed constants at the end need C++17, the core's language. */
#ifndef TRISTREAM_CONFIG_H
#define TRISTREAM_CONFIG_H

#include <stdint.h>

/* An installed core (cmake --install) records the configuration and the CPU it was built with in
   tristream/config_build.h, which its copy of this header includes (TRISTREAM_INSTALLED_CONFIG 1):
   the knobs below then take the library's values, a file that defines one otherwise is refused,
   and so is a file compiled for another CPU or FPU calling convention. The source tree has no such file. */
#define TRISTREAM_INSTALLED_CONFIG 0
#if TRISTREAM_INSTALLED_CONFIG
#include "tristream/config_build.h"
#endif

/* Sub-pixel bits of vertex positions (format fx28_4 by default). Positions, edge functions and
   their bit budget are in docs/FIXED_POINT.md. With 4 bits and TS_MAX_DIMENSION 2048 every
   coordinate difference fits 16 bits (signed) and every edge function value at a sample point is
   below 2^31 in magnitude (the setup computes it in int64). */
#ifndef TS_SUBPIXEL_BITS
#define TS_SUBPIXEL_BITS 4
#endif

/* Largest width or height, of the triangulation's domain and of the output, in pixels. */
#ifndef TS_MAX_DIMENSION
#define TS_MAX_DIMENSION 2048
#endif

/* Fraction bits of the per-vertex gradients stored for zienkiewicz (format q19_12). */
#ifndef TS_GRADIENT_FRAC_BITS
#define TS_GRADIENT_FRAC_BITS 12
#endif

/* Largest magnitude of a stored gradient component, in value units (0..255) per domain pixel. */
#ifndef TS_MAX_GRADIENT
#define TS_MAX_GRADIENT 32767
#endif

/* Pixel formats compiled into the core, one bit per PixelFormat value: bit 0 L8, 1 RGB888,
   2 RGB565 little-endian, 3 RGB565 big-endian, 4 XRGB8888, 5 coverage counts (a test aid, not in
   the default set nor in the C API). Firmware that drives one display saves the flash of the
   other formats' code; asking for a format that is not compiled in returns Status::not_compiled. */
#ifndef TS_PIXEL_FORMATS
#define TS_PIXEL_FORMATS 0x1F
#endif

/* Interpolation methods compiled in: bit 0 bilinear, bit 1 zienkiewicz. A blob of another
   method gives Status::not_compiled when rendered. */
#ifndef TS_METHODS
#define TS_METHODS 0x3
#endif

/* Colour spaces compiled in, one bit per ColorSpace value: bit 0 grey, bit 1 RGB, bit 2 YCbCr;
   and 1 to compile in blobs of one mesh per channel (three layers, `--color separate`), 0 for
   blobs of one mesh only. Each colour space and the layered path is its own copy of the
   rasterizer and shader for each format and method: firmware that shows one kind of picture
   keeps one copy. A blob of a colour space or layering left out gives Status::not_compiled when
   rendered. */
#ifndef TS_COLOR_SPACES
#define TS_COLOR_SPACES 0x7
#endif
#ifndef TS_LAYERED
#define TS_LAYERED 1
#endif

/* 1: SSE2 on x86-64 hosts: the covered columns of small triangles four columns at a time, the
   tile cull eight triangles at a time, and the RGB pixels of bilinear spans and of
   forward-differenced zienkiewicz rows with the three channels in vector lanes; 0: column by
   column, triangle by triangle and channel by channel (the only choice on other targets). The
   pixels are the same either way (test_core_golden_portable runs the golden cases with 0 on the host). */
#ifndef TS_USE_SSE2
#if defined(__SSE2__)
#define TS_USE_SSE2 1
#else
#define TS_USE_SSE2 0
#endif
#endif

/* 1: the setup's wide products and divisions use the compiler's 128-bit integers where it has them
   (64-bit hosts); 0: the portable forms Cortex-M uses (four-multiply high products, the reciprocal
   by 32-bit divisions, bilinear scan-path quotients in 15-bit chunks). The pixels are the same
   either way (test_core_golden_portable runs the golden cases with 0 and the scalar paths on the host). */
#ifndef TS_USE_INT128
#if defined(__SIZEOF_INT128__)
#define TS_USE_INT128 1
#else
#define TS_USE_INT128 0
#endif
#endif

/* The core reads the blob in place on every render: its bytes must not change between ts_open
   (open_blob), which validates them all, and the last render. */

#endif

/* The typed constants, for the core's C++ headers. Their guard is their own, so that a C++ header
   reaches them even after tristream.h took the macros alone (it defines TS_CONFIG_MACROS_ONLY
   around its include: C and C++98 callers of the C API never see this part). Every source of the
   core comes here before any other line that needs C++17, so in an older mode its first error is
   the #error below, which names the fix (tests/ecosystems checks both). */
#if defined(__cplusplus) && !defined(TS_CONFIG_MACROS_ONLY) && !defined(TRISTREAM_CONFIG_CXX)
#define TRISTREAM_CONFIG_CXX
#if __cplusplus < 201703L
#error "tristream's core needs C++17: compile it with -std=gnu++17 (README.md, 'Firmware ecosystems')"
#endif
namespace tristream::core::config {

inline constexpr int subpixel_bits = TS_SUBPIXEL_BITS;
inline constexpr int max_dimension = TS_MAX_DIMENSION;
inline constexpr int gradient_frac_bits = TS_GRADIENT_FRAC_BITS;
inline constexpr int32_t max_gradient = TS_MAX_GRADIENT;
inline constexpr uint32_t pixel_formats = TS_PIXEL_FORMATS;
inline constexpr uint32_t methods = TS_METHODS;
inline constexpr uint32_t color_spaces = TS_COLOR_SPACES;
inline constexpr bool layered = TS_LAYERED != 0;

static_assert(subpixel_bits >= 0 && subpixel_bits <= 8, "sub-pixel bits out of the supported range");
static_assert(max_dimension >= 2 && max_dimension <= 4096, "max dimension out of the supported range");
static_assert(pixel_formats != 0 && pixel_formats <= 0x3F, "TS_PIXEL_FORMATS: bits 0..5, at least one");
static_assert(methods != 0 && methods <= 0x3, "TS_METHODS: bits 0..1, at least one");
static_assert(color_spaces != 0 && color_spaces <= 0x7, "TS_COLOR_SPACES: bits 0..2, at least one");
static_assert(TS_LAYERED == 0 || TS_LAYERED == 1, "TS_LAYERED: 0 or 1");
static_assert(gradient_frac_bits >= 0 && gradient_frac_bits <= 16, "gradient fraction bits out of range");
static_assert(int64_t(max_gradient) << gradient_frac_bits < (int64_t(1) << 31), "gradients must fit int32");

}  /* namespace tristream::core::config */
#endif
