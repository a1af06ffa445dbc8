"""Shared pieces of the evaluators of Python-like code we read (see ``budget``)."""
