"""rclpy QoS values: an ``int`` depth, a ``QoSProfile(...)`` call, a preset profile
(``qos_profile_sensor_data``, ``QoSPresetProfiles.SENSOR_DATA.value``), as a dictionary
of policies (``rclpy.DEFAULT_QOS`` for what is not given).
"""

from __future__ import annotations

import ast
from typing import Any

from ...model.values import Value
from . import rclpy
from .objects import Frame, QoS, Ref
from .scopes import EvaluatorBase


class QoSProfiles(EvaluatorBase):
    def qos(self, value: object) -> dict[str, Any] | None:
        if isinstance(value, bool):
            return None
        if isinstance(value, int):
            return {**rclpy.DEFAULT_QOS, "depth": value}
        if isinstance(value, QoS):
            return value.as_dict()
        preset = as_profile(value)
        return preset.as_dict() if preset is not None else None

    def qos_profile(self, expr: ast.Call, frame: Frame) -> QoS:
        policies: dict[str, Any] = dict(rclpy.DEFAULT_QOS)
        for keyword in expr.keywords:
            if keyword.arg == "depth":
                depth = self.eval(keyword.value, frame)
                policies["depth"] = depth if isinstance(depth, int) else None
            elif keyword.arg in rclpy.POLICIES:
                policies[keyword.arg] = _policy(self.eval(keyword.value, frame),
                                                rclpy.POLICIES[keyword.arg])
            elif keyword.arg is None:
                base = self.qos(self.eval(keyword.value, frame))
                if base:
                    policies.update(base)
        return QoS(tuple(policies.items()))


def as_profile(value: object) -> QoS | None:
    """A profile, or a preset profile named (``qos_profile_sensor_data``,
    ``QoSPresetProfiles.SENSOR_DATA.value``) as one, else None."""
    if isinstance(value, QoS):
        return value
    if isinstance(value, Ref):
        parts = value.qualname.split(".")
        if parts[-1] in rclpy.PRESETS:
            return QoS(tuple(rclpy.PRESETS[parts[-1]].items()))
        if len(parts) >= 2 and parts[-1] == "value" and parts[-2] in rclpy.PRESET_ENUM:
            return QoS(tuple(rclpy.PRESETS[rclpy.PRESET_ENUM[parts[-2]]].items()))
    return None


def with_policy(qos: QoS, attr: str, value: object) -> QoS | None:
    """``qos`` after ``qos.<attr> = value`` (``profile.durability =
    DurabilityPolicy.TRANSIENT_LOCAL``, ``profile.depth = 1``: rclpy's QoSProfile
    properties), or None when ``attr`` is no policy of it."""
    policies = qos.as_dict()
    if attr == "depth":
        policies["depth"] = value if isinstance(value, int) and not isinstance(
            value, bool) else None
    elif attr in rclpy.POLICIES:
        policies[attr] = _policy(value, rclpy.POLICIES[attr])
    else:
        return None
    return QoS(tuple(policies.items()))


def _policy(value: object, words: tuple[str, ...]) -> str | None:
    """``ReliabilityPolicy.BEST_EFFORT`` (or its older spellings) -> ``best_effort``."""
    if isinstance(value, Ref):
        last = value.qualname.split(".")[-1].lower()
        for word in sorted(words, key=len, reverse=True):
            if last == word or last.endswith("_" + word):
                return word
    if isinstance(value, Value) and value.literal in words:
        return value.literal
    return None
