#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The bench-mcu programs of the Cortex-M0+ (tools/bench-mcu/m4 for ARMv6-M), built in <dir> by build-core.sh.
# Usage: build-m0plus.sh <dir> [target...] (default: all).
exec bash "$(dirname "$0")/build-core.sh" m0plus "$@"
