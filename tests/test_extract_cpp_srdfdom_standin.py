"""srdfdom's semantic robot model stands in when the workspace has no srdfdom (MoveIt
has it installed): declared permissively, ``const srdf::ModelSharedPtr& srdf = loader->
getSRDF() ? loader->getSRDF() : std::make_shared<srdf::Model>();`` (MoveIt's
robot_model_loader.cpp, in the function that reads the robot description parameters)
was an ambiguous conditional, and move_group, servo and every MoveIt tool building a
RobotModelLoader were partial for it. With srdfdom in the workspace, its own header is
read."""

from __future__ import annotations

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan
from tests.conftest import package_xml

SOURCE = """#include <rclcpp/rclcpp.hpp>
#include <srdfdom/model.h>
#include <urdf/model.h>
#include <memory>

class Loader
{
public:
  const srdf::ModelSharedPtr & getSRDF() const { return srdf_; }
  const urdf::ModelInterfaceSharedPtr & getURDF() const { return urdf_; }
  srdf::ModelSharedPtr srdf_;
  urdf::ModelInterfaceSharedPtr urdf_;
};

void configure(const rclcpp::Node::SharedPtr & node, const std::shared_ptr<Loader> & loader)
{
  const srdf::ModelSharedPtr & srdf =
    loader->getSRDF() ? loader->getSRDF() : std::make_shared<srdf::Model>();
  for (const srdf::Model::Group & group : srdf->getGroups()) {
    node->declare_parameter<std::string>(
      "robot_description_kinematics." + group.name_ + ".kinematics_solver", "");
  }
  node->declare_parameter("robot_description_planning.joint_limits_count",
                          static_cast<int>(srdf->getVirtualJoints().size()));
}
"""


def test_srdfdom_model_parses_where_the_workspace_has_none(tmp_path) -> None:
    (tmp_path / "package.xml").write_text(package_xml("loader", "ament_cmake"))
    source = tmp_path / "loader.cpp"
    source.write_text(SOURCE)
    result = extract_cpp([str(source)], scan([str(tmp_path)]), cache_dir=None,
                         distro="jazzy")
    assert sorted((c.kind, c.name) for c in result.calls) == [
        ("declare", "robot_description_kinematics.?.kinematics_solver"),
        ("declare", "robot_description_planning.joint_limits_count")]
    assert [d.message for d in result.diagnostics if d.code in (
        "CPP_PARSE_ERROR", "CPP_ERROR_NEAR_CALL", "CPP_NAMES_DECLARED")] == []
