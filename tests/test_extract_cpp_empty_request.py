"""rosidl_generator_cpp gives a ROS 2 message (or request, response) without fields one
member, ``uint8_t structure_needs_at_least_one_member``, and code sets it (aerostack2's
as2_geozones.cpp:261 ``request->structure_needs_at_least_one_member = 0;`` on an empty
``GetOrigin`` request): the synthesised header declares it too, so the function that
does it parses and its calls are not said to be missed."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan

SOURCE = """\
#include <memory>
#include <rclcpp/rclcpp.hpp>
#include <geo/srv/get_origin.hpp>

class Zones : public rclcpp::Node {
 public:
  Zones() : rclcpp::Node("zones") {
    client_ = create_client<geo::srv::GetOrigin>("get_origin");
    auto request = std::make_shared<geo::srv::GetOrigin::Request>();
    request->structure_needs_at_least_one_member = 0;
    client_->async_send_request(request);
  }
  rclcpp::Client<geo::srv::GetOrigin>::SharedPtr client_;
};
"""


def test_an_empty_request_has_rosidl_s_placeholder_member(tmp_path) -> None:
    (tmp_path / "package.xml").write_text(package_xml("geo", "ament_cmake").replace(
        "</package>", "<depend>rclcpp</depend></package>"))
    (tmp_path / "srv").mkdir()
    (tmp_path / "srv" / "GetOrigin.srv").write_text("# empty request\n---\nbool success\n")
    source = tmp_path / "zones.cpp"
    source.write_text(SOURCE)
    result = extract_cpp([str(source)], scan([str(tmp_path)]), cache_dir=None)
    assert [(c.kind, c.name, c.type) for c in result.calls] == [
        ("client", "get_origin", "geo/srv/GetOrigin")]
    assert [d.message for d in result.diagnostics if d.code == "CPP_PARSE_ERROR"] == []
