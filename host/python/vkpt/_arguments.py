"""Short TypeErrors for vkpt's functions: pybind11 answers a wrong argument with every
overload's full signature (25 lines for Scene.render); this names the argument at fault,
from the same signature, in one line:

    TypeError: Scene.render(): spp takes int, not str ('4')
    TypeError: Scene.render(): no keyword argument 'sp' (did you mean 'spp'?)
"""

import difflib
import functools
import os
import re

_INCOMPATIBLE = "incompatible function arguments"
_INCOMPATIBLE_CONSTRUCTOR = "incompatible constructor arguments"


def _parameters(function):
    """pybind11's signature of `function` as [(name, type)], self left out, and how many
    of them may be given by position."""
    line = (function.__doc__ or "").split("\n")[0]
    m = re.match(r"\w+\((.*)\)\s*->", line)
    if not m:
        return [], 0
    params, positional = [], None
    for p in re.split(r", (?![^\[]*\])", m.group(1)):
        name, _, rest = p.partition(":")
        if name == "*":
            positional = len(params)
        elif name != "self" and not name.startswith("*"):
            params.append((name, rest.split("=")[0].strip()))
    return params, len(params) if positional is None else positional


def _number(value):
    return isinstance(value, (int, float)) or hasattr(value, "__float__")


def _accepts(kind, value):
    """Whether pybind11 converts `value` to `kind` (as far as a wrong type can be told)."""
    if kind.startswith("Optional["):
        return value is None or _accepts(kind[len("Optional["):-1], value)
    if kind == "int":
        return hasattr(value, "__index__")
    if kind == "float":
        return _number(value)
    if kind == "bool":
        return isinstance(value, bool) or type(value).__name__ == "bool_"
    if kind == "str":
        return isinstance(value, str)
    if kind == "os.PathLike":
        return isinstance(value, (str, os.PathLike))
    if kind == "dict":
        return isinstance(value, dict)
    m = re.fullmatch(r"List\[(.*)\]", kind)
    if m:
        if isinstance(value, (str, bytes)) or not hasattr(value, "__len__") or not hasattr(value, "__iter__"):
            return False
        item, size = re.fullmatch(r"(\w+)(?:\[(\d+)\])?", m.group(1)).groups()
        if size and len(value) != int(size):
            return False
        return all(_accepts("float" if size else item, v) for v in value)
    return True  # object, or a type this does not know: pybind11's message stands


def _fault(qualname, params, positional, args, kwargs):
    """One line naming the argument pybind11 refused, or None where none can be named."""
    names = [name for name, _ in params]
    if len(args) > positional:
        return f"{qualname}() takes {positional} positional argument(s) ({', '.join(names[:positional])}), " \
               f"not {len(args)}: the others are keywords"
    for name in kwargs:
        if name not in names:
            close = difflib.get_close_matches(name, names, n=1)
            hint = f" (did you mean {close[0]!r}?)" if close else ""
            return f"{qualname}(): no keyword argument {name!r}{hint}"
    given = list(zip(names, args)) + list(kwargs.items())
    kinds = dict(params)
    for name, value in given:
        if not _accepts(kinds[name], value):
            shown = repr(value)
            shown = shown if len(shown) <= 40 else shown[:37] + "..."
            kind = kinds[name].replace("os.PathLike", "str or os.PathLike").replace("Optional[", "None or ")
            kind = re.sub(r"List\[float\[(\d+)\]\]", r"\1 numbers", kind).replace("List[", "a list of ").rstrip("]")
            return f"{qualname}(): {name} takes {kind}, not {type(value).__name__} ({shown})"
    return None


def shorten_type_errors(cls, method):
    """Wraps cls.method so that a refused argument raises a one-line TypeError naming it."""
    function = getattr(cls, method)
    params, positional = _parameters(function)
    qualname = f"{cls.__name__}.{method}" if method != "__init__" else cls.__name__

    @functools.wraps(function)
    def checked(self, *args, **kwargs):
        try:
            return function(self, *args, **kwargs)
        except TypeError as e:
            text = str(e)
            line = (_INCOMPATIBLE in text or _INCOMPATIBLE_CONSTRUCTOR in text) and _fault(qualname, params, positional,
                                                                                          args, kwargs)
            if not line:
                raise
            raise TypeError(line) from None

    setattr(cls, method, checked)
