"""One reader of the ``)`` that closes a ``(`` in C/C++ text (``ctext.closing``), used by
the C++ extractor's permissive declarations (plain, either way) and by the recall's
logging statements (string and character literals and comments read over)."""

import pytest

from haros_arch.ctext import closing
from haros_arch.extract.cpp.recall import log_statements


def test_plain_forwards_and_backwards() -> None:
    text = b"if (f(a, (b)) && c) x;"
    assert closing(text, 3) == text.index(b") x")
    assert closing(text, text.index(b") x"), backwards=True) == 3
    assert closing(text, 5) == text.index(b")) &&") + 1
    assert closing(b"f(a, (b)", 1) is None                    # never closed
    assert closing(b"f(" + b" " * 50 + b")", 1, span=20) is None  # beyond the span


def test_plain_counts_a_parenthesis_in_a_string() -> None:
    text = b'g("(", x);'
    assert closing(text, 1) is None
    assert closing(text, 1, literals=True) == len(text) - 2


@pytest.mark.parametrize("text", [
    b'ROS_INFO("a) b %d", n);',
    b"ROS_INFO(\"%c\", ')');",
    b'ROS_INFO("a \\" ) b");',
    b"ROS_INFO(\"n\", // a ) here\n  n);",
    b'ROS_INFO("n", /* ) */ n);',
    b'ROS_INFO("%d", 1\'000);',
])
def test_literals_read_over(text: bytes) -> None:
    assert closing(text, text.index(b"("), literals=True) == len(text) - 2


def test_literals_unclosed_comment_and_backwards() -> None:
    assert closing(b"f(a /* ) ", 1, literals=True) is None
    with pytest.raises(ValueError):
        closing(b"(a)", 2, backwards=True, literals=True)


def test_log_statements_end_past_the_parenthesis() -> None:
    data = b'void f() {\n  ROS_WARN_THROTTLE(1, "x) %s", s.c_str());\n  g();\n}\n'
    [(start, end)] = log_statements(data)
    assert data[start:end] == b'ROS_WARN_THROTTLE(1, "x) %s", s.c_str())'
