"""Graph assembly: launch declarations meet node models and become a Computation Graph."""

from .build import build

__all__ = ["build"]
