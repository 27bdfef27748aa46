"""The version of kanat: the one place it is written (``pyproject.toml`` reads it from here,
so reading it costs no ``importlib.metadata`` scan of the installed packages)."""

__version__ = "0.1.0"
