"""Format strings read as text and holes: what a formatting call makes of a literal.

``values.Scope`` reads a name built by a formatting function with a literal format
string (``fmt::format("bridge.{}.qos", topic)``, ``std::format``, ``snprintf(buf, n,
"livox/lidar_%s", ip)``, ``boost::format("%s/odom") % ns``) as the format's text with
each hole filled by its argument's value, ``?`` where that is not known. A format is
split here into pieces: a ``str`` is text written as it is, a ``Hole`` an argument (by
its index among the arguments after the format) and how it is converted. A format
these functions would reject, or one written with features not read here (a named
field, a positional printf argument ``%1$s``), gives None: the whole value unknown.
"""

from __future__ import annotations

import re
from dataclasses import dataclass

# how a hole writes its argument: ``TEXT`` as the argument is (a string as it is, an
# integer in decimal), ``UNSIGNED`` a non-negative integer in decimal, ``HEX`` /
# ``UPPER_HEX`` / ``OCTAL`` an integer so, ``OTHER`` in a way not modelled (a width, a
# precision, a float, a character): not known
TEXT, UNSIGNED, HEX, UPPER_HEX, OCTAL, OTHER = "text", "u", "x", "X", "o", "other"


@dataclass(frozen=True)
class Hole:
    index: int
    conversion: str


Piece = str | Hole

# printf's conversion: flags, width, precision, length, conversion character
_PRINTF = re.compile(r"%([-+ #0']*)(\*|\d+)?(?:\.(\*|\d*))?"
                     r"(hh|h|ll|l|j|z|t|L|q|I64|I32|I)?([diouxXeEfFgGaAcspn%])")
_INTEGERS = {"d": TEXT, "i": TEXT, "u": UNSIGNED, "x": HEX, "X": UPPER_HEX, "o": OCTAL}
# {fmt} / std::format: ``{}``, ``{0}``, ``{:spec}``, ``{1:spec}``; a named field is not read
_FIELD = re.compile(r"\{(\d*)(?::([^{}]*))?\}")
# a format spec that writes the argument as it is: none, or only the type's own
_PLAIN_SPECS = {"": TEXT, "s": TEXT, "d": TEXT, "x": HEX, "X": UPPER_HEX, "o": OCTAL}


def _text(pieces: list[Piece], text: str) -> None:
    if text:
        if pieces and isinstance(pieces[-1], str):
            pieces[-1] += text
        else:
            pieces.append(text)


def printf_pieces(text: str) -> list[Piece] | None:
    """The pieces of a printf format (``snprintf``): ``%s`` a string, ``%d`` / ``%i`` /
    ``%u`` / ``%x`` / ``%X`` / ``%o`` an integer (any length modifier: ``%zu``,
    ``%lu``), ``%%`` a percent sign; a flag, a width or a precision (``%02d``), a float
    or a character is a hole not known; a ``*`` width takes an argument of its own."""
    pieces: list[Piece] = []
    index, at = 0, 0
    while at < len(text):
        found = text.find("%", at)
        if found < 0:
            _text(pieces, text[at:])
            break
        _text(pieces, text[at:found])
        match = _PRINTF.match(text, found)
        if match is None:
            return None
        flags, width, precision, _length, conversion = match.groups()
        at = match.end()
        if conversion == "%":
            _text(pieces, "%")
            continue
        if conversion == "n":
            return None  # writes, not text
        for star in (width, precision):
            if star == "*":
                index += 1
        plain = not flags and width is None and precision is None
        if conversion == "s" and plain:
            pieces.append(Hole(index, TEXT))
        elif conversion in _INTEGERS and plain:
            pieces.append(Hole(index, _INTEGERS[conversion]))
        else:
            pieces.append(Hole(index, OTHER))
        index += 1
    return pieces


def brace_pieces(text: str) -> list[Piece] | None:
    """The pieces of a ``fmt::format`` / ``std::format`` format: ``{}`` the next
    argument, ``{N}`` the N-th, with a spec after ``:`` a hole not known unless it is
    only a type (``{:d}``, ``{:s}``, ``{:x}``); ``{{`` and ``}}`` a brace. Automatic and
    manual numbering mixed, a named field or an unmatched brace: None."""
    pieces: list[Piece] = []
    at, following = 0, 0
    manual: bool | None = None
    while at < len(text):
        char = text[at]
        if char in "{}" and text[at + 1:at + 2] == char:
            _text(pieces, char)
            at += 2
            continue
        if char == "}":
            return None
        if char != "{":
            _text(pieces, char)
            at += 1
            continue
        match = _FIELD.match(text, at)
        if match is None:
            return None
        number, spec = match.groups()
        if (manual is not None and manual != bool(number)):
            return None
        manual = bool(number)
        if number:
            index = int(number)
        else:
            index, following = following, following + 1
        pieces.append(Hole(index, _PLAIN_SPECS.get(spec or "", OTHER)))
        at = match.end()
    return pieces


# boost::format's own directives beside printf's: ``%N%`` the N-th argument, ``%|spec|``
_BOOST_POSITION = re.compile(r"%(\d+)%")
_BOOST_ABSOLUTE = re.compile(r"%\|[^|]*\|")


def boost_pieces(text: str) -> list[Piece] | None:
    """The pieces of a ``boost::format`` format: ``%N%`` the N-th argument (counted
    from 1) as it streams, printf's directives as ``printf_pieces`` (boost streams the
    argument whatever the type letter: ``%d`` of a string is the string), ``%|spec|`` a
    hole not known. Positional and sequential directives mixed: None."""
    pieces: list[Piece] = []
    at, following = 0, 0
    positional: bool | None = None
    while at < len(text):
        found = text.find("%", at)
        if found < 0:
            _text(pieces, text[at:])
            break
        _text(pieces, text[at:found])
        position = _BOOST_POSITION.match(text, found)
        absolute = _BOOST_ABSOLUTE.match(text, found)
        if text.startswith("%%", found):
            _text(pieces, "%")
            at = found + 2
            continue
        if position is not None:
            if positional is False or int(position.group(1)) < 1:
                return None
            positional = True
            pieces.append(Hole(int(position.group(1)) - 1, TEXT))
            at = position.end()
            continue
        if positional is True:
            return None
        positional = False
        if absolute is not None:
            pieces.append(Hole(following, OTHER))
            following += 1
            at = absolute.end()
            continue
        match = _PRINTF.match(text, found)
        if match is None or "*" in (match.group(2), match.group(3)):
            return None
        flags, width, precision, _length, conversion = match.groups()
        plain = not flags and width is None and precision is None
        pieces.append(Hole(following, TEXT if plain and conversion in ("d", "i", "u", "s")
                           else OTHER))
        following += 1
        at = match.end()
    return pieces


def integer_text(value: int, conversion: str) -> str | None:
    """An integer as a hole writes it; None for a conversion not modelled."""
    if conversion == TEXT:
        return str(value)
    if value < 0:
        return None  # printf's %x of a negative int is its two's complement
    if conversion == UNSIGNED:
        return str(value)
    if conversion == HEX:
        return format(value, "x")
    if conversion == UPPER_HEX:
        return format(value, "X")
    if conversion == OCTAL:
        return format(value, "o")
    return None
