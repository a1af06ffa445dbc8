"""The metamodel: plain dataclasses with locations and conditions."""

from .conditions import Condition
from .diagnostic import Diagnostic
from .location import NOWHERE, Location
from .model import Model
from .rosname import RosName
from .runtime import (
    LINK_CLASSES,
    Action,
    ActionClientLink,
    ActionServerLink,
    Configuration,
    Link,
    NodeInstance,
    Parameter,
    ParamReadLink,
    ParamWriteLink,
    PublishLink,
    Resource,
    Service,
    ServiceClientLink,
    ServiceProviderLink,
    SubscribeLink,
    Topic,
)
from .source import Dependency, Node, Package, Plugin, PrimitiveCall, SourceFile
from .values import Unknown, Value

__all__ = [
    "LINK_CLASSES",
    "NOWHERE",
    "Action",
    "ActionClientLink",
    "ActionServerLink",
    "Condition",
    "Configuration",
    "Dependency",
    "Diagnostic",
    "Link",
    "Location",
    "Model",
    "Node",
    "NodeInstance",
    "Package",
    "ParamReadLink",
    "ParamWriteLink",
    "Parameter",
    "Plugin",
    "PrimitiveCall",
    "PublishLink",
    "Resource",
    "RosName",
    "Service",
    "ServiceClientLink",
    "ServiceProviderLink",
    "SourceFile",
    "SubscribeLink",
    "Topic",
    "Unknown",
    "Value",
]
