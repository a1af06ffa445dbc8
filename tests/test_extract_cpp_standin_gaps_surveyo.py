"""Stand-in gaps seen on real code (bench/README, survey O): ublox_dgnss' node registers
its shutdown with ``get_node_base_interface()->get_context()->on_shutdown(lambda)``
(rclcpp's ``Context::on_shutdown``, which returns the callback) and prints a frame in hex
with ``std::uppercase``, and writes its USB buffers as glibc's ``u_char *``
(``<sys/types.h>``'s BSD names): the stand-ins declared none of them, so each was a C++ error in a
function that calls the ROS API and the node was partial (CPP_NODE_PARTIAL warnings)."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan

SOURCE = """#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/string.hpp>
#include <iomanip>
#include <sstream>
#include <unistd.h>
#include <vector>

void write_buffer(u_char * buf, size_t size);
u_int count(u_short a, u_long b);

class Gnss : public rclcpp::Node {
public:
  Gnss() : rclcpp::Node("gnss")
  {
    get_node_base_interface()->get_context()->on_shutdown([this]() { running_ = false; });
    std::ostringstream text;
    text << std::hex << std::uppercase << std::setw(2) << 10 << std::nouppercase
         << std::showbase << std::oct << 8 << std::noshowbase << std::dec;
    std::vector<unsigned char> frame(4);
    write_buffer(&frame[0], frame.size());
    pub_ = create_publisher<std_msgs::msg::String>("fix", 10);
  }
private:
  bool running_ = true;
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr pub_;
};

int main(int argc, char** argv) {
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<Gnss>());
}
"""


def test_context_on_shutdown_and_stream_manipulators(tmp_path) -> None:
    (tmp_path / "package.xml").write_text(package_xml("gnss", "ament_cmake"))
    source = tmp_path / "gnss.cpp"
    source.write_text(SOURCE)
    result = extract_cpp([str(source)], scan([str(tmp_path)]), cache_dir=None,
                         distro="humble")
    assert [(d.location.line, d.message) for d in result.diagnostics
            if d.code in ("CPP_PARSE_ERROR", "CPP_ERROR_NEAR_CALL", "CPP_NAMES_DECLARED",
                          "CPP_INCLUDE_MISSING")] == []
    assert [c.name for c in result.calls if c.kind == "publish"] == ["fix"]
