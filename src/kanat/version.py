"""The installed version of kanat (``0+unknown`` in a source tree that was never installed)."""
from importlib.metadata import PackageNotFoundError, version

try:
    __version__ = version("kanat")
except PackageNotFoundError:  # running from a source tree that was never installed
    __version__ = "0+unknown"
