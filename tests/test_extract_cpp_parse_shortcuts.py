"""The shortcuts of the Python around a unit's parses give what the long way gave (#24):
the calls of C library functions found by their first word, and the facts of a run's
header diagnostics read on from where the last unit stopped."""

from __future__ import annotations

import random
import re

from haros_arch import diagnostics as diag
from haros_arch.extract.cpp import _fieldless_packages, _HeaderFacts, synthesis
from haros_arch.model.location import Location

_TEXT = b"""void f() {
  ogg_stream_init(x);
  oggz_run(y);
  xogg_a(b);
  urg_open (1);
  ::urg_q(1);
  a.urg_m(1);
  liboggz_f(2);
  ogg_(3);
  ogg_x;
  urg_a_b_c(d);
  return urg_ret(1);
  int urg_decl(int);
}
"""


def _declared(libraries: set[str], text: bytes) -> list[str]:
    names = synthesis.Names(libraries=libraries)
    names.learn([("expected expression", text, 0)])
    return sorted(names.root.children)


def test_c_library_calls_are_declared_by_their_first_word() -> None:
    expected = ["liboggz_f", "ogg_stream_init", "urg_a_b_c", "urg_open", "urg_ret"]
    assert _declared({"ogg", "liboggz", "urg"}, _TEXT) == expected
    # a prefix of other letters than ASCII's: the pattern of every prefix
    assert _declared({"ogg", "liboggz", "urg", "caf\u00e9"}, _TEXT) == expected


def _every_prefix(prefixes: list[bytes]) -> re.Pattern[bytes]:
    """The pattern ``_spread_calls`` matched before: every prefix tried in turn."""
    words = b"|".join(re.escape(p) for p in sorted(prefixes, key=len)[::-1])
    return re.compile(rb"(?<![\w:.>])((?:" + words + rb")_\w+)\s*\(")


def test_the_first_word_finds_what_every_prefix_found() -> None:
    pieces = [b"ogg", b"oggz", b"urg", b"liburg", b"x", b"_", b"__", b"(", b" (", b"::",
              b".", b"->", b">", b" ", b"\n", b"a1", b"9", b"init", b"ogg_", b"_urg", b";",
              b"\xc3\xa9", b"lib", b"z("]
    prefixes = [b"ogg", b"urg", b"liburg", b"libogg"]
    chooser = random.Random(24)
    compared = found = 0
    for _ in range(3000):
        text = b"".join(chooser.choice(pieces) for _ in range(chooser.randrange(1, 40)))
        before = [(m.start(), m.end(), m.group(1)) for m in _every_prefix(prefixes).finditer(text)]
        now = [(m.start(), m.end(), m.group(1)) for m in synthesis._LIBRARY_CALL.finditer(text)
               if m.group(2) in prefixes]
        assert now == before, text
        compared += 1
        found += len(before)
    assert compared == 3000 and found > 100  # not a comparison of empty lists


def _missing(header: str) -> diag.Diagnostic:
    return diag.make("CPP_INCLUDE_MISSING", Location(), header=header)


def _fieldless(header: str) -> diag.Diagnostic:
    return diag.make("CPP_MESSAGE_UNKNOWN", Location(), header=header)


class _Setup:
    def __init__(self) -> None:
        self.diagnostics: list[diag.Diagnostic] = []
        self.prepared: frozenset[str] | None = None
        self.prepared_said = 0
        self.unit_missing: list[diag.Diagnostic] = []


def test_header_facts_read_on_are_those_of_the_whole_list() -> None:
    setup = _Setup()
    facts = _HeaderFacts()

    def whole() -> tuple[set[str], set[str]]:
        return _fieldless_packages(setup.diagnostics), synthesis.library_prefixes(
            d.message for d in setup.diagnostics if d.code == "CPP_INCLUDE_MISSING")

    asked = []
    for added in ([], [_missing("ogg/ogg.h")], [_fieldless("foo_msgs/Bar.h"), _missing(
            "urg_c/urg_sensor.h")], [], [_fieldless("baz_msgs/Q.h")]):
        setup.diagnostics += added
        asked.append((facts.fieldless(setup), facts.libraries(setup)))  # type: ignore[arg-type]
        assert asked[-1] == whole()
    assert asked[-1] == ({"foo_msgs", "baz_msgs"}, {"ogg", "libogg", "urg", "liburg"})
    # a list that shrank is read anew
    del setup.diagnostics[1:]
    assert (facts.fieldless(setup), facts.libraries(setup)) == whole() == (  # type: ignore[arg-type]
        set(), {"ogg", "libogg"})
    # what a caller does with the sets it gets is not kept
    facts.fieldless(setup).add("x")  # type: ignore[arg-type]
    assert facts.fieldless(setup) == set()  # type: ignore[arg-type]


def test_a_units_missing_libraries_are_the_preparations_and_its_own() -> None:
    """Once the batch parses, what the parses said of other units (a header one of them
    stood in for) is none of the next unit's: its process's earlier units made its
    permissive declarations depend on the worker it went to."""
    setup = _Setup()
    facts = _HeaderFacts()
    setup.diagnostics += [_missing("ogg/ogg.h")]
    setup.prepared, setup.prepared_said = frozenset(), 1  # the first parse begins
    setup.diagnostics += [_missing("urg_c/urg_sensor.h")]  # another unit's repair
    assert facts.libraries(setup) == {"ogg", "libogg"}  # type: ignore[arg-type]
    setup.unit_missing = [_missing("urg_c/urg_sensor.h")]  # this unit includes it too
    assert facts.libraries(setup) == {"ogg", "libogg", "urg", "liburg"}  # type: ignore[arg-type]
