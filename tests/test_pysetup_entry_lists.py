"""console_scripts as setuptools reads them: nested lists and tuples flattened, a string
split into lines (rmf_demos_bridges lists its two scripts inside one tuple)."""

from __future__ import annotations

from conftest import package_xml

from haros_arch import pysetup
from haros_arch.workspace import scan

NODE = "import rclpy\n\ndef main():\n    rclpy.init()\n"


def _nodes(tmp_path, scripts: str):
    files = {"src/pkg/package.xml": package_xml("pkg", "ament_python"),
             "src/pkg/pkg/__init__.py": "", "src/pkg/pkg/a.py": NODE, "src/pkg/pkg/b.py": NODE,
             "src/pkg/setup.py": (
                 "from setuptools import setup\n"
                 f"setup(name='pkg', entry_points={{'console_scripts': {scripts}}})\n")}
    for rel, text in files.items():
        path = tmp_path / rel
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(text)
    ws = scan([str(tmp_path / "src")], {})
    nodes, found = pysetup.parse_package(ws.packages["pkg"], ws)
    return sorted(n.name for n in nodes), {d.code for d in found}


def test_a_tuple_inside_the_list_is_flattened(tmp_path) -> None:
    scripts = "[('a=' 'pkg.a:main', 'b=' 'pkg.b:main',)]"
    assert _nodes(tmp_path, scripts) == (["pkg/a", "pkg/b"], set())


def test_a_string_of_several_lines(tmp_path) -> None:
    scripts = "'''\n  a = pkg.a:main\n  # not this one\n  b = pkg.b:main\n'''"
    assert _nodes(tmp_path, scripts) == (["pkg/a", "pkg/b"], set())


def test_a_computed_dict_with_nested_lists(tmp_path) -> None:
    scripts = "[['a=pkg.a:main'], ('b=pkg.b:main',)]"
    assert _nodes(tmp_path, scripts) == (["pkg/a", "pkg/b"], set())


def test_an_unknown_part_is_still_said(tmp_path) -> None:
    scripts = "[('a=pkg.a:main', open('x').read())]"
    names, codes = _nodes(tmp_path, scripts)
    assert names == ["pkg/a"] and codes == {"PYSETUP_DYNAMIC"}
