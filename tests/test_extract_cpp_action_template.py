"""A class template on its action (bwi_common's InterruptableActionServer<ActionSpec>):
actionlib's ``ACTION_DEFINITION(ActionSpec)`` gives it the action's types, and its
constructor builds ``new actionlib::ActionServer<ActionSpec>(n_, name, ...)`` and
``new actionlib::SimpleActionClient<ActionSpec>(name, true)``, types clang leaves
dependent. The stand-ins had no ACTION_DEFINITION (43 clang errors, the services' names
``?/?_interruptable/pause``) and the new-expressions were not read: the node had neither
its action server nor its action client."""

from __future__ import annotations

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import Workspace

SOURCE = """
#include <ros/ros.h>
#include <actionlib/server/action_server.h>
#include <actionlib/client/simple_action_client.h>
#include <actionlib/action_definition.h>
#include <actionlib_tutorials/FibonacciAction.h>
#include <std_srvs/Empty.h>
namespace ex {
template <class ActionSpec>
class Interruptable {
 public:
  ACTION_DEFINITION(ActionSpec);
  typedef typename actionlib::ActionServer<ActionSpec>::GoalHandle GoalHandle;
  Interruptable(ros::NodeHandle n, std::string name) : n_(n) {
    std::string own = name + "_interruptable";
    as_.reset(new actionlib::ActionServer<ActionSpec>(n_, own,
        boost::bind(&Interruptable::goalCallback, this, _1), false));
    pause_ = n_.advertiseService(own + "/pause", &Interruptable::pause, this);
    ac_.reset(new actionlib::SimpleActionClient<ActionSpec>(name, true));
  }
  void goalCallback(GoalHandle goal) {
    GoalConstPtr given = goal.getGoal();
    ac_->sendGoal(*given, typename actionlib::SimpleActionClient<ActionSpec>::SimpleDoneCallback(),
                  typename actionlib::SimpleActionClient<ActionSpec>::SimpleActiveCallback());
  }
  bool pause(std_srvs::Empty::Request&, std_srvs::Empty::Response&) { return true; }
  ros::NodeHandle n_;
  ros::ServiceServer pause_;
  boost::shared_ptr<actionlib::ActionServer<ActionSpec> > as_;
  boost::shared_ptr<actionlib::SimpleActionClient<ActionSpec> > ac_;
};
}
int main(int argc, char** argv) {
  ros::init(argc, argv, "fib");
  ros::NodeHandle nh;
  ex::Interruptable<actionlib_tutorials::FibonacciAction> as(nh, "fibonacci");
  ros::spin();
}
"""


def test_an_action_server_and_client_of_a_class_template_on_its_action(tmp_path) -> None:
    (tmp_path / "ex").mkdir()
    (tmp_path / "ex" / "srv.cpp").write_text(SOURCE)
    result = extract_cpp([str(tmp_path / "ex" / "srv.cpp")], Workspace(root=str(tmp_path)),
                         cache_dir=None)
    assert sorted((c.kind, c.name, c.location.line) for c in result.calls) == [
        ("action-client", "fibonacci", 19),
        ("action-server", "fibonacci_interruptable", 16),
        ("server", "fibonacci_interruptable/pause", 18),
    ]
    assert [d for d in result.diagnostics if d.code == "CPP_PARSE_ERROR"] == []
