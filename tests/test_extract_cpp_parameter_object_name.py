"""``set_parameter(p)`` / ``set_parameters({p})`` of a local ``rclcpp::Parameter`` writes
the parameter the object was built with (rclcpp names the write by the object's own
name): vanttec_usv's obstacle publisher writes ``m3.name`` through ``rclcpp::Parameter
updated_param("m3.name", new_prefix); this->set_parameter(updated_param);``, which was a
write of ``?``. What the variable holds where the call reads it is its last write that
always runs before: not its first value when a call it is handed by reference
(``get_parameter(name, p)``) may have filled it since."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan

NODE = r"""
#include <rclcpp/rclcpp.hpp>
#include <string>

class Writer : public rclcpp::Node {
 public:
  Writer() : Node("writer") {
    rclcpp::Parameter updated("m3.name", std::string("m3_v2"));
    this->set_parameter(updated);
    rclcpp::Parameter braced{"rate", 2.0};
    set_parameters({braced});
    auto assigned = rclcpp::Parameter("gain", 1.0);
    set_parameter(assigned);
    rclcpp::Parameter twice("first", 1);
    twice = rclcpp::Parameter("second", 2);
    set_parameter(twice);
    rclcpp::Parameter filled("seed", 0);
    get_parameter("filled_from", filled);
    set_parameter(filled);
  }
};

int main(int argc, char** argv) {
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<Writer>());
}
"""


def test_a_parameter_object_names_its_write(write_tree) -> None:
    root = write_tree({
        "src/w/package.xml": package_xml("w", "ament_cmake").replace(
            "</package>", "<depend>rclcpp</depend></package>"),
        "src/w/CMakeLists.txt": "project(w)\nadd_executable(writer src/writer.cpp)\n",
        "src/w/src/writer.cpp": NODE,
    })
    result = extract_cpp([str(root / "src/w/src/writer.cpp")], scan([str(root / "src")]),
                         cache_dir=None)
    writes = sorted((c.location.line, c.name) for c in result.calls if c.kind == "write")
    # the last one: get_parameter filled the object with another parameter meanwhile
    assert writes == [(8, "m3.name"), (10, "rate"), (12, "gain"), (15, "second"),
                      (18, "?")]


LISTS = r"""
#include <rclcpp/rclcpp.hpp>
#include <string>
#include <vector>

class Lister : public rclcpp::Node {
 public:
  Lister() : Node("lister") {
    std::vector<rclcpp::Parameter> both{rclcpp::Parameter("a", 1), rclcpp::Parameter("b", 2)};
    set_parameters(both);
    std::vector<rclcpp::Parameter> assigned = {rclcpp::Parameter("c", 1)};
    set_parameters_atomically(assigned);
    std::vector<rclcpp::Parameter> grown{rclcpp::Parameter("d", 1)};
    grown.push_back(rclcpp::Parameter("e", 2));
    set_parameters(grown);
    std::vector<std::string> names{"rate", "gain"};
    auto values = get_parameters(names);
  }
};
"""


def test_a_local_list_of_parameters_names_each_write(write_tree) -> None:
    """``set_parameters(params)`` of a local ``std::vector`` built from a braced list
    writes each element's parameter, as ``set_parameters({...})`` does (and
    ``get_parameters(names)`` reads each name); not when the list may have changed
    between (``push_back``): then the write stays ``?``."""
    root = write_tree({
        "src/w/package.xml": package_xml("w", "ament_cmake").replace(
            "</package>", "<depend>rclcpp</depend></package>"),
        "src/w/CMakeLists.txt": "project(w)\nadd_library(lister SHARED src/lister.cpp)\n",
        "src/w/src/lister.cpp": LISTS,
    })
    result = extract_cpp([str(root / "src/w/src/lister.cpp")], scan([str(root / "src")]),
                         cache_dir=None)
    calls = sorted((c.location.line, c.kind, c.name) for c in result.calls
                   if c.kind in ("write", "read"))
    assert calls == [(9, "write", "a"), (9, "write", "b"), (11, "write", "c"),
                     (14, "write", "?"), (16, "read", "gain"), (16, "read", "rate")]
