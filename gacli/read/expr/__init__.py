"""Expressions of system files: a restricted grammar and its translation to SymPy."""
