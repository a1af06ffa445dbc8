"""A component library's sources, narrowed to one class: its own files, the helper files
it names (a base class, a strategy it builds), not another component's helpers."""

from __future__ import annotations

from pathlib import Path

from haros_arch.plugins.classes import narrow
from haros_arch.workspace import scan

FILES = {
    "package.xml": "<package format='2'><name>pre</name><version>1.0.0</version>"
                   "<description>d</description><maintainer email='a@b.c'>m</maintainer>"
                   "<license>BSD</license></package>",
    "include/pre/filter.hpp": "namespace pre { class Filter { public: Filter(); }; }\n",
    "include/pre/crop_box.hpp": '#include "pre/filter.hpp"\n'
                                "namespace pre { class CropBox : public Filter {}; }\n",
    "include/pre/concat.hpp": "namespace pre { class MatchingStrategy;\n"
                              "class Concat { MatchingStrategy * strategy_; }; }\n",
    "src/filter.cpp": '#include "pre/filter.hpp"\nnamespace pre {\nFilter::Filter() {}\n}\n',
    "src/matching.cpp": "namespace pre {\nvoid MatchingStrategy::match(int x) {}\n}\n",
    "src/util.cpp": "int clamp(int x) { return x; }\n",
    "src/crop_box.cpp": '#include "pre/crop_box.hpp"\n'
                        "int limit(int x) { return clamp(x); }\n"
                        "RCLCPP_COMPONENTS_REGISTER_NODE(pre::CropBox)\n",
    "src/test_utils.cpp": "void publish_mandatory_topics(int node) {\n}\n",
    "src/concat.cpp": '#include "pre/concat.hpp"\n'
                      "RCLCPP_COMPONENTS_REGISTER_NODE(pre::Concat)\n",
}
SOURCES = ["pre/src/filter.cpp", "pre/src/matching.cpp", "pre/src/util.cpp",
           "pre/src/test_utils.cpp", "pre/src/crop_box.cpp", "pre/src/concat.cpp"]


def test_a_component_keeps_the_helpers_it_names(tmp_path: Path) -> None:
    for name, text in FILES.items():
        path = tmp_path / "pre" / name
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(text)
    ws = scan([str(tmp_path)])
    # the base class's file (named in its header) and the free function it calls stay;
    # the other component's strategy and functions no file calls (test helpers) go
    assert narrow(SOURCES, "pre::CropBox", ws) == [
        "pre/src/filter.cpp", "pre/src/util.cpp", "pre/src/crop_box.cpp"]
    assert narrow(SOURCES, "pre::Concat", ws) == ["pre/src/matching.cpp", "pre/src/concat.cpp"]
