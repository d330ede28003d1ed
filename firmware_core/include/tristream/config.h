#pragma once
// Every compile-time knob of the core, with its default (C and C++). Override by defining the macro before
// this header is included (e.g. -DTS_SUBPIXEL_BITS=4); blobs record the values that change their
// layout (see blob_config_hash), and the core rejects a blob packed for another configuration.
#include <stdint.h>

// Sub-pixel bits of vertex positions (format fx28_4 by default). Positions, edge functions and
// their bit budget are in docs/FIXED_POINT.md. With 4 bits and TS_MAX_DIMENSION 2048 every
// coordinate difference fits 16 bits and every edge function value fits 33 bits.
#ifndef TS_SUBPIXEL_BITS
#define TS_SUBPIXEL_BITS 4
#endif

// Largest width or height, of the triangulation's domain and of the output, in pixels.
#ifndef TS_MAX_DIMENSION
#define TS_MAX_DIMENSION 2048
#endif

// Fraction bits of the per-vertex gradients stored for zienkiewicz (format q19_12).
#ifndef TS_GRADIENT_FRAC_BITS
#define TS_GRADIENT_FRAC_BITS 12
#endif

// Largest magnitude of a stored gradient component, in value units (0..255) per domain pixel.
#ifndef TS_MAX_GRADIENT
#define TS_MAX_GRADIENT 32767
#endif

// 1: render_blob re-validates the blob on every call (cheap checks only: header and table).
// Full validation is always done by open_blob.
#ifndef TS_CHECK_HEADER_ON_RENDER
#define TS_CHECK_HEADER_ON_RENDER 1
#endif

// 1: find the covered columns of small triangles with SSE2 (x86-64 hosts), four columns at a time;
// 0: column by column (the only choice on other targets). The pixels are the same either way.
#ifndef TS_USE_SSE2
#if defined(__SSE2__)
#define TS_USE_SSE2 1
#else
#define TS_USE_SSE2 0
#endif
#endif

#ifdef __cplusplus
namespace tristream::core::config {

inline constexpr int subpixel_bits = TS_SUBPIXEL_BITS;
inline constexpr int max_dimension = TS_MAX_DIMENSION;
inline constexpr int gradient_frac_bits = TS_GRADIENT_FRAC_BITS;
inline constexpr int32_t max_gradient = TS_MAX_GRADIENT;

static_assert(subpixel_bits >= 0 && subpixel_bits <= 8, "sub-pixel bits out of the supported range");
static_assert(max_dimension >= 2 && max_dimension <= 4096, "max dimension out of the supported range");
static_assert(gradient_frac_bits >= 0 && gradient_frac_bits <= 16, "gradient fraction bits out of range");
static_assert(int64_t(max_gradient) << gradient_frac_bits < (int64_t(1) << 31), "gradients must fit int32");

}  // namespace tristream::core::config
#endif
