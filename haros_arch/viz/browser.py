"""Headless Debian chromium driven by Playwright, for the report's tests and benchmarks.

Never downloads a browser: it uses $HAROS_ARCH_CHROMIUM or the ``chromium`` on PATH.
"""

from __future__ import annotations

import os
import shutil

CHROMIUM_ARGS = ["--no-sandbox", "--disable-gpu", "--disable-background-networking",
                 "--disable-component-update", "--disable-sync", "--no-first-run"]


def chromium_path() -> str | None:
    return os.environ.get("HAROS_ARCH_CHROMIUM") or shutil.which("chromium")


def why_no_browser() -> str | None:
    """Why browser tests cannot run here, or None when they can."""
    try:
        import playwright.sync_api  # noqa: F401
    except ImportError:
        return "the playwright Python package is not installed (pip install -e .[test])"
    if chromium_path() is None:
        return "no chromium (scripts/setup --browser installs Debian's)"
    from .html import ReportError, find_d3

    try:
        find_d3()
    except ReportError as err:
        return str(err)
    return None
