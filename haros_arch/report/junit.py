"""JUnit XML: one test suite per rule (or diagnostic code), one failing case per finding.

CI systems show failing cases; a rule with no findings is one passing case, so the
report also says what was checked.
"""

from __future__ import annotations

from collections.abc import Iterable, Sequence
from xml.etree import ElementTree as ET

from ..model.diagnostic import Diagnostic
from ..model.finding import Finding
from .escape import printable


def _also(places: Sequence[object]) -> str:
    """The other places of the same problem, as a line of the failure's text."""
    return f"\nalso at: {', '.join(map(str, places))}" if places else ""


def to_junit(findings: Iterable[Finding], diagnostics: Iterable[Diagnostic] = (),
             checked: Iterable[str] = ()) -> str:
    cases: dict[str, list[tuple[str, str, str, str]]] = {rule: [] for rule in checked}
    for f in findings:
        configs = ", ".join(f.configurations)
        name = f"{configs}: {f.location}" if configs else str(f.location)
        cases.setdefault(f.rule, []).append((name, f.severity, f.title, f.message + (
            f"\ninvolves: {', '.join(f.entities)}" if f.entities else "") + _also(f.also)))
    for d in diagnostics:
        cases.setdefault(d.code, []).append((str(d.location), d.severity, d.code,
                                             d.message + _also(d.also)))
    root = ET.Element("testsuites", name="haros-arch")
    total = failures = 0
    for rule, items in sorted(cases.items()):
        suite = ET.SubElement(root, "testsuite", name=rule, tests=str(max(1, len(items))),
                              failures=str(len(items)))
        total += max(1, len(items))
        failures += len(items)
        if not items:
            ET.SubElement(suite, "testcase", classname=rule, name="no findings")
        for name, severity, title, message in items:
            case = ET.SubElement(suite, "testcase", classname=rule, name=name)
            failure = ET.SubElement(case, "failure", type=severity, message=title)
            failure.text = message
    root.set("tests", str(total))
    root.set("failures", str(failures))
    ET.indent(root)
    # names may hold control characters or lone surrogates, which XML 1.0 cannot carry
    return printable('<?xml version="1.0" encoding="UTF-8"?>\n' + ET.tostring(root, "unicode")
                     + "\n")
