"""A plugin class that is a specialisation of a class template, described and exported
as such (grid_map_cv's filter_plugins.xml: ``type="grid_map::InpaintFilter<
grid_map::GridMap>"``, exported by ``PLUGINLIB_EXPORT_CLASS(grid_map::InpaintFilter<
grid_map::GridMap>, filters::FilterBase<grid_map::GridMap>)`` in InpaintFilter.cpp): the
type was read as a factory template registered for its argument (mavros'
``PluginFactoryTemplate<Imu>``, exported by ``MAVROS_PLUGIN_REGISTER(Imu)``), so the class
looked for was ``grid_map::GridMap``, which no file exports: PLUGIN_CLASS_NOT_BUILT and
a node with no source. The argument stands for the class only when the library exports
it and not the specialisation."""

from __future__ import annotations

from haros_arch.pipeline import Options, analyse
from haros_arch.project import load

DESCRIPTION = """\
<class_libraries>
  <library path="lib/libmaps">
    <class name="maps/Inpaint" type="maps::InpaintFilter&lt;maps::Map&gt;"
           base_class_type="filters::FilterBase&lt;maps::Map&gt;"/>
  </library>
</class_libraries>
"""
FILTER = """\
#include <filters/filter_base.h>
#include <pluginlib/class_list_macros.h>
#include <ros/ros.h>
namespace maps {
struct Map {};
template <typename T>
class InpaintFilter : public filters::FilterBase<T> {
 public:
  bool configure() override { return this->getParam("radius", radius_); }
  bool update(const T& in, T& out) override { out = in; return true; }
  double radius_;
};
}  // namespace maps
PLUGINLIB_EXPORT_CLASS(maps::InpaintFilter<maps::Map>, filters::FilterBase<maps::Map>)
"""


def test_a_plugin_that_is_a_template_specialisation_is_built_by_its_file(write_tree):
    root = write_tree({
        "src/maps/package.xml": (
            "<package format='2'><name>maps</name><version>1.0.0</version>"
            "<description>d</description><maintainer email='a@b.c'>m</maintainer>"
            "<license>BSD</license><buildtool_depend>catkin</buildtool_depend>"
            "<depend>filters</depend><export>"
            "<filters plugin='${prefix}/filter_plugins.xml'/></export></package>"),
        "src/maps/CMakeLists.txt": (
            "project(maps)\nfind_package(catkin REQUIRED COMPONENTS filters)\n"
            "catkin_package()\nadd_library(maps src/processing.cpp src/inpaint.cpp)\n"),
        "src/maps/filter_plugins.xml": DESCRIPTION,
        "src/maps/src/processing.cpp": "namespace maps { int twice(int x) { return 2 * x; } }\n",
        "src/maps/src/inpaint.cpp": FILTER,
        "project.yaml": "project: p\nworkspace: src\nconfigurations: {}\n",
    })
    model = analyse(load(str(root / "project.yaml")), {}, Options(cache_dir=None, jobs=1))
    assert "PLUGIN_CLASS_NOT_BUILT" not in [d.code for d in model.diagnostics]
    inpaint = next(n for n in model.nodes if n.name == "maps/maps/Inpaint")
    # its file, and the helper file that exports nothing (``narrow`` keeps it)
    assert inpaint.sources == ["maps/src/processing.cpp", "maps/src/inpaint.cpp"]
    assert inpaint.completeness != "unknown"
