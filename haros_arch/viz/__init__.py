"""The interactive HTML report: one self-contained file with the graph drawn by D3.

    write_report(model_data, findings, workspace_root, "report.html")
"""

from .html import ReportError, render_report, write_report

__all__ = ["ReportError", "render_report", "write_report"]
