"""ROS 2 interfaces written in IDL (``msg/Name.idl``, rosidl's OMG IDL subset) are read
as their .msg / .srv would be: reference-system de8f3bc's reference_interfaces defines
Message4kb and TransmissionStats so, and every unit using them had the message
synthesised without fields (CPP_MESSAGE_UNKNOWN and a C++ error per field read)."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.extract.cpp import extract_cpp
from haros_arch.extract.cpp.interfaces import parse_definition
from haros_arch.workspace import scan

STATS = """// a comment
#include "pkg/msg/Other.idl"
module pkg {
  module msg {
    module Stats_Constants {
      const uint64 NAME_LENGTH = 48;
    };
    @verbatim (language="comment", text="the stats")
    struct Stats {
      uint64 timestamp;            // when
      char node_name[48];
      sequence<double> samples;
      sequence<int32, 5> last;
      string<10> label;
      boolean ok;
      @default (value=1.5)
      float gain;
      pkg::msg::Other other;
    };
  };
};
"""

SERVICE = """module pkg { module srv {
  struct Reset_Request { string reason; };
  struct Reset_Response { boolean done; };
}; };
"""


def test_an_idl_definition_has_the_fields_of_its_struct():
    stats = parse_definition("pkg", "Stats", STATS)
    assert [(f.type, f.name, f.array, f.constant) for f in stats.sections[0]] == [
        ("uint64", "NAME_LENGTH", None, "48"), ("uint64", "timestamp", None, None),
        ("char", "node_name", "48", None), ("float64", "samples", "", None),
        ("int32", "last", "", None), ("string<=10", "label", None, None),
        ("bool", "ok", None, None), ("float32", "gain", None, None),
        ("pkg/Other", "other", None, None)]
    reset = parse_definition("pkg", "Reset", SERVICE)
    assert [[(f.type, f.name) for f in section] for section in reset.sections] == [
        [("string", "reason")], [("bool", "done")]]


NODE = """#include <rclcpp/rclcpp.hpp>
#include "pkg/msg/stats.hpp"
int main(int argc, char ** argv) {
  rclcpp::init(argc, argv);
  auto node = rclcpp::Node::make_shared("stats");
  auto pub = node->create_publisher<pkg::msg::Stats>("stats", 10);
  pkg::msg::Stats msg;
  msg.timestamp = 1;
  msg.samples.push_back(0.5);
  msg.label = "x";
  pub->publish(msg);
  return 0;
}
"""


def test_a_node_using_an_idl_message_reads_its_fields(write_tree):
    root = write_tree({
        "src/pkg/package.xml": package_xml("pkg", "ament_cmake").replace(
            "</package>", "<depend>rclcpp</depend></package>"),
        "src/pkg/msg/Stats.idl": STATS.replace('#include "pkg/msg/Other.idl"', "").replace(
            "      pkg::msg::Other other;\n", ""),
        "src/pkg/src/stats.cpp": NODE,
    })
    result = extract_cpp([str(root / "src/pkg/src/stats.cpp")], scan([str(root / "src")]),
                         cache_dir=None)
    codes = {d.code for d in result.diagnostics}
    assert not codes & {"CPP_MESSAGE_UNKNOWN", "CPP_MESSAGE_FIELD", "CPP_PARSE_ERROR"}
    assert [(c.kind, c.name, c.type) for c in result.calls] == [
        ("publish", "stats", "pkg/msg/Stats")]
