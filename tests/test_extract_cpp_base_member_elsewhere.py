"""A string member of a base class whose constructor, defined in another file of the
node, sets it from its parameter: navigation2's collision monitor builds one ``Scan``,
``PointCloud``, ... per element of ``observation_sources`` (collision_monitor_node.cpp),
each passing the element to ``Source``'s constructor (source.cpp), which keeps it in
``source_name_``; pointcloud.cpp reads ``source_name_ + ".min_height"``. The member is
what those files give it (``links.MEMBER``), so the read is one per element of the
list (was ``~/?.min_height``)."""

from __future__ import annotations

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan
from tests.conftest import package_xml

HEADER = """
#include <rclcpp/rclcpp.hpp>
class Source {
public:
  Source(rclcpp::Node * node, const std::string & source_name, double timeout);
  virtual ~Source() {}
  virtual bool configure() = 0;
protected:
  rclcpp::Node * node_;
  std::string source_name_;
  std::string fixed_;
  double timeout_;
};
class Cloud : public Source {
public:
  Cloud(rclcpp::Node * node, const std::string & source_name, double timeout);
  bool configure() override;
};
"""

SOURCE = """
#include "source.hpp"
Source::Source(rclcpp::Node * node, const std::string & source_name, double timeout)
: node_(node), source_name_(source_name), timeout_(timeout) {}
"""

CLOUD = """
#include "source.hpp"
Cloud::Cloud(rclcpp::Node * node, const std::string & source_name, double timeout)
: Source(node, source_name, timeout) {}
bool Cloud::configure() {
  node_->declare_parameter(source_name_ + ".min_height", 0.05);
  node_->declare_parameter(fixed_ + ".max_height", 0.5);
  return true;
}
"""

NODE = """
#include "source.hpp"
class Monitor : public rclcpp::Node {
public:
  Monitor() : rclcpp::Node("monitor") {
    std::vector<std::string> names = declare_parameter<std::vector<std::string>>(
      "observation_sources", std::vector<std::string>());
    for (std::string name : names) {
      auto s = std::make_shared<Cloud>(this, name, 2.0);
      s->configure();
      sources_.push_back(s);
    }
  }
  std::vector<std::shared_ptr<Source>> sources_;
};
int main(int argc, char ** argv) {
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<Monitor>());
}
"""


def test_a_base_member_set_in_another_file_names_the_read(write_tree) -> None:
    root = write_tree({"cm/package.xml": package_xml("cm", "ament_cmake"),
                       "cm/src/source.hpp": HEADER, "cm/src/source.cpp": SOURCE,
                       "cm/src/cloud.cpp": CLOUD, "cm/src/node.cpp": NODE})
    result = extract_cpp([str(root / "cm" / "src" / name)
                          for name in ("node.cpp", "source.cpp", "cloud.cpp")],
                         scan([str(root)]), cache_dir=None)
    made = sorted((c.name, c.name_param, c.name_each) for c in result.calls
                  if c.kind == "declare" and c.name != "observation_sources")
    assert made == [
        ("?.max_height", None, None),  # a member no constructor sets: unknown
        ("?.min_height", "observation_sources", "."),
    ]
