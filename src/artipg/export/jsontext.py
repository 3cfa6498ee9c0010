"""Indented JSON text, byte for byte what ``json.dumps(data, indent=n)`` writes, faster.

``json.dumps`` encodes indented JSON with a pure-Python generator per nested value,
but compact JSON in C. Indented text is compact text (``separators=(",", ": ")``)
with a line break and ``n`` spaces per nesting level after every ``[``, ``{`` and
``,`` and before every ``]`` and ``}`` outside strings (none inside an empty ``[]`` or
``{}``). :func:`dumps_indented` encodes compact text in C and inserts those breaks with
numpy: the output is ASCII (``ensure_ascii``), so strings are found by their quotes,
an escaped quote being one after an odd run of backslashes.
"""

from __future__ import annotations

import json

import numpy as np

_QUOTE, _BACKSLASH, _SPACE, _NEWLINE = (ord(c) for c in '"\\ \n')
_OPEN = np.zeros(256, dtype=bool)
_OPEN[[ord("["), ord("{")]] = True
_CLOSE = np.zeros(256, dtype=bool)
_CLOSE[[ord("]"), ord("}")]] = True


def dumps_indented(data, indent: int = 1) -> str:
    """``json.dumps(data, indent=indent)`` (ASCII output, keys in insertion order).

    Parameters
    ----------
    data : JSON-ready data (dicts, lists, tuples, str, int, float, bool, None)
    indent : int
        Spaces per nesting level (>= 0; a string indent goes to ``json.dumps``).

    Returns
    -------
    str
        The same text as ``json.dumps(data, indent=indent)``; the same errors for data
        ``json`` cannot encode.
    """
    if not isinstance(indent, int):
        return json.dumps(data, indent=indent)
    indent = max(0, indent)  # json indents by " " * indent
    b = np.frombuffer(json.dumps(data, separators=(",", ": ")).encode("ascii"), dtype=np.uint8)
    n = len(b)
    quote = b == _QUOTE
    backslash = b == _BACKSLASH
    if backslash.any():  # a quote after an odd number of backslashes is escaped
        i = np.arange(n)
        last = np.maximum.accumulate(np.where(backslash, -1, i))  # last non-backslash at or before i
        run = np.zeros(n, dtype=np.int64)
        run[1:] = i[:-1] - last[:-1]  # backslashes just before i
        quote &= run % 2 == 0
    outside = np.cumsum(quote) % 2 == 0  # outside strings (a closing quote counts as outside)
    opens = _OPEN[b] & outside
    closes = _CLOSE[b] & outside
    commas = (b == ord(",")) & outside
    level = np.cumsum(opens.astype(np.int64) - closes)  # nesting after each character
    empty = np.zeros(n, dtype=bool)  # opening brackets closed right away
    empty[:-1] = opens[:-1] & closes[1:]
    after = np.where((opens & ~empty) | commas, 1 + indent * level, 0)  # line break after
    before = np.zeros(n, dtype=np.int64)  # line break before
    before[1:] = np.where(closes[1:] & ~empty[:-1], 1 + indent * level[1:], 0)
    shift = np.cumsum(before + after)
    pos = np.arange(n) + shift - after  # where each character goes
    out = np.full(n + int(shift[-1]) if n else 0, _SPACE, dtype=np.uint8)
    out[pos] = b
    out[(pos - before)[before > 0]] = _NEWLINE
    out[(pos + 1)[after > 0]] = _NEWLINE
    return out.tobytes().decode("ascii")
