"""Reporters: how a model and its diagnostics are shown (text now; JSON via serialise)."""
