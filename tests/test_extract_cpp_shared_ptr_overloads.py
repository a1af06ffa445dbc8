"""The ``std::shared_ptr`` stand-in converts a ``shared_ptr<Y>`` to a ``shared_ptr<T>``
only when ``Y*`` converts to ``T*``, as the real one: MoveIt's publish_scene_from_text
builds ``PlanningScene ps(rml->getModel())`` where PlanningScene has a constructor on a
``RobotModelConstPtr`` and a private one on a ``PlanningSceneConstPtr``; the
unconstrained conversion made the two ambiguous, a parse error beside the node's
publisher. A class the parse declared permissively (from a header not found) still
converts, as before, and so does a base to its derived class (the stand-ins return
rclcpp's ``TimerBase`` where the real ``create_timer`` returns a ``GenericTimer<F>``)."""

from __future__ import annotations

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import Workspace

SOURCE = """
#include <ros/ros.h>
#include <memory>
#include <std_msgs/String.h>
#include <missing/unknown_model.h>

struct RobotModel {};
struct Base { virtual ~Base(); };
struct Derived : Base {};
class Scene;
typedef std::shared_ptr<const Scene> SceneConstPtr;
typedef std::shared_ptr<const RobotModel> RobotModelConstPtr;
class Scene {
public:
  Scene(const RobotModelConstPtr& model);
private:
  Scene(const SceneConstPtr& parent);
};
struct Loader { const std::shared_ptr<RobotModel>& getModel() const; };
void take(std::shared_ptr<Base> b);
void take_model(std::shared_ptr<unknown::Model> m);
std::shared_ptr<Base> make_base();
std::shared_ptr<Derived> make_derived() { return make_base(); }

int main(int argc, char** argv) {
  ros::init(argc, argv, "n");
  ros::NodeHandle nh;
  std::shared_ptr<Loader> rml;
  Scene ps(rml->getModel());
  take(std::make_shared<Derived>());
  std::shared_ptr<Base> b;
  b = std::make_shared<Derived>();
  std::shared_ptr<unknown::Other> other;
  take_model(other);
  ros::Publisher pub = nh.advertise<std_msgs::String>("out", 1);
  return 0;
}
"""


def test_overloads_on_unrelated_shared_ptrs_are_not_ambiguous(tmp_path) -> None:
    source = tmp_path / "scene.cpp"
    source.write_text(SOURCE)
    result = extract_cpp([str(source)], Workspace(root=str(tmp_path)), cache_dir=None)
    assert [(c.kind, c.name) for c in result.calls] == [("publish", "out")]
    assert [d.message for d in result.diagnostics
            if d.code in ("CPP_PARSE_ERROR", "CPP_ERROR_NEAR_CALL")] == []
