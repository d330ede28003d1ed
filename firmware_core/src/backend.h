/* SPDX-License-Identifier: MIT */
#pragma once
// The one place that chooses the kernels' platform code. A kernel that has a platform form calls
// backend::<name>; every platform's form has the same interface and gives the same results:
//   portable/  plain C++, the form of every target without SSE2 (Cortex-M among them), compiled
//              on every host so that tests compare it with the others (test_core_backends);
//   sse2/      x86-64 hosts (TS_USE_SSE2), several values in vector lanes;
//   arm/       inline assembly for Cortex-M with the DSP extension (interpolate.h uses it where
//              __ARM_FEATURE_DSP is defined).
// Which parts have which forms: the files of those folders.
#include "tristream/config.h"

namespace tristream::core::detail {
namespace portable {}
namespace sse2 {}
#if TS_USE_SSE2
namespace backend = sse2;
#else
namespace backend = portable;
#endif
}  // namespace tristream::core::detail
