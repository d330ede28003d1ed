#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The bench-mcu programs of RISC-V rv32imc (tools/bench-mcu/riscv), built in <dir> by build-core.sh.
# Usage: build-rv32imc.sh <dir> [target...] (default: all).
exec bash "$(dirname "$0")/build-core.sh" rv32imc "$@"
