"""Why a ROS 1 substitution's part is not known is kept as a value: the detail said and,
for a ``$(find)`` of a package not here, that package. The loader's ``resolve(command=
True)`` (a ``<param command=...>`` never run, whose program's package is not needed)
dropped those reasons by the text they begin with (``"package NAME "``), a message read
back; it now drops them by the package recorded. What is said is unchanged
(tests/test_launch_ros1_xacro_not_here.py)."""

from __future__ import annotations

from haros_arch.launch.ros1.substitution import Context, Reason, substitute
from haros_arch.model.values import Value


def _context() -> Context:
    return Context({"robot": Value.of("r2")}, {}, lambda name: None, "/ws/a.launch",
                   declared=lambda name: name == "model",
                   absence=lambda name: "is not installed here")


def test_a_package_not_found_is_recorded_with_its_name() -> None:
    ctx = _context()
    value = substitute("$(find xacro)/xacro $(find bot_description)/$(arg robot).xacro "
                       "$(env HOME)", ctx)
    assert not value.is_known
    substitute("$(eval arg('model') + 'x')", ctx)
    # (``env`` is substituted before ``find``, as roslaunch does)
    assert ctx.unknown == [
        Reason("environment variable HOME is not set"),
        Reason("package xacro is not installed here", "xacro"),
        Reason("package bot_description is not installed here", "bot_description"),
        Reason("$(eval arg('model') + 'x') depends on unknown values")]


def test_a_reason_of_no_package_is_none_whatever_its_text() -> None:
    # an environment variable whose text reads like a package's reason is no package
    ctx = _context()
    substitute("$(env package)", ctx)
    assert ctx.unknown == [Reason("environment variable package is not set")]
    assert ctx.unknown[0].package is None
