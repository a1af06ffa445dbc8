"""In a unit whose wrappers include one named like a method of a ROS client library's
class (autoware_utils' ``DebugPublisher::publish`` makes publishers), a call of that
name that a template leaves unresolved, on an object the code declares of the library's
class (``pub_ptr_->publish(msg)``, ``pub_ptr_`` a ``typename
rclcpp::Publisher<ExportObj>::SharedPtr``: Autoware's fusion node template) is the
library's method: no call is hidden there, so it is no ``CPP_CALL_MISSED`` and does not
leave five fusion nodes partial. The same call on an object of a template parameter's
type may be the wrapper's, and is read as its call."""

from __future__ import annotations

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan
from tests.conftest import package_xml

SOURCE = """#include <rclcpp/rclcpp.hpp>
#include <std_msgs/msg/header.hpp>
#include <std_msgs/msg/string.hpp>
#include <map>
#include <string>

class DebugPublisher
{
public:
  explicit DebugPublisher(rclcpp::Node * node) : node_(node) {}
  template <class T>
  void publish(const std::string & name, const T & data)
  {
    if (pubs_.count(name) == 0) {
      pubs_[name] = node_->create_publisher<T>("debug/" + name, 1);
    }
  }

private:
  rclcpp::Node * node_;
  std::map<std::string, rclcpp::PublisherBase::SharedPtr> pubs_;
};

template <class Msg>
class Fusion : public rclcpp::Node
{
public:
  Fusion() : rclcpp::Node("fusion"), debug_(this) {}

  void export_msg(const Msg & msg)
  {
    if (!pub_ptr_) {
      return;
    }
    pub_ptr_->publish(msg);
  }

  template <class P>
  void forward(P & publisher, const Msg & msg)
  {
    int copies = 1;
    (void)copies;
    publisher.publish("forwarded", msg);
  }

  void debug()
  {
    int unused = 0;
    (void)unused;
    debug_.publish("stamp", std_msgs::msg::Header());
  }

protected:
  typename rclcpp::Publisher<Msg>::SharedPtr pub_ptr_;
  DebugPublisher debug_;
};

int helper() { return undeclared_function(3); }

template class Fusion<std_msgs::msg::String>;

class Node : public Fusion<std_msgs::msg::String>
{
public:
  Node() { pub_ptr_ = create_publisher<std_msgs::msg::String>("output", 1); }
};
"""


def test_a_library_method_in_a_template_hides_no_call(tmp_path) -> None:
    (tmp_path / "package.xml").write_text(package_xml("fusion", "ament_cmake"))
    source = tmp_path / "fusion.cpp"
    source.write_text(SOURCE)
    result = extract_cpp([str(source)], scan([str(tmp_path)]), cache_dir=None,
                         distro="jazzy")
    assert sorted(c.name for c in result.calls) == ["debug/forwarded", "debug/stamp",
                                                    "output"]
    assert [d.message for d in result.diagnostics if d.code == "CPP_CALL_MISSED"] == []
