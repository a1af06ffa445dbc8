"""The query parser read from the shipped table (haros_arch/query/grammar.json) is the
parser grammar.lark builds: same trees, same syntax errors; a stale or missing table
falls back to building it."""

from __future__ import annotations

import json
from importlib import resources

import pytest
from lark import Lark
from lark.exceptions import UnexpectedInput

from haros_arch.query import parser
from haros_arch.query.catalogue import load_catalogue

BAD = ["nodes[", "nodes[x >]", "topics | ", "nodes[name == 'a' and]", "(", ")", "nodes.",
       "nodes[x @ 1]", "nodes{", "a + * b", "count(", "nodes[x] | [", "'unterminated"]


def _table() -> dict:
    return json.loads(resources.files(parser.__package__).joinpath(parser.TABLE)
                      .read_text("utf-8"))


def test_the_shipped_table_is_built_from_todays_grammar() -> None:
    # stale: run scripts/grammar-table after changing grammar.lark or upgrading lark
    assert _table()["stamp"] == parser._stamp(parser._grammar())


def _outcome(lark: Lark, text: str) -> object:
    try:
        return lark.parse(text)
    except UnexpectedInput as err:
        return ("error", str(parser._syntax_error(err, text)))


def test_the_table_parses_as_the_grammar_does() -> None:
    table = parser._int_keys(_table()["table"])
    shipped = Lark._load_from_dict(table["data"], table["memo"])
    built = parser._build(parser._grammar())
    texts = [rule.query for rule in load_catalogue()] + BAD
    assert len(texts) > 20
    for text in texts:
        assert _outcome(shipped, text) == _outcome(built, text), text
    errors = [text for text in texts if isinstance(_outcome(built, text), tuple)]
    assert len(errors) >= len(BAD) - 1  # the bad ones fail, with the same message


def test_without_a_usable_table_the_parser_is_built(monkeypatch: pytest.MonkeyPatch) -> None:
    parser._lark.cache_clear()
    monkeypatch.setattr(parser, "TABLE", "no-such-table.json")
    try:
        assert parser.parse("nodes[name == 'a']") == parser.parse("nodes[name == 'a']")
        assert isinstance(parser._lark(), Lark)
        monkeypatch.setattr(parser, "_stamp", lambda grammar: {"grammar": "other"})
        parser._lark.cache_clear()
        assert parser._lark().parse("nodes") is not None
    finally:
        parser._lark.cache_clear()
