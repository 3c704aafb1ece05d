"""Which system names are safe as file, module and C identifier prefixes.

A system's ``name:`` becomes ``<name>.py``, ``<name>.c``, ``<name>.h``,
``<name>.tex``, a Python module name, and the prefix of C functions and
macros. So it must be a short portable identifier that neither language
reserves and that hides nothing: ``name: math`` would write a ``math.h``
that ``#include <math.h>`` can find first (with ``-I.``, or on a
case-insensitive file system as ``Math.h``), ``name: numpy`` a module that
imports itself, ``name: class`` a module no ``import`` statement can name.
No SymPy here: :mod:`gacli.read.declarations` calls :func:`name_problem` at load time.

>>> name_problem("pendulum") is None
True
>>> name_problem("stdio")
"'stdio' is the name of a C standard header (stdio.h), which the generated stdio.h would hide"
"""

from __future__ import annotations

import keyword
import sys

MAX_LENGTH = 64

# C23 and C++20 keywords (a system name is the prefix of C identifiers, and
# the header may be included from C++).
C_KEYWORDS = frozenset("""
    alignas alignof auto bool break case char const constexpr continue default do double
    else enum extern false float for goto if inline int long nullptr register restrict
    return short signed sizeof static static_assert struct switch thread_local true
    typedef typeof typeof_unqual union unsigned void volatile while
    _Alignas _Alignof _Atomic _BitInt _Bool _Complex _Decimal128 _Decimal32 _Decimal64
    _Generic _Imaginary _Noreturn _Static_assert _Thread_local
    and and_eq asm bitand bitor catch char8_t char16_t char32_t class compl concept
    consteval constinit const_cast co_await co_return co_yield decltype delete
    dynamic_cast explicit export friend mutable namespace new noexcept not not_eq
    operator or or_eq private protected public reinterpret_cast requires static_cast
    template this throw try typeid typename using virtual wchar_t xor xor_eq
""".split())

# The standard headers of C99, C11 and C23, without ".h".
C_HEADERS = frozenset("""
    assert complex ctype errno fenv float inttypes iso646 limits locale math setjmp
    signal stdalign stdarg stdatomic stdbit stdbool stdckdint stddef stdint stdio
    stdlib stdnoreturn string tgmath threads time uchar wchar wctype
""".split())

# Modules the generated Python imports, and gacli itself, besides the standard library.
PYTHON_MODULES = frozenset({"math", "numpy", "gacli"}) | frozenset(getattr(sys, "stdlib_module_names", ()))

_FIRST = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz_"
_REST = _FIRST + "0123456789"


def name_problem(name: str) -> str | None:
    """Why ``name`` cannot name a system, or None."""
    if not name or name[0] not in _FIRST or any(c not in _REST for c in name):
        return "a system name is a letter or '_' followed by letters, digits and '_'"
    if len(name) > MAX_LENGTH:
        return f"a system name is at most {MAX_LENGTH} characters long (this one has {len(name)})"
    if name.startswith("__") or (name[0] == "_" and name[1:2].isupper()):
        return f"'{name}' is reserved in C (names starting with '__' or '_' and a capital)"
    if keyword.iskeyword(name):
        return f"'{name}' is a Python keyword: the generated module could not be imported"
    if name in C_KEYWORDS:
        return f"'{name}' is a C or C++ keyword"
    if name.lower() in C_HEADERS:
        header = f"{name.lower()}.h"
        return f"'{name}' is the name of a C standard header ({header}), which the generated {name}.h would hide"
    if name in PYTHON_MODULES:
        return f"'{name}' is the name of a Python module that the generated {name}.py would hide"
    return None
