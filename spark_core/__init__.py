"""SPARK engine: typed behavior-tree grammar, perception, planning, control, simulation and execution.

Importable without the server; `server/` only calls this package's public API.
"""

__version__ = "0.1.0"
