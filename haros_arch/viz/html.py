"""Assemble the report page: D3, our JS and CSS, and the data, all inlined and escaped.

The model, the findings and the source lines go into one ``<script type=
"application/json">`` element with ``<``, ``>``, ``&``, U+2028 and U+2029 written as
``\\u`` escapes, so no text from the workspace can close the element or start markup.
The page's Content-Security-Policy allows only its own inline scripts (by hash) and no
network at all, so a report opened from a CI artifact fetches nothing.
"""

from __future__ import annotations

import base64
import hashlib
import html
import os
import re
from collections.abc import Iterable, Sequence
from pathlib import Path
from typing import Any

from ..model.serialise import json_text, to_data
from .sources import collect_snippets, folder_labels

STATIC = Path(__file__).resolve().parent / "static"
VENDORED_D3 = Path(__file__).resolve().parent / "vendor" / "d3.min.js"
REPO_D3 = Path(__file__).resolve().parents[2] / "node_modules" / "d3" / "dist" / "d3.min.js"

# concatenated in this order
MODULES = ("layout.js", "compound.js", "namespaces.js", "graph.js", "panel.js", "launch.js",
           "app.js")

_JSON_ESCAPES = {"<": "\\u003c", ">": "\\u003e", "&": "\\u0026",
                 "\u2028": "\\u2028", "\u2029": "\\u2029"}


class ReportError(Exception):
    """The report cannot be written (D3 missing, output not writable)."""


def find_d3() -> Path:
    """D3's minified file: $HAROS_ARCH_D3, the copy in the package, or node_modules."""
    override = os.environ.get("HAROS_ARCH_D3")
    candidates = [Path(override)] if override else [VENDORED_D3, REPO_D3]
    for path in candidates:
        if path.is_file():
            return path
    raise ReportError(
        "D3 is not installed: run scripts/setup (it runs `npm ci`), or `npm ci` in the "
        "haros-arch checkout, or set HAROS_ARCH_D3 to a d3.min.js (version 7)")


_SURROGATE = re.compile("[\ud800-\udfff]")
PAGE_DATA = '<script type="application/json" id="haros-data">'  # the page's data follows


def json_for_script(data: Any) -> str:
    """JSON that is safe inside a ``<script type="application/json">`` element."""
    text = json_text(data, ensure_ascii=False, separators=(",", ":"))
    # a lone surrogate (a name from a Python literal '\udc80') cannot be written as UTF-8;
    # in JSON text it only occurs inside strings, where \uXXXX gives it back to the page
    return script_escaped(_SURROGATE.sub(lambda m: f"\\u{ord(m.group()):04x}", text))


def script_escaped(text: str) -> str:
    """JSON text with the characters a ``<script>`` element must not hold as escapes."""
    for ch, escaped in _JSON_ESCAPES.items():  # one pass of C per character escaped
        text = text.replace(ch, escaped)  # (no escape holds another's character)
    return text


def render_report(model_data: dict[str, Any], findings: Iterable[Any],
                  workspace_root: str | Sequence[str],
                  live: dict[str, Any] | None = None) -> str:
    """The whole report page as text; ``live``: a capture's comparison per configuration
    name (``live.compare.compare_all``), shown beside each graph."""
    found = [to_data(item) for item in findings]
    found += [item for item in model_data.get("findings", []) if item not in found]
    payload = {
        "model": model_data,
        "findings": found,
        "sources": collect_snippets({"model": model_data, "findings": found},
                                    workspace_root),
        "folders": folder_labels(workspace_root),
        **({"live": live} if live is not None else {}),
    }
    scripts = [_script_text(find_d3()), app_script()]
    style = (STATIC / "report.css").read_text(encoding="utf-8")
    hashes = " ".join(f"'sha256-{_digest(s)}'" for s in scripts)
    csp = (f"default-src 'none'; script-src {hashes}; style-src 'unsafe-inline'; "
           "img-src data:; base-uri 'none'; form-action 'none'")
    title = html.escape(f"haros-arch: {model_data.get('project') or 'report'}")
    parts = [
        "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n",
        f'<meta http-equiv="Content-Security-Policy" content="{html.escape(csp, quote=False)}">\n',
        '<meta name="viewport" content="width=device-width, initial-scale=1">\n',
        f"<title>{title}</title>\n<style>\n{style}\n</style>\n</head>\n<body>\n",
        PAGE_DATA,
        json_for_script(payload),
        "</script>\n",
        *(f"<script>{s}</script>\n" for s in scripts),
        "</body>\n</html>\n",
    ]
    return "".join(parts)


def write_report(model_data: dict[str, Any], findings: Iterable[Any],
                 workspace_root: str | Sequence[str], output: str,
                 live: dict[str, Any] | None = None) -> None:
    """Write the report of ``model_data`` (a ``haros-arch/1`` document) to ``output``."""
    write_page(render_report(model_data, findings, workspace_root, live), output)


def write_page(page: str, output: str) -> None:
    """Write a rendered report page to ``output``."""
    try:
        with open(output, "w", encoding="utf-8") as handle:
            handle.write(page)
    except OSError as err:
        raise ReportError(f"cannot write {output}: {err.strerror or err}") from err


def app_script() -> str:
    """Our modules, in order, as one strict-mode function body."""
    body = "\n".join(_script_text(STATIC / name) for name in MODULES)
    return f'(function () {{\n"use strict";\n{body}\n}})();'


def _script_text(path: Path) -> str:
    text = path.read_text(encoding="utf-8")
    if "</script" in text.lower():
        raise ReportError(f"{path} contains '</script' and cannot be inlined")
    return text


def _digest(text: str) -> str:
    return base64.b64encode(hashlib.sha256(text.encode("utf-8")).digest()).decode("ascii")
