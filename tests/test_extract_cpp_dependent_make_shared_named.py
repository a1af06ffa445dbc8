"""A class template on its action that builds its client with ``std::make_shared``:
MoveIt 1's ``ActionBasedControllerHandle<T>`` (moveit_simple_controller_manager)
makes ``std::make_shared<actionlib::SimpleActionClient<T>>(getActionName(), true)``,
the name of the controller the ``controller_list`` parameter gives. clang leaves that
call unresolved (its arguments depend on the template's parameter), and only the
make_shared of a class whose row has a fixed name (a tf listener) was read: the
controller manager plugin had no action client, so move_group made no goal on any
controller's ``follow_joint_trajectory`` and a controller's action server (the_italian
job's ARIAC forwarders) was reported without a client. The client is now made, its name
as far as the arguments are known, as for ``new actionlib::SimpleActionClient<T>(...)``.
"""

from __future__ import annotations

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import Workspace

SOURCE = """
#include <ros/ros.h>
#include <memory>
#include <actionlib/client/simple_action_client.h>
#include <actionlib_tutorials/FibonacciAction.h>
namespace ex {
class Base {
 public:
  explicit Base(const std::string& name) : name_(name) {}
  virtual ~Base() {}
 protected:
  std::string name_;
};
template <typename T>
class Handle : public Base {
 public:
  Handle(const std::string& name, const std::string& ns) : Base(name), namespace_(ns) {
    client_ = std::make_shared<actionlib::SimpleActionClient<T>>(getActionName(), true);
    other_ = std::make_shared<actionlib::SimpleActionClient<T>>(name_ + "/other", true);
  }
 protected:
  std::string getActionName() const {
    return namespace_.empty() ? name_ : name_ + "/" + namespace_;
  }
  std::string namespace_;
  std::shared_ptr<actionlib::SimpleActionClient<T>> client_, other_;
};
class FibHandle : public Handle<actionlib_tutorials::FibonacciAction> {
 public:
  FibHandle(const std::string& name, const std::string& ns)
      : Handle<actionlib_tutorials::FibonacciAction>(name, ns) {}
};
}
int main(int argc, char** argv) {
  ros::init(argc, argv, "fib");
  ros::NodeHandle nh("~");
  std::string name;
  nh.getParam("controller", name);
  ex::FibHandle h(name, "follow");
  ros::spin();
}
"""


def test_a_dependent_make_shared_of_an_action_client_is_a_client(tmp_path) -> None:
    (tmp_path / "ex").mkdir()
    (tmp_path / "ex" / "handle.cpp").write_text(SOURCE)
    result = extract_cpp([str(tmp_path / "ex" / "handle.cpp")],
                         Workspace(root=str(tmp_path)), cache_dir=None)
    clients = sorted((c.name, c.location.line) for c in result.calls
                     if c.kind == "action-client")
    assert clients == [("?/follow", 18), ("?/other", 19)]
    unresolved = sorted(d.location.line for d in result.diagnostics
                        if d.code == "CPP_CALL_UNRESOLVED")
    assert unresolved == [18, 19]
