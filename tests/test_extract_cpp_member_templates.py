"""A member named with C++'s ``template`` keyword on an object of a class known only by
name (``blackboard_->template set<T>("node", node_)``, navigation2's BtActionServer on
BehaviorTree.CPP's Blackboard before the library had a stand-in; here a library with
none) is declared a member template: before, it was a static
member, the statement an error, and the function that holds it, which calls the ROS API,
made its node partial (bt_navigator)."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.extract.cpp import extract_cpp, synthesis
from haros_arch.workspace import scan

SOURCE = """\
#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/string.hpp>
#include <treelib/factory.h>
using S = std_msgs::msg::String;
template <class NodeT>
class Server {
public:
  explicit Server(std::shared_ptr<NodeT> node) : node_(node) {}
  void configure() {
    blackboard_ = treelib::Blackboard::create();
    blackboard_->template set<std::shared_ptr<NodeT>>("node", node_);
    blackboard_->template set<int>(key_, 3);
    pub_ = node_->template create_publisher<S>("status", 1);
  }
  std::shared_ptr<NodeT> node_;
  treelib::Blackboard::Ptr blackboard_;
  std::string key_ = "depth";
  typename rclcpp::Publisher<S>::SharedPtr pub_;
};
class Nav : public rclcpp::Node {
public:
  Nav() : Node("nav") {
    server_ = std::make_shared<Server<rclcpp::Node>>(std::shared_ptr<rclcpp::Node>(this));
    server_->configure();
  }
  std::shared_ptr<Server<rclcpp::Node>> server_;
};
"""


def test_a_member_named_after_the_template_keyword_is_a_member_template(tmp_path) -> None:
    (tmp_path / "package.xml").write_text(package_xml("nav", "ament_cmake").replace(
        "</package>", "<depend>rclcpp</depend><depend>treelib</depend></package>"))
    source = tmp_path / "nav.cpp"
    source.write_text(SOURCE)
    result = extract_cpp([str(source)], scan([str(tmp_path)]), cache_dir=None)
    assert [(c.kind, c.name) for c in result.calls] == [("publish", "status")]
    codes = [d.code for d in result.diagnostics]
    assert "CPP_ERROR_NEAR_CALL" not in codes and "CPP_PARSE_ERROR" not in codes
    assert "CPP_NAMES_DECLARED" in codes


def test_the_declaration_takes_any_arguments_and_writes_none() -> None:
    names = synthesis.Names()
    names.read_members([b"bb->template set<int>(key, 3); x.template get<T>(); y.size();"])
    names.learn([("'put' following the 'template' keyword does not refer to a template",
                  None, 0)])
    header = names.header()
    for member in ("set", "get", "put"):
        # const references: a variable given to it is not written (a key stays a key)
        assert f"template <class... T, class... A> static haros_any &{member}(const A &...);" \
            in header
        assert f"static haros_any {member};" not in header
    assert "static haros_any size;" in header
