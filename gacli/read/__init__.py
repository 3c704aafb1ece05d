"""The reading stage: a system file's text to typed declarations and expression trees.

``source`` (YAML nodes with their places, size and alias limits) →
``schema`` and the ``declare_*`` readers (the keys each place may have, read
into typed records; no SymPy) → ``expr`` (the restricted grammar, parsed
without ``eval``, and its translation to SymPy). Beside them: what free text
(``textsafe``) and ``latex:`` overrides (``texsafe``) may contain, the rules
for a system's name (``system_name``), imaginary values found where they are
read (``imaginary``), and the JSON Schema of the format (``file_schema``).
:mod:`gacli.loader.loading` puts these together into a :class:`gacli.model.System`.
"""
