"""blossom: certified Bézier curves for numpy users, with Python bezier's names, and
certified region booleans (docs/python.md).

The compiled extension is ``blossom._blossom``; this package re-exports it and adds the
font functions of ``blossom._fonts`` (pure Python; fontTools is imported when they run).
"""

from ._blossom import *  # noqa: F401,F403 - the extension's names, listed in its __all__
from ._blossom import __all__ as _extension_names
from ._blossom import __doc__ as _extension_doc  # noqa: F401
from ._blossom import __version__  # noqa: F401
from ._fonts import remove_overlaps

__all__ = list(_extension_names) + ["remove_overlaps"]
