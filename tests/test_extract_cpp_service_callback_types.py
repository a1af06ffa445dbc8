"""rclcpp's service and client callback types as code names them
(``rclcpp::Service<S>::CallbackType``, ``CallbackWithHeaderType``, ``SharedRequest``,
``rclcpp::Client<S>::CallbackType``): Autoware's component_interface_utils wraps a
service callback as ``typename rclcpp::Service<...>::CallbackType``, and without it the
wrapper's class was an error in every node building an interface adaptor."""

from __future__ import annotations

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan
from tests.conftest import package_xml

SOURCE = """#include <rclcpp/rclcpp.hpp>
#include <std_srvs/srv/trigger.hpp>

using Trigger = std_srvs::srv::Trigger;

class Gate : public rclcpp::Node
{
public:
  Gate() : Node("gate")
  {
    rclcpp::Service<Trigger>::CallbackType callback =
      [](const rclcpp::Service<Trigger>::SharedRequest, rclcpp::Service<Trigger>::SharedResponse
           response) { response->success = true; };
    service_ = create_service<Trigger>("~/trigger", callback);
    rclcpp::Service<Trigger>::CallbackWithHeaderType with_header =
      [](const std::shared_ptr<rmw_request_id_t>, const std::shared_ptr<Trigger::Request>,
         std::shared_ptr<Trigger::Response>) {};
    headed_ = create_service<Trigger>("~/trigger_with_header", with_header);
    client_ = create_client<Trigger>("/other/trigger");
    rclcpp::Client<Trigger>::CallbackType done = [](rclcpp::Client<Trigger>::SharedFuture) {};
    client_->async_send_request(std::make_shared<Trigger::Request>(), done);
  }

private:
  rclcpp::Service<Trigger>::SharedPtr service_, headed_;
  rclcpp::Client<Trigger>::SharedPtr client_;
};
"""


def test_service_and_client_callback_types_parse(tmp_path) -> None:
    (tmp_path / "package.xml").write_text(package_xml("gate", "ament_cmake"))
    source = tmp_path / "gate.cpp"
    source.write_text(SOURCE)
    result = extract_cpp([str(source)], scan([str(tmp_path)]), cache_dir=None,
                         distro="humble")
    assert sorted((c.kind, c.name) for c in result.calls) == [
        ("client", "/other/trigger"), ("server", "~trigger"),
        ("server", "~trigger_with_header")]
    assert [d.message for d in result.diagnostics if d.code in (
        "CPP_PARSE_ERROR", "CPP_ERROR_NEAR_CALL", "CPP_NAMES_DECLARED")] == []
