"""A name made of a member that holds the node's name as constructed: navigation2's
``ClearCostmapService`` serves ``"clear_entirely_" + costmap_.getName()``, and
``Costmap2DROS::name_`` is what each constructor hands its LifecycleNode base as the
node's name (``"costmap"`` for the default constructor, the name argument for the
other). The costmap program constructs ``costmap``; a nav2 server constructs its own
(``local_costmap``), a node of the server's process (``plugins.hosts.Child``) whose
calls are the program's. The server's clients call ``clear_entirely_local_costmap``:
the child's service was ``clear_entirely_costmap`` (Humble, whose program passes the
name) or ``clear_entirely_?`` (Rolling, whose constructors disagree)."""

from __future__ import annotations

import pytest

from haros_arch.extract.cpp import extract_cpp
from haros_arch.model import PrimitiveCall
from haros_arch.plugins.attach import _constructed
from haros_arch.workspace import scan
from tests.conftest import package_xml

HEADER = """
#pragma once
#include <string>
#include <memory>
#include <rclcpp/rclcpp.hpp>
#include <rclcpp_lifecycle/lifecycle_node.hpp>
#include <std_srvs/srv/empty.hpp>
namespace cm {
class Costmap : public rclcpp_lifecycle::LifecycleNode
{
public:
  %s
  Costmap(const std::string & name, const std::string & ns, const rclcpp::NodeOptions & o);
  std::string getName() const { return name_; }
  void configure();
  std::string topicName() const { return topic_; }
private:
  std::string name_;
  std::string topic_;
};
class ClearService
{
public:
  ClearService(rclcpp_lifecycle::LifecycleNode::SharedPtr node, Costmap & costmap);
private:
  Costmap & costmap_;
  rclcpp::Service<std_srvs::srv::Empty>::SharedPtr clear_, other_;
};
}
"""

# Rolling's costmap: a default constructor names the node ``costmap``
DEFAULT = ("explicit Costmap(const rclcpp::NodeOptions & options = rclcpp::NodeOptions());", """
Costmap::Costmap(const rclcpp::NodeOptions & options)
: rclcpp_lifecycle::LifecycleNode("costmap", "", options), name_("costmap"), topic_("grid")
{
}
""", "")
# Humble's: a constructor of the name alone delegates, the program names it
DELEGATING = ("explicit Costmap(const std::string & name);", """
Costmap::Costmap(const std::string & name)
: Costmap(name, "/", rclcpp::NodeOptions()) {}
""", '"costmap"')

NODE = """
#include "cm/costmap.hpp"
namespace cm {
%s
Costmap::Costmap(const std::string & name, const std::string & ns,
                 const rclcpp::NodeOptions & o)
: rclcpp_lifecycle::LifecycleNode(name, ns, o), name_(name), topic_(ns)
{
}
void Costmap::configure()
{
  auto service = std::make_shared<ClearService>(shared_from_this(), *this);
  (void)service;
}
}
"""

SERVICE = """
#include "cm/costmap.hpp"
namespace cm {
static void cb(const std::shared_ptr<std_srvs::srv::Empty::Request>,
               std::shared_ptr<std_srvs::srv::Empty::Response>) {}
ClearService::ClearService(rclcpp_lifecycle::LifecycleNode::SharedPtr node,
                           Costmap & costmap)
: costmap_(costmap)
{
  clear_ = node->create_service<std_srvs::srv::Empty>(
    "clear_entirely_" + costmap_.getName(), &cb);
  other_ = node->create_service<std_srvs::srv::Empty>(
    "clear_" + costmap_.topicName(), &cb);
}
}
"""

MAIN = """
#include "cm/costmap.hpp"
int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  auto node = std::make_shared<cm::Costmap>(%s);
  node->configure();
  rclcpp::spin(node->get_node_base_interface());
}
"""


@pytest.mark.parametrize(("constructors", "own"), [
    (DEFAULT, "clear_entirely_?"),  # its "costmap" and the other's name disagree
    (DELEGATING, "clear_entirely_costmap"),
])
def test_a_member_holding_the_node_name_is_named_per_construction(
        write_tree, constructors: tuple[str, str, str], own: str) -> None:
    declared, defined, constructed = constructors
    root = write_tree({
        "cm/package.xml": package_xml("cm", "ament_cmake"),
        "cm/include/cm/costmap.hpp": HEADER % declared,
        "cm/src/costmap.cpp": NODE % defined,
        "cm/src/clear_service.cpp": SERVICE,
        "cm/src/main.cpp": MAIN % constructed,
    })
    sources = [str(root / "cm" / "src" / name)
               for name in ("main.cpp", "costmap.cpp", "clear_service.cpp")]
    result = extract_cpp(sources, scan([str(root)]), cache_dir=None,
                         include_dirs=[str(root / "cm" / "include")])
    servers = {c.name: c for c in result.calls if c.kind == "server"}
    clear = servers[own]
    # the program's own construction names it; the run is the node's name as built
    assert clear.name_built == "clear_entirely_?"
    # a member each constructor sets otherwise (the namespace, not the node's name)
    # is no name as constructed
    others = [c for c in servers.values() if c.name.startswith("clear_") and c is not clear]
    assert others and all(c.name_built is None for c in others)
    # a host's code constructs it as local_costmap: its own name there
    assert _constructed(clear, "local_costmap").name == "clear_entirely_local_costmap"
    assert _constructed(others[0], "local_costmap") == others[0]


def test_a_call_named_otherwise_is_left() -> None:
    call = PrimitiveCall("server", "clear", "std_srvs/srv/Empty")
    assert _constructed(call, "local_costmap") is call
