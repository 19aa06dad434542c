"""Keyword options of ``biped simulate`` / ``biped walk`` turned into its command-line words.

A keyword is the option's long name with ``_`` for ``-`` (``sole_size`` for ``--sole-size``).
Flags take ``True`` (given) or ``False`` (left out); other values are written as the command
line reads them: numbers exactly (``repr``), sequences comma-separated (``feet=("l", "r")``,
``sole_size=(0.2, 0.1)``), mappings as ``NAME=VALUE`` pairs (``pose={"knee": 0.4}``), paths as
text. A repeatable option (``plot``) takes a list, one entry per use.
"""

from __future__ import annotations

import os
from typing import Any, Dict, List, Mapping

from ._native import BipedError, option_spec

_SPECS: Dict[str, Dict[str, tuple]] = {}


def _spec(command: str) -> Dict[str, tuple]:
    if command not in _SPECS:
        _SPECS[command] = dict(option_spec(command))
    return _SPECS[command]


def _text(command: str, key: str, value: Any) -> str:
    """One option value as command-line text."""
    if isinstance(value, bool):
        raise BipedError(f"{command}: `{key}` takes a value, not {value!r}")
    if isinstance(value, (int, float)):
        return repr(value)
    if isinstance(value, (str, os.PathLike)):
        return os.fspath(value)
    if isinstance(value, Mapping):
        return ",".join(f"{k}={_text(command, key, v)}" for k, v in value.items())
    try:
        items = list(value)
    except TypeError:
        raise BipedError(
            f"{command}: `{key}` must be a number, text, a sequence or a mapping, "
            f"not {type(value).__name__}"
        ) from None
    return ",".join(_text(command, key, v) for v in items)


def words(command: str, options: Mapping[str, Any]) -> List[str]:
    """The command-line words of ``biped <command>`` for keyword ``options``."""
    spec = _spec(command)
    out: List[str] = []
    for key, value in options.items():
        if key not in spec:
            known = ", ".join(sorted(spec))
            raise BipedError(f"{command}: unknown option `{key}` (options: {known})")
        takes_value, repeatable = spec[key]
        flag = "--" + key.replace("_", "-")
        if not takes_value:
            if not isinstance(value, bool):
                raise BipedError(f"{command}: `{key}` is a flag: give True or False, not {value!r}")
            if value:
                out.append(flag)
            continue
        if value is None:
            continue
        values = value if repeatable and isinstance(value, (list, tuple)) else [value]
        for v in values:
            out += [flag, _text(command, key, v)]
    return out
