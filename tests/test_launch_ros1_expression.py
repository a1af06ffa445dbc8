"""The safe expression evaluator used by $(eval) and PythonExpression."""

from __future__ import annotations

import pytest

from haros_arch.launch.expression import BUILTINS, MATH, Limits, Unknown, evaluate

ARGS = {"robot": "r2", "count": "3", "flag": "true", "nothing": Unknown("arg unset")}


def names(name: str) -> object:
    return ARGS[name]


@pytest.mark.parametrize(("text", "expected"), [
    ("1 + 2 * 3", 7),
    ("7 // 2, 7 % 2, 2 ** 10, -3", (3, 1, 1024, -3)),
    ("'a' + 'b' * 2", "abb"),
    ("1 < 2 <= 2 != 3", True),
    ("1 < 2 > 5", False),
    ("not 0 and (0 or 'x')", "x"),
    ("'y' if robot == 'r2' else 'n'", "y"),
    ("robot.upper() + '_' + robot.replace('2', 'two')", "R2_rtwo"),
    ("'a,b,c'.split(',')[1:]", ["b", "c"]),
    ("'-'.join(['a', 'b'])", "a-b"),
    ("'{}/{}'.format(robot, 1)", "r2/1"),
    ("' X '.strip().lower().startswith('x')", True),
    ("'abc'.find('c')", 2),
    ("len('abcd') + int('4') + int(float('2.5'))", 10),
    ("str(3) + str(True)", "3True"),
    ("min(3, 1, 2), max([4, 9]), abs(-2), round(2.567, 2)", (1, 9, 2, 2.57)),
    ("{'a': 1, 'b': [1, 2]}['b'][-1]", 2),
    ("(1, 2, 3)[::-1]", (3, 2, 1)),
    ("[x * 2 for x in [1, 2, 3] if x > 1]", [4, 6]),
    ("'b' in ['a', 'b']", True),
    ("f'{robot}_{count}'", "r2_3"),
    ("bool('') or None", None),
    ("False and nothing", False),
    ("True or nothing", True),
    ("'same' if nothing else 'same'", "same"),
    ("sorted(set('ndt_yabloc'.split('_')).intersection(['ndt', 'artag']))", ["ndt"]),
    ("set([1, 2]).union({3}) == {1, 2, 3}, {1}.issubset([1, 2])", (True, True)),
])
def test_evaluates(text: str, expected: object) -> None:
    assert evaluate(text, names) == expected


def test_math_table() -> None:
    value = evaluate("radians(180) == pi and floor(2.7) == 2", names, {**BUILTINS, **MATH})
    assert value is True


def test_functions_from_the_caller() -> None:
    called: list[tuple[object, ...]] = []

    def arg(*a: object) -> object:
        called.append(a)
        return "x"

    assert evaluate("arg('robot') + 'y'", names, {"arg": arg}) == "xy"
    assert called == [("robot",)]


@pytest.mark.parametrize(("text", "kind"), [
    ("nothing", "unknown"),
    ("nothing + 'a'", "unknown"),
    ("nothing == 'x'", "unknown"),
    ("True and nothing", "unknown"),
    ("'a' if nothing else 'b'", "unknown"),
    ("undefined_name", "undefined"),
    ("__import__('os').system('touch /tmp/haros_pwned')", "unsupported"),
    ("().__class__.__bases__[0].__subclasses__()", "unsupported"),
    ("open('/etc/passwd').read()", "unsupported"),
    ("(lambda: 1)()", "unsupported"),
    ("robot.__len__()", "unsupported"),
    ("robot.encode", "unsupported"),
    ("len", "unsupported"),
    ("1 / 0", "error"),
    ("[1][5]", "error"),
    ("int('x')", "error"),
    ("1 +", "syntax"),
    ("x = 1", "syntax"),
    ("9 ** 9 ** 9", "limit"),
    ("'a' * 10 ** 9", "limit"),
    ("[0] * 10 ** 8", "limit"),
    ("'{:999999999}'.format(1)", "limit"),
    ("'%999999999d' % 1", "limit"),
    ("'a'.zfill(10 ** 9)", "limit"),
    ("[x for x in range(1000) for y in range(1000)]", "limit"),
    ("1 << 100000", "limit"),
    ("-" * 200 + "1", "limit"),
    ("+".join(["1"] * 5000), "limit"),
])
def test_refuses(text: str, kind: str) -> None:
    result = evaluate(text, names)
    assert isinstance(result, Unknown), result
    assert result.kind == kind, result


def test_nothing_is_executed(tmp_path) -> None:  # type: ignore[no-untyped-def]
    marker = tmp_path / "pwned"
    evaluate(f"__import__('os').system('touch {marker}')", names)
    evaluate("[c for c in ().__class__.__base__.__subclasses__()]", names)
    assert not marker.exists()


def test_limits_are_configurable() -> None:
    assert isinstance(evaluate("'a' * 20", names, limits=Limits(length=10)), Unknown)
    assert evaluate("'a' * 5", names, limits=Limits(length=10)) == "aaaaa"
