"""A name of a library the stand-ins provide that the code uses without including it,
because a header that would have included it is missing (Autoware's scenario selector
holds a ``boost::optional<rclcpp::Time>`` that only lanelet2's headers include), is the
stand-in's declaration, not a permissive one: ``stop_time_ = {}`` on a permissive
template was ambiguous, an error in the constructor that makes the node's calls."""

from __future__ import annotations

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan
from tests.conftest import package_xml

SOURCE = """#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/string.hpp>
#include <lanelet2_core/LaneletMap.h>

class Selector : public rclcpp::Node
{
public:
  Selector() : rclcpp::Node("selector")
  {
    stop_time_ = {};
    if (!stop_time_ || stop_time_ == boost::none) {
      stop_time_ = now();
    }
    pub_ = create_publisher<std_msgs::msg::String>("scenario", 1);
  }
  boost::optional<rclcpp::Time> stop_time_;
  lanelet::LaneletMapPtr map_;
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr pub_;
};
"""


def test_a_boost_name_reached_through_a_missing_header_is_the_stand_in_s(tmp_path) -> None:
    (tmp_path / "package.xml").write_text(package_xml("selector", "ament_cmake"))
    source = tmp_path / "selector.cpp"
    source.write_text(SOURCE)
    result = extract_cpp([str(source)], scan([str(tmp_path)]), cache_dir=None,
                         distro="humble")
    assert [c.name for c in result.calls] == ["scenario"]
    assert [d.message for d in result.diagnostics
            if d.code in ("CPP_PARSE_ERROR", "CPP_ERROR_NEAR_CALL")] == []


def test_the_stand_in_s_names_are_not_declared_again_in_a_reopened_namespace(
        tmp_path, monkeypatch) -> None:
    # boost is a namespace the parse knows (boost::shared_ptr's stand-in): the synthesised
    # header reopens it; the names the stand-in header provides are included, not also
    # declared there as permissive templates
    from haros_arch.extract.cpp import synthesis

    headers: list[str] = []
    original = synthesis.Names.header

    def header(self: synthesis.Names) -> str:
        headers.append(original(self))
        return headers[-1]

    monkeypatch.setattr(synthesis.Names, "header", header)
    (tmp_path / "package.xml").write_text(package_xml("selector", "ament_cmake"))
    source = tmp_path / "selector.cpp"
    source.write_text(SOURCE.replace("#include <lanelet2_core/LaneletMap.h>",
                                     "#include <boost/shared_ptr.hpp>\n"
                                     "#include <lanelet2_core/LaneletMap.h>"))
    result = extract_cpp([str(source)], scan([str(tmp_path)]), cache_dir=None,
                         distro="humble")
    assert [c.name for c in result.calls] == ["scenario"]
    assert headers and all("#include <boost/optional.hpp>" in text for text in headers)
    assert not any("struct optional" in text or "struct none" in text for text in headers)


def test_the_diagnostic_lists_only_the_names_declared_permissively(tmp_path) -> None:
    # boost::optional and boost::none come from the stand-in's header: CPP_NAMES_DECLARED
    # listed them among the permissive names and counted them
    (tmp_path / "package.xml").write_text(package_xml("selector", "ament_cmake"))
    source = tmp_path / "selector.cpp"
    source.write_text(SOURCE)
    result = extract_cpp([str(source)], scan([str(tmp_path)]), cache_dir=None,
                         distro="humble")
    (said,) = [d.message for d in result.diagnostics if d.code == "CPP_NAMES_DECLARED"]
    assert said.startswith("2 name(s) unknown to the parse declared permissively "
                           "(lanelet, lanelet::LaneletMapPtr); boost::none, "
                           "boost::optional from the stand-ins' headers;"), said
    source.write_text(SOURCE.replace("  lanelet::LaneletMapPtr map_;\n", ""))
    result = extract_cpp([str(source)], scan([str(tmp_path)]), cache_dir=None,
                         distro="humble")
    (said,) = [d.message for d in result.diagnostics if d.code == "CPP_NAMES_DECLARED"]
    assert said.startswith("0 name(s) unknown to the parse declared permissively (none); "
                           "boost::none, boost::optional from the stand-ins' headers;"), said
