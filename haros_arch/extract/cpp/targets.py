"""Code for another processor than the parse's.

libclang parses for the machine that runs the analysis (no ``-target``): on a PC, clang
defines ``__x86_64__`` and not ``__arm__`` / ``__aarch64__``. A robot's computer is as
often an ARM board, and drivers of its hardware choose their code by the processor:
UbiquityRobotics' raspicam_node builds its whole node under ``#if defined(__arm__) ||
defined(__aarch64__)`` and, under ``#ifdef __x86_64__``, a ``main`` that only says the
node is a fake. Read for the PC, the node made no ROS call and was ``complete``, so every
parameter its launch files set was "set but never read". Which processor the robot has
is not known here; a ROS call in a branch of a condition on the processor that the
parse left out is ``CPP_TARGET_UNKNOWN`` at that call (its first per branch), which
makes the node partial: on the other processor the code makes that call.
"""

from __future__ import annotations

import re

from . import versions

# the macros compilers predefine for a processor (GCC's and clang's, and MSVC's ``_M_``
# ones), and for its instruction set extensions
PROCESSOR_MACROS = re.compile(
    r"\b(?:__arm__|__aarch64__|__arm64__|__ARM_ARCH\w*|__ARM_NEON\w*|__thumb\w*"
    r"|__x86_64__|__x86_64|__amd64__|__amd64|__i386__|__i486__|__i586__|__i686__"
    r"|_M_X64|_M_AMD64|_M_IX86|_M_ARM\w*"
    r"|__SSE\w*__|__AVX\w*__|__powerpc\w*|__PPC\w*|__ppc\w*|__riscv\w*|__mips\w*"
    r"|__s390x__|__loongarch\w*)\b")


def unknown_target_calls(text: str, skipped: list[tuple[int, int]]
                         ) -> list[tuple[int, str, str]]:
    """(line, call text, condition) of the first ROS API call of each branch of a
    condition on the processor that the parse skipped for that condition."""
    return versions.skipped_calls(text, skipped, PROCESSOR_MACROS)
