"""haros_arch: static extraction and analysis of the ROS Computation Graph."""

__version__ = "0.1.0"
SCHEMA = "haros-arch/1"
