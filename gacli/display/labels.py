"""What the tape's labels are called in a printout: a quantity's name, its vector's, and the words for it.

A label (gacli.mechanics.program.tape) says what a program value is: a
frame's angular velocity along its own axes for a pass of rates, a point's
velocity along a frame, an inertia entry, an entry of M or F. The printout
names it as a hand derivation would (``w_fork_steer_z``: the angular
velocity of fork per unit rate of steer, along z), and says so once in
words, with a legend for the words (docs/printing.md).
"""

from __future__ import annotations

import re

AXES = "xyz"


def identifier(text: str) -> str:
    """``text`` as an identifier of the grammar: letters, digits and single underscores."""
    out = re.sub(r"[^A-Za-z0-9_]+", "_", text)
    out = re.sub(r"_+", "_", out).strip("_")
    return out if out and not out[0].isdigit() else f"n_{out}"


def point_words(point: str) -> str:
    """How a report says a point of the frame model (gacli.frame_model names them)."""
    if "+" in point:
        return "the mass centre of " + " and ".join(point.split("+"))
    if point.startswith("loads[") and point.endswith("@"):
        return f"the point of application of {point[:-1]}"
    if point.endswith("@"):
        return f"the mass centre of {point[:-1]}"
    if "#" in point:
        base, link = point.split("#", 1)
        return f"{base}, link {link}"
    return point


_FIXED = {"actual": ("", "", ""), "gamma": ("_gamma", "", " for gamma"), "rest": ("_rest", "", ", speeds' rates zero")}


def _pass(key: str) -> tuple[str, str, str]:
    """(name suffix, words before, words after) of a pass of rates (gacli.mechanics.program.vectors.Pass)."""
    if key in _FIXED:
        return _FIXED[key]
    if key.startswith("u_"):
        return f"_{key[2:]}", "partial ", f" for dot({key[2:]})"
    if key.startswith("e_"):
        return f"_unit_{key[2:]}", "", f" per unit dot({key[2:]})"
    return f"_{key}", "", f" for {key}"


# What each kind of label is, and, once for the section, what the words mean (LEGEND).
_WHAT = {"w": "angular velocity", "alpha": "angular acceleration", "v": "velocity", "a": "acceleration"}
_REST = {"alpha": ", accelerations zero", "a": ", accelerations zero"}
LEGEND = "a frame's angular velocity and acceleration along its own axes, a point's along the frame in brackets"
# What the words of a description mean, said once in the legend when some description has them.
WORDS = (("partial", "partial: for one speed, eq. (14.8)"),
         ("accelerations zero", "accelerations zero: the velocity-product part, eq. (14.14)"),
         ("speeds' rates zero", "speeds' rates zero: the part of eq. (14.14) without the u-dots"),
         ("for gamma", "for gamma: the dependent accelerations' part"),
         ("per unit dot(", "per unit dot(q): for the rolling rows"))


def _rest(kind: str, key: str) -> str:
    """", accelerations zero" after α and a with every q̈ zero; nothing after a rest, which says so itself."""
    return "" if key == "rest" else _REST.get(kind, "")


def legend(abouts) -> str:
    """The legend of a program's named quantities: what their descriptions say, the words they use."""
    said = [meaning for word, meaning in WORDS if any(word in a for a in abouts if a)]
    return "(" + "; ".join([LEGEND, *said]) + ")"


def label_name(label: tuple) -> tuple[str, str, str]:
    """(name, vector's name, words) of a tape label (gacli.mechanics.program.tape)."""
    kind = label[0]
    if kind in ("w", "alpha"):
        _, frame, key, i = label
        suffix, before, after = _pass(key)
        base = identifier(f"{kind[:2]}_{frame}{suffix}")
        return f"{base}_{AXES[i]}", base, f"{before}{_WHAT[kind]} of {frame}{after}{_rest(kind, key)}"
    if kind in ("v", "a"):
        _, point, key, frame, i = label
        suffix, before, after = _pass(key)
        base = identifier(f"{kind}_{point.rstrip('@')}{suffix}")
        words = f"{before}{_WHAT[kind]} of {point_words(point)}{after}{_rest(kind, key)} [{frame}]"
        return f"{base}_{AXES[i]}", base, words
    if kind == "r":
        _, point, frame, i = label
        base = identifier(f"r_{point}")
        return f"{base}_{AXES[i]}", base, f"position of {point_words(point)} [{frame}]"
    if kind == "I":
        _, point, frame, i, j = label
        base = identifier(f"I_{point}")
        equal = isinstance(i, tuple)  # one moment about several axes (units._axes)
        axes = "".join(AXES[a] * 2 for a in i) if equal else AXES[i] + AXES[j]
        said = ", equal about " + " and ".join(AXES[a] for a in i) if equal else ""
        return f"{base}_{axes}", base, f"inertia of {point_words(point)} about it{said} [{frame}]"
    if kind == "M":
        return f"M_{label[1] + 1}_{label[2] + 1}", "M", "mass matrix"
    if kind == "F":
        return f"F_{label[1] + 1}", "F", "forcing"
    return identifier("_".join(map(str, label))), "", ""
