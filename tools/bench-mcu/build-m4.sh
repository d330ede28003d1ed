#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The bench-mcu programs of the Cortex-M4 (tools/bench-mcu/m4), built in <dir> by build-core.sh.
# Usage: build-m4.sh <dir> [target...] (default: all).
exec bash "$(dirname "$0")/build-core.sh" m4 "$@"
