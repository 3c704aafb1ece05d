"""gacli's version, in a module of its own.

Generated files name the version that wrote them. The emitters read it here,
not from the package ``gacli``, whose ``__init__`` (the public API) sits above
them: importing it from below would close a loop through the whole package.
"""

__version__ = "0.1.0"
