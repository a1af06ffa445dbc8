"""Query text to AST: lark (LALR) parses, a transformer builds ``syntax`` values.

Errors become ``QuerySyntaxError`` with the offset of the offending token, so the message
shows the query with a caret under it. Names that start with an underscore are refused
here, before anything runs.
"""

from __future__ import annotations

import functools
import hashlib
import json
from importlib import resources
from typing import Any

import lark
from lark import Lark, Token, Transformer, Tree, v_args
from lark.exceptions import UnexpectedCharacters, UnexpectedEOF, UnexpectedInput, UnexpectedToken

from . import syntax as s
from .errors import QueryError, QuerySyntaxError

MAX_QUERY_CHARS = 20_000
MAX_DEPTH = 120
MAX_NUMBER_CHARS = 400  # a literal number (a float past 1e308 is inf anyway)


TABLE = "grammar.json"  # the parser built from grammar.lark, shipped (``write_table``)


def _grammar() -> str:
    return resources.files(__package__).joinpath("grammar.lark").read_text("utf-8")


def _build(grammar: str) -> Lark:
    return Lark(grammar, parser="lalr", propagate_positions=True, maybe_placeholders=True)


def _stamp(grammar: str) -> dict[str, str]:
    """What a shipped table was built from: the grammar's text and lark's version."""
    return {"grammar": hashlib.sha256(grammar.encode("utf-8")).hexdigest(),
            "lark": lark.__version__}


@functools.lru_cache(maxsize=1)
def _lark() -> Lark:
    """The parser, read from the shipped table when it was built from this grammar by
    this lark (a tenth of the time building it takes), else built. The table is plain
    JSON in the package, never a pickle and never written at run time."""
    grammar = _grammar()
    try:
        data = json.loads(resources.files(__package__).joinpath(TABLE).read_text("utf-8"))
        if data.get("stamp") == _stamp(grammar):
            table = _int_keys(data["table"])
            return Lark._load_from_dict(table["data"], table["memo"])
    except (OSError, ValueError, KeyError, TypeError, AttributeError):
        pass  # no table, or one lark cannot read: build the parser
    return _build(grammar)


def _int_keys(value: Any) -> Any:
    """JSON's string keys back to the parse table's numbers (states, memo ids)."""
    if isinstance(value, dict):
        return {int(k) if k.isdigit() else k: _int_keys(v) for k, v in value.items()}
    if isinstance(value, list):
        return [_int_keys(v) for v in value]
    return value


def table_text() -> str:
    """The shipped table for today's grammar and lark (``scripts/grammar-table`` writes
    it into the package; a test says when it is stale)."""
    from lark.grammar import Rule
    from lark.lexer import TerminalDef

    grammar = _grammar()
    data, memo = _build(grammar).memo_serialize([TerminalDef, Rule])
    return json.dumps({"stamp": _stamp(grammar), "table": {"data": data, "memo": memo}},
                      sort_keys=True, separators=(",", ":")) + "\n"


def _pos(meta: Any) -> int:
    return getattr(meta, "start_pos", 0) or 0


def _string(token: Token) -> str:
    return str(token)[1:-1]


def _number(token: Token) -> int | float:
    text = str(token)
    if text[:2].lower() == "0x":
        return int(text, 16)
    if any(c in text for c in ".eE"):
        return float(text)
    return int(text)


@v_args(meta=True)
class _Build(Transformer[Token, s.Expr]):
    """One method per grammar rule, each returning an AST value."""

    def __init__(self, text: str) -> None:
        super().__init__()
        self.text = text

    def _name(self, token: Token) -> str:
        name = str(token)
        if name.startswith("_"):
            raise QuerySyntaxError(
                f"names that start with '_' are not allowed ('{name}')",
                self.text, token.start_pos)
        return name

    # ---- FLWR
    def flwr(self, meta: Any, items: list[Any]) -> s.Flwr:
        fors: tuple[tuple[str, s.Expr], ...] = ()
        lets: list[tuple[str, s.Expr]] = []
        where = None
        returns: tuple[s.Expr, ...] = ()
        keys = None
        for item in items:
            if item is None:
                continue
            tag, value = item
            if tag == "for":
                fors = tuple(value)
            elif tag == "let":
                lets.extend(value)
            elif tag == "where":
                where = value
            else:
                returns, keys = value
        return s.Flwr(fors, tuple(lets), where, returns, keys, pos=_pos(meta))

    def for_clause(self, meta: Any, items: list[Any]) -> tuple[str, Any]:
        return "for", items

    def for_def(self, meta: Any, items: list[Any]) -> tuple[str, s.Expr]:
        return self._name(items[0]), items[1]

    def let_clause(self, meta: Any, items: list[Any]) -> tuple[str, Any]:
        return "let", items

    def let_def(self, meta: Any, items: list[Any]) -> tuple[str, s.Expr]:
        return self._name(items[0]), items[1]

    def where_clause(self, meta: Any, items: list[Any]) -> tuple[str, Any]:
        return "where", items[0]

    def return_clause(self, meta: Any, items: list[Any]) -> tuple[str, Any]:
        return "return", items[0]

    def out_tuple(self, meta: Any, items: list[Any]) -> tuple[tuple[s.Expr, ...], None]:
        return tuple(items), None

    def out_dict(self, meta: Any, items: list[Any]) -> tuple[tuple[s.Expr, ...], tuple[str, ...]]:
        keys = tuple(_string(k) for k in items[0::2])
        return tuple(items[1::2]), keys

    # ---- paths and sets
    def path(self, meta: Any, items: list[s.Step]) -> s.Path:
        return s.Path(tuple(items), pos=_pos(meta))

    def step(self, meta: Any, items: list[Any]) -> s.Step:
        return s.Step(self._name(items[0]), items[1], pos=_pos(meta))

    def _setop(op: str) -> Any:  # type: ignore[misc]
        def build(self: _Build, meta: Any, items: list[Any]) -> s.SetOp:
            return s.SetOp(op, items[0], items[1], pos=_pos(meta))
        return build

    union = _setop("|")
    intersection = _setop("&")
    difference = _setop("-")

    # ---- conditions
    def or_(self, meta: Any, items: list[Any]) -> s.Or:
        return s.Or(items[0], items[1], pos=_pos(meta))

    def and_(self, meta: Any, items: list[Any]) -> s.And:
        return s.And(items[0], items[1], pos=_pos(meta))

    def not_(self, meta: Any, items: list[Any]) -> s.Not:
        return s.Not(items[0], pos=_pos(meta))

    def compare(self, meta: Any, items: list[Any]) -> s.Compare:
        return s.Compare(str(items[1]), items[0], items[2], pos=_pos(meta))

    def less(self, meta: Any, items: list[Any]) -> s.Compare:
        return s.Compare("<", items[0], items[1], pos=_pos(meta))

    def greater(self, meta: Any, items: list[Any]) -> s.Compare:
        return s.Compare(">", items[0], items[1], pos=_pos(meta))

    def in_(self, meta: Any, items: list[Any]) -> s.Compare:
        return s.Compare("in", items[0], items[1], pos=_pos(meta))

    def not_in(self, meta: Any, items: list[Any]) -> s.Compare:
        return s.Compare("not in", items[0], items[1], pos=_pos(meta))

    def set_compare(self, meta: Any, items: list[Any]) -> s.SetCompare:
        op = " ".join(str(items[1]).split())
        return s.SetCompare(op, items[0], items[2], pos=_pos(meta))

    def quantifier(self, meta: Any, items: list[Any]) -> str:
        return str(items[0])

    def quantified(self, meta: Any, items: list[Any]) -> s.Quantified:
        mode, var, source, condition = items
        return s.Quantified(mode, self._name(var), source, condition, pos=_pos(meta))

    # ---- values
    def binop(self, meta: Any, items: list[Any]) -> s.Arith:
        return s.Arith(str(items[1]), items[0], items[2], pos=_pos(meta))

    def neg(self, meta: Any, items: list[Any]) -> s.Expr:
        operand = items[0]
        if isinstance(operand, s.Literal) and isinstance(operand.value, int | float):
            return s.Literal(-operand.value, pos=_pos(meta))
        return s.Neg(operand, pos=_pos(meta))

    def attr(self, meta: Any, items: list[Any]) -> s.Attr:
        name: Token = items[1]
        return s.Attr(items[0], self._name(name), pos=name.start_pos or _pos(meta))

    def call(self, meta: Any, items: list[Any]) -> s.Call:
        args = tuple(a for a in items[1:] if a is not None)
        return s.Call(items[0], args, pos=_pos(meta))

    def index(self, meta: Any, items: list[Any]) -> s.Index:
        return s.Index(items[0], items[1], pos=_pos(meta))

    def name(self, meta: Any, items: list[Token]) -> s.Name:
        return s.Name(self._name(items[0]), pos=_pos(meta))

    def number(self, meta: Any, items: list[Token]) -> s.Literal:
        if len(items[0]) > MAX_NUMBER_CHARS:  # int() of thousands of digits raises
            from .errors import QueryLimitError

            raise QueryLimitError(f"a number {len(items[0])} characters long; the limit is "
                                  f"{MAX_NUMBER_CHARS}", self.text, _pos(meta))
        return s.Literal(_number(items[0]), pos=_pos(meta))

    def string(self, meta: Any, items: list[Token]) -> s.Literal:
        return s.Literal(_string(items[0]), pos=_pos(meta))

    def list_(self, meta: Any, items: list[Any]) -> s.ListOf:
        return s.ListOf(tuple(i for i in items if i is not None), pos=_pos(meta))


def _nesting(text: str) -> tuple[int, int]:
    """The deepest bracket nesting outside strings, and where it is reached."""
    level = deepest = where = 0
    quote = ""
    for i, char in enumerate(text):
        if quote:
            quote = "" if char == quote else quote
        elif char in "'\"":
            quote = char
        elif char in "([{":
            level += 1
            if level > deepest:
                deepest, where = level, i
        elif char in ")]}":
            level -= 1
    return deepest, where


def parse(text: str) -> s.Expr:
    """Parse a query. Raises ``QuerySyntaxError`` (or ``QueryLimitError``) with a caret."""
    from .errors import QueryLimitError

    if len(text) > MAX_QUERY_CHARS:
        raise QueryLimitError(f"the query is {len(text)} characters long; the limit is "
                              f"{MAX_QUERY_CHARS}")
    deepest, where = _nesting(text)
    if deepest > MAX_DEPTH // 2:
        raise QueryLimitError(f"brackets nested {deepest} deep; the limit is {MAX_DEPTH // 2}",
                              text, where)
    try:
        tree = _lark().parse(text)
    except UnexpectedInput as err:
        raise _syntax_error(err, text) from None
    try:
        result = _Build(text).transform(tree) if isinstance(tree, Tree) else tree
    except QueryError:
        raise
    except RecursionError:
        raise QueryLimitError("the query is nested too deeply", text, 0) from None
    except Exception as err:  # lark wraps errors raised in callbacks
        inner = getattr(err, "orig_exc", None)
        if isinstance(inner, QueryError):
            raise inner from None
        if isinstance(inner, RecursionError):
            raise QueryLimitError("the query is nested too deeply", text, 0) from None
        raise
    if not isinstance(result, s.Expr):
        raise QuerySyntaxError("not a query", text, 0)
    if s.depth(result) > MAX_DEPTH:
        raise QueryLimitError(f"the query is nested more than {MAX_DEPTH} deep", text, 0)
    return result


_TOKEN_WORDS = {
    "LESSTHAN": "'<'", "MORETHAN": "'>'", "LPAR": "'('", "RPAR": "')'", "LSQB": "'['",
    "RSQB": "']'", "LBRACE": "'{'", "RBRACE": "'}'", "COMMA": "','", "DOT": "'.'",
    "COLON": "':'", "SLASH": "'/'", "VBAR": "'|'", "AMPERSAND": "'&'", "MINUS": "'-'",
    "EQUAL": "'='", "COMP_OP": "a comparison", "ADD_OP": "'+' or '-'",
    "MUL_OP": "'*', '/' or '%'", "NAME": "a name", "STRING": "a string",
    "NUMBER": "a number", "SET_OP": "subset/superset/is",
}


def _expected(names: set[str]) -> str:
    words = sorted({_TOKEN_WORDS.get(n, n.lower()) for n in names if not n.startswith("__")})
    if not words:
        return ""
    shown = ", ".join(words[:8]) + (", ..." if len(words) > 8 else "")
    return f"; expected {shown}"


def _syntax_error(err: UnexpectedInput, text: str) -> QuerySyntaxError:
    if isinstance(err, UnexpectedToken):
        token = err.token
        if token.type == "$END":
            return QuerySyntaxError("unexpected end of query" + _expected(set(err.expected)),
                                    text, len(text))
        return QuerySyntaxError(f"unexpected '{token}'" + _expected(set(err.expected)), text,
                                token.start_pos)
    if isinstance(err, UnexpectedCharacters):
        pos = err.pos_in_stream or 0
        return QuerySyntaxError(f"unexpected character '{text[pos:pos + 1]}'"
                                + _expected(set(err.allowed or ())), text, pos)
    if isinstance(err, UnexpectedEOF):
        return QuerySyntaxError("unexpected end of query", text, len(text))
    return QuerySyntaxError(str(err), text, getattr(err, "pos_in_stream", 0))
