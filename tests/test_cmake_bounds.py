"""CMake growth and depth are bounded: each hostile file ends quickly with a CMAKE_LIMIT
diagnostic at its line, and what came before it is kept."""

from __future__ import annotations

import time

import pytest
import regex

from haros_arch.cmake import listops
from haros_arch.cmake.interpreter import Interpreter
from haros_arch.cmake.lexer import tokenize

PREFIX = "project(p)\nadd_executable(kept src/kept.cpp)\n"

CASES = {
    "nested ifs": ("if(TRUE)\n" * 3000 + "endif()\n" * 3000, "nested deeper"),
    "nested foreach": ("foreach(i a)\n" * 3000 + "endforeach()\n" * 3000, "nested deeper"),
    "list doubling": ("set(a x)\nforeach(i RANGE 200)\n  list(APPEND a ${a})\nendforeach()\n",
                      "arguments expand"),
    "macro ARGN doubling": ("macro(m)\n  set(a ${ARGN} ${ARGN})\n  m(${a})\nendmacro()\n"
                            "set(a x y)\nm(${a})\n", "arguments expand"),
    "string doubling": ("set(s " + "x" * 60 + ")\nforeach(i RANGE 60)\n"
                        "  string(APPEND s ${s})\nendforeach()\n", "grew past"),
    "cache doubling": ("set(s " + "x" * 60 + ")\nforeach(i RANGE 60)\n"
                       "  set(s ${s}${s} CACHE STRING \"\" FORCE)\n  set(s ${s}${s})\n"
                       "endforeach()\n", "grew past"),
    # each elseif test is work: 2,000 of them in a loop of 9,000 ran for minutes
    "elseif chain in a loop": ("foreach(i RANGE 9000)\nif(FALSE)\n" + "elseif(FALSE)\n" * 2000
                               + "endif()\nendforeach()\n", "commands evaluated"),
    "nested ifs in a loop": ("foreach(i RANGE 9000)\n" + "if(TRUE)\n" * 150 + "set(x 1)\n"
                             + "endif()\n" * 150 + "endforeach()\n", "commands evaluated"),
    # found by the fuzzer: int() of 5,000 digits raised ValueError (and len() of a range
    # past 64 bits raises OverflowError)
    "range bound of 5,000 digits": ("foreach(i RANGE 1" + "9" * 5000 + ")\nendforeach()\n",
                                    "more than 18 digits"),
    # found by the fuzzer: a loop of 10,000 rounds over one command of 20,000 characters
    "a big command in a long loop": ("while(1)\ninstall(PROGRAMS " + "x" * 20_000
                                     + " DESTINATION bin)\nendwhile()\n",
                                     "characters of arguments expanded"),
    # and 833 rounds of a command of 3,000 short arguments took 8.7 s
    "many arguments in a long loop": ("while(1)\ninstall(PROGRAMS " + "$e " * 3000
                                      + "DESTINATION bin)\nendwhile()\n",
                                      "characters of arguments expanded"),
    "range bound past 64 bits": ("foreach(i RANGE 0 1" + "0" * 30 + " 1)\nendforeach()\n",
                                 "more than 18 digits"),
}


def run(text: str) -> Interpreter:
    it = Interpreter("/pkg", {})
    it.run_file(tokenize(text, "CMakeLists.txt"))
    return it


@pytest.mark.parametrize("case", sorted(CASES))
def test_growth_and_depth_end_with_a_limit(case: str) -> None:
    body, detail = CASES[case]
    started = time.process_time()  # work done, not how busy the machine is
    it = run(PREFIX + body)
    assert time.process_time() - started < 5
    limits = [d for d in it.diagnostics if d.code == "CMAKE_LIMIT"]
    assert len(limits) == 1 and detail in limits[0].message
    assert limits[0].location.line > 2
    assert "kept" in it.targets  # what came before the limit is kept


def test_regex_past_its_time_bound_leaves_the_value_unknown(monkeypatch) -> None:
    # a pattern that backtracks on any engine given a small enough bound
    monkeypatch.setattr(listops, "REGEX_SECONDS", 0.000001)
    text = ("set(s " + "a" * 5000 + "c)\nset(out before)\n"
            "string(REGEX MATCH \"(a|aa)*(b|c)$\" out ${s})\n")
    it = run(PREFIX + text)
    assert it.get("out") is None
    assert [d.code for d in it.diagnostics] == ["CMAKE_LIMIT"]


def test_a_busy_machine_does_not_stop_a_regex(monkeypatch) -> None:
    # the engine's bound is of the clock; a machine busy with other work lets it pass
    # while this run waits, having done almost nothing: the value must still be known
    # (issue 24: no result may depend on the machine's load)
    real = regex.compile("([a-z]+)_([0-9]+)")
    waits: list[float] = []

    class Busy:
        groups = real.groups
        pattern = real.pattern

        def search(self, text: str, timeout: float):
            waits.append(timeout)
            if len(waits) < 3:
                raise TimeoutError("regex timed out")  # the clock passed, not the work
            return real.search(text, timeout=timeout)

    bounded = listops.BoundedRegex(Busy())  # type: ignore[arg-type]
    found = bounded.search("node_42")
    assert found is not None and found.group(2) == "42"
    assert waits[0] == listops.REGEX_SECONDS and waits[2] > waits[1] > waits[0]


def test_regex_still_works() -> None:
    it = run("string(REGEX REPLACE \"([a-z]+)_([0-9]+)\" \"\\\\2-\\\\1\" out \"node_42\")\n"
             "list(APPEND l a1 b2 a3)\nlist(FILTER l INCLUDE REGEX \"^a\")\n"
             "if(\"abc\" MATCHES \"^a.c$\")\n  set(m yes)\nendif()\n")
    assert it.get("out") == "42-node"
    assert it.get("l") == "a1;a3"
    assert it.get("m") == "yes"


def test_blocks_found_once_still_branch_right_on_every_pass() -> None:
    # the marks of a block are kept per opening command and reused on every pass of the
    # loop (and in every slice that holds the block)
    it = run("set(out)\nforeach(i 1 2 3 4)\n"
             "  if(i EQUAL 1)\n    list(APPEND out one)\n"
             "  elseif(i EQUAL 2)\n    if(TRUE)\n      list(APPEND out two)\n    endif()\n"
             "  elseif(i EQUAL 3)\n    foreach(j a b)\n      list(APPEND out three${j})\n"
             "    endforeach()\n"
             "  else()\n    list(APPEND out other)\n  endif()\nendforeach()\n")
    assert it.get("out") == "one;two;threea;threeb;other"
    assert it.diagnostics == []
