"""Query errors: each knows the query text and the column, and shows a caret under it."""

from __future__ import annotations

WIDTH = 100


class QueryError(Exception):
    """A query that cannot be parsed or evaluated; ``str()`` shows the caret."""

    kind = "error"

    def __init__(self, message: str, text: str = "", pos: int | None = None) -> None:
        self.message, self.text, self.pos = message, text, pos
        super().__init__(self.render())

    def render(self) -> str:
        if not self.text or self.pos is None:
            return f"query {self.kind}: {self.message}"
        pos = max(0, min(self.pos, len(self.text)))
        start = self.text.rfind("\n", 0, pos) + 1
        end = self.text.find("\n", pos)
        line_text = self.text[start:] if end < 0 else self.text[start:end]
        line = self.text.count("\n", 0, pos) + 1
        column = pos - start + 1
        offset = pos - start
        if len(line_text) > WIDTH:  # show a window around the caret
            left = max(0, min(offset - WIDTH // 2, len(line_text) - WIDTH))
            line_text = line_text[left:left + WIDTH]
            offset -= left
        caret = " " * offset + "^"
        return (f"query {self.kind} at line {line}, column {column}: {self.message}\n"
                f"  {line_text}\n  {caret}")

    def at(self, text: str, pos: int | None) -> QueryError:
        """The same error, placed in ``text`` (when it has no place yet)."""
        if self.text or pos is None:
            return self
        return type(self)(self.message, text, pos)


class QuerySyntaxError(QueryError):
    kind = "syntax error"


class QueryNameError(QueryError):
    """An unknown name, a field that is not allowed, a function that is not listed."""

    kind = "error"


class QueryTypeError(QueryError):
    kind = "type error"


class QueryLimitError(QueryError):
    """The query broke the step budget, the time limit or a size limit."""

    kind = "limit"
