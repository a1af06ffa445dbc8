"""The C++ toolchain libclang parses with: the library itself and the language flags.

By default nothing of the system is used: the stand-in standard library replaces it
(``headers``). Only with ``system_headers`` (the real ROS headers, HAROS's way) do we need
the system compiler's headers, since the libclang wheel ships neither clang's resource
headers nor a C++ standard library: its search list (``c++ -E -x c++ - -v``) when a
compiler is installed, else the usual Debian / GCC folders found by globbing.
"""

from __future__ import annotations

import functools
import glob
import os
import shutil
import subprocess

import clang.cindex as ci

COMPILERS = ("c++", "g++", "clang++")


@functools.lru_cache(maxsize=1)
def index() -> ci.Index:
    """One libclang index for the process (creating it loads the library)."""
    return ci.Index.create()


@functools.lru_cache(maxsize=1)
def system_include_dirs() -> tuple[str, ...]:
    """The system compiler's ``#include <...>`` search list, in order."""
    for compiler in COMPILERS:
        path = shutil.which(compiler)
        if path is None:
            continue
        found = _ask_compiler(path)
        if found:
            return found
    return _guess_include_dirs()


def _ask_compiler(path: str) -> tuple[str, ...]:
    try:
        done = subprocess.run(
            [path, "-E", "-x", "c++", "-", "-v"], input="", capture_output=True, text=True,
            timeout=20, check=False)
    except (OSError, subprocess.SubprocessError):
        return ()
    dirs: list[str] = []
    inside = False
    for line in done.stderr.splitlines():
        if line.startswith("#include <...> search starts here"):
            inside = True
        elif line.startswith("End of search list"):
            break
        elif inside:
            folder = line.strip().removesuffix(" (framework directory)")
            if os.path.isdir(folder):
                dirs.append(os.path.normpath(folder))
    return tuple(dirs)


def _guess_include_dirs() -> tuple[str, ...]:
    def newest(pattern: str) -> list[str]:
        found = sorted(glob.glob(pattern), key=lambda p: _version_key(os.path.basename(p)))
        return found[-1:]

    dirs = newest("/usr/include/c++/*")
    if dirs:
        version = os.path.basename(dirs[0])
        dirs += glob.glob(f"/usr/include/*-linux-gnu/c++/{version}")
        dirs += [d for d in (os.path.join(dirs[0], "backward"),) if os.path.isdir(d)]
        dirs += glob.glob(f"/usr/lib/gcc/*-linux-gnu/{version}/include")
    dirs += ["/usr/local/include", *glob.glob("/usr/include/*-linux-gnu"), "/usr/include"]
    return tuple(d for d in dirs if os.path.isdir(d))


def _version_key(text: str) -> tuple[int, ...]:
    return tuple(int(p) for p in text.split(".") if p.isdigit())


def base_arguments(system_headers: bool = True, std: str | None = None) -> list[str]:
    """Language flags, and the system include path when ``system_headers`` is set.

    Without it nothing of the system is searched (``-nostdinc``): the caller puts our
    stand-in standard library on the path instead. ``std`` is the C++ standard (default
    C++17; a compile command's ``-std`` may name another).
    """
    args = ["-x", "c++", f"-std={std or 'c++17'}", "-nostdinc", "-nostdinc++", "-fsyntax-only",
            "-Wno-everything", "-ferror-limit=0"]
    if system_headers:
        for folder in system_include_dirs():
            args += ["-isystem", folder]
    return args
